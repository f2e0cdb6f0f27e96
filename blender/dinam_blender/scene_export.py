"""What the add-on hands dinam: each selected object's mesh as an OBJ file and one scene file.

The OBJ holds the object's own vertices in its own order (one `v` line per vertex, in world
coordinates, so that gravity points down whatever the object's transform), its faces and its loose
edges as line elements, and, where its material has an image texture, its UVs. dinam numbers the
nodes of an OBJ file in the order of its `v` lines, so point k of the cache dinam writes is the
object's vertex k. The scene carries each object's look as Blender shows it: its material's base
colour (or image texture) and its shading (flat, smooth, or smooth with sharp edges).
"""
import hashlib
import json
import math
import os
import struct

import bpy
import mathutils

# dinam's named materials (docs/materials.md; `material: {preset: NAME}` in a scene): the same
# names, so an artist's choice here is dinam's preset with its values and sources. "custom" takes
# the panel's density, Young's modulus and wire radius instead.
PRESETS = {
    "cotton": ("Cotton", "Shirting cotton, 120 g/m²: a shirt, a flag, a sheet"),
    "denim": ("Denim", "12 oz denim, 400 g/m²: jeans, heavy garments"),
    "silk": ("Silk", "Silk habotai, 60 g/m²: light and flowing"),
    "canvas": ("Canvas", "10 oz cotton duck, 340 g/m²: sails, awnings, bags"),
    "leather": ("Leather", "Garment leather, 1.2 mm"),
    "rubber_sheet": ("Rubber sheet", "Natural rubber, 1 mm: stretches"),
    "hemp_rope": ("Hemp rope", "12 mm three-strand hemp rope"),
    "nylon_rope": ("Nylon rope", "12 mm three-strand nylon rope"),
    "steel_cable": ("Steel cable", "6 mm 6×19 wire rope: stiff, so small steps"),
    "chain": ("Chain", "6 mm steel link chain"),
    "copper_wire": ("Copper wire", "2 mm annealed copper wire: bends and stays bent"),
    "steel_wire": ("Steel wire", "2 mm mild steel wire: stiff, so small steps"),
}


def material_text(settings, preset=None):
    """An object's `material` map: its own preset (`preset`, one of PRESETS), else the panel's
    preset, or the panel's own values."""
    if preset in PRESETS:
        return f"{{preset: {preset}}}"
    if settings.preset in PRESETS:
        return f"{{preset: {settings.preset}}}"
    return (f"{{density: {settings.density!r}, youngs_modulus: {settings.youngs_modulus!r}, "
            f"radius: {settings.radius!r}}}")


class ExportError(Exception):
    """A reason the selection cannot be simulated, worded for the artist."""


def object_file_stem(name, taken=None):
    """A file name for an object: letters, digits, '-', '_' and '.' kept, anything else '_', at
    most 100 characters (a longer name ends in a digest of the whole); where `taken` (a set of
    stems already used) holds it, a number follows, so that "a b" and "a_b" get files of their
    own. The stem is added to `taken`."""
    stem = "".join(c if c.isascii() and (c.isalnum() or c in "-_.") else "_" for c in name)
    stem = stem if stem and not stem.startswith(".") else "object" + stem
    if len(stem) > 100:
        stem = stem[:83] + "-" + hashlib.sha256(name.encode("utf-8")).hexdigest()[:16]
    if taken is not None:
        base, number = stem, 1
        while stem in taken:
            stem, number = f"{base}_{number}", number + 1
        taken.add(stem)
    return stem


def check_mesh(obj):
    """Raises ExportError where the object's vertices cannot all become nodes of the cache."""
    mesh = obj.data
    if len(mesh.edges) == 0:
        raise ExportError(f"'{obj.name}' has no edges: dinam makes a bar of every edge")
    on_edge = [False] * len(mesh.vertices)
    for edge in mesh.edges:
        on_edge[edge.vertices[0]] = on_edge[edge.vertices[1]] = True
    loose = on_edge.count(False)
    if loose:
        raise ExportError(
            f"'{obj.name}' has {loose} vertices on no edge, which dinam drops, so its cache would "
            "not match the object vertex for vertex: delete them (Mesh > Clean Up > Delete Loose)")


def write_obj(obj, path, positions=None, uvs=False):
    """Writes the object's mesh (without its modifiers) in world coordinates, or with its vertices
    at `positions` (world coordinates, one per vertex in order) where given; with `uvs`, its active
    UV map too, a `vt` per face corner."""
    mesh = obj.data
    world = obj.matrix_world
    lines = [f"# {obj.name}: written by the dinam Blender add-on, one v per vertex in order",
             f"o {object_file_stem(obj.name)}"]
    for k, vertex in enumerate(mesh.vertices):
        p = world @ vertex.co if positions is None else mathutils.Vector(positions[k])
        lines.append(f"v {p.x!r} {p.y!r} {p.z!r}")
    uv_layer = mesh.uv_layers.active if uvs else None
    if uv_layer is not None:
        lines += [f"vt {loop.uv[0]!r} {loop.uv[1]!r}" for loop in uv_layer.data]
    for polygon in mesh.polygons:
        if uv_layer is not None:
            lines.append("f " + " ".join(f"{mesh.loops[k].vertex_index + 1}/{k + 1}"
                                         for k in polygon.loop_indices))
        else:
            lines.append("f " + " ".join(str(v + 1) for v in polygon.vertices))
    for edge in mesh.edges:
        if edge.is_loose:
            lines.append(f"l {edge.vertices[0] + 1} {edge.vertices[1] + 1}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def base_colour_source(material):
    """What gives a material its base colour: the Principled BSDF's (or Diffuse BSDF's) colour
    input where the material uses nodes, else None."""
    if material is None or not material.use_nodes or material.node_tree is None:
        return None
    for node in material.node_tree.nodes:
        if node.type in ("BSDF_PRINCIPLED", "BSDF_DIFFUSE"):
            return node.inputs.get("Base Color") or node.inputs.get("Color")
    return None


def object_look(obj, inputs, stem):
    """The object's look as Blender shows it, for its scene entry: `color` (Blender's colours are
    linear already), `texture` (its material's image texture, saved as a PNG into `inputs` under
    `stem`, when it has a UV map) and `shading` (flat where no face is smooth; auto, with the
    mesh's angle, where Auto Smooth is on; else smooth)."""
    look = {}
    material = obj.active_material
    source = base_colour_source(material)
    if source is not None and source.is_linked:
        image_node = source.links[0].from_node
        image = getattr(image_node, "image", None)
        if image is not None and obj.data.uv_layers.active is not None:
            path = os.path.join(inputs, stem + ".png")
            copy = image.copy()
            try:
                copy.filepath_raw = path
                copy.file_format = "PNG"
                copy.save()
            finally:
                bpy.data.images.remove(copy)
            look["texture"] = os.path.basename(path)
    elif source is not None:
        look["color"] = tuple(source.default_value)[:3]
    elif material is not None:
        look["color"] = tuple(material.diffuse_color)[:3]
    mesh = obj.data
    smooth = any(polygon.use_smooth for polygon in mesh.polygons)
    if mesh.polygons and not smooth:
        look["shading"] = "flat"
    elif smooth and getattr(mesh, "use_auto_smooth", False):
        look["shading"] = "auto"
        look["sharp_angle"] = round(math.degrees(mesh.auto_smooth_angle), 3)  # a float32
    return look


def look_lines(look, collider=False):
    """The scene lines of `look` (object_look); a collider smooth as modelled, not subdivided."""
    lines = []
    if "color" in look:
        linear = ", ".join(repr(min(max(float(c), 0.0), 1.0)) for c in look["color"])
        lines.append(f"    color: {{linear: [{linear}]}}")
    if "texture" in look:
        lines.append(f"    texture: {json.dumps(look['texture'])}")
    if "shading" in look:
        lines.append(f"    shading: {look['shading']}")
    if "sharp_angle" in look:
        lines.append(f"    sharp_angle: {look['sharp_angle']!r}")
    elif collider and "shading" not in look:
        lines.append("    subdivide: 0")
    return lines


def collider_track(context, obj):
    """The collider's vertices in world coordinates at every frame of the scene's range (its keys,
    parents, armature and shape keys evaluated), a list of lists of (x, y, z); None where it does
    not move. Where a modifier changes the vertex count (a Subdivision), its own vertices are
    placed by its transform alone: the track must be of the vertices the OBJ holds."""
    scene = context.scene
    current = scene.frame_current
    count = len(obj.data.vertices)
    samples = []
    try:
        for frame in range(scene.frame_start, scene.frame_end + 1):
            scene.frame_set(frame)
            evaluated = obj.evaluated_get(context.evaluated_depsgraph_get())
            world = evaluated.matrix_world
            mesh = evaluated.to_mesh()
            try:
                vertices = mesh.vertices if len(mesh.vertices) == count else obj.data.vertices
                samples.append([tuple(world @ v.co) for v in vertices])
            finally:
                evaluated.to_mesh_clear()
    finally:
        scene.frame_set(current)
    first = samples[0]
    moves = any(abs(a - b) > 1e-7
                for sample in samples[1:] for p, q in zip(sample, first) for a, b in zip(p, q))
    return samples if moves else None


def write_pc2(path, samples):
    """Writes `samples` (each a list of (x, y, z)) as a PC2 point cache, one sample a frame from
    the scene's first: dinam's t = 0."""
    with open(path, "wb") as f:
        f.write(struct.pack("<12siiffi", b"POINTCACHE2\0", 1, len(samples[0]), 0.0, 1.0,
                            len(samples)))
        for sample in samples:
            f.write(struct.pack(f"<{3 * len(sample)}f", *(c for p in sample for c in p)))


def pinned_indices(obj, group_name):
    """The vertices of `group_name` with a weight above one half, or [] without the group."""
    group = obj.vertex_groups.get(group_name) if group_name else None
    if group is None:
        return []
    pinned = []
    for vertex in obj.data.vertices:
        for g in vertex.groups:
            if g.group == group.index and g.weight > 0.5:
                pinned.append(vertex.index)
    return pinned


def vector(v):
    return "[" + ", ".join(repr(float(c)) for c in v) + "]"


def ground_height(settings):
    """The ground's height: the top of the chosen floor object's bounds in the world, else the
    panel's height."""
    floor = settings.floor
    if floor is None:
        return settings.ground_height
    return max((floor.matrix_world @ mathutils.Vector(corner)).z for corner in floor.bound_box)


def scene_text(settings, objects, frame_count, fps, colliders=(), name="untitled"):
    """The scene file `name` (the .blend's) for `objects` (each a dict: name, obj (its file), pins
    (vertex indices), preset (its own, or None for the panel's), look (object_look), attach (a
    list of (vertex indices, target object's name))) and `colliders` (each a dict: name, obj,
    track (its PC2 file or None), look: obstacles that push and that the cloth does not move);
    JSON's quoted strings are YAML's too."""
    lines = [
        "# Written by the dinam Blender add-on.",
        "version: 1",
        f"name: {json.dumps(name)}",
        f"duration: {frame_count / fps!r}",
        f"fps: {fps!r}",
        "timestep: auto",
        f"gravity: {vector(settings.gravity)}",
    ]
    if any(settings.wind):
        wind = [f"velocity: {vector(settings.wind)}"]
        if settings.turbulence > 0:
            wind.append(f"turbulence: {{amplitude: {settings.turbulence!r}}}")
        if settings.gust > 0:
            wind.append(f"gust: {{amplitude: {settings.gust!r}}}")
        lines.append("wind: {" + ", ".join(wind) + "}")
    if settings.ground:
        lines.append(f"ground: {{height: {float(ground_height(settings))!r}}}")
    else:
        lines.append("ground: {contact: false}")
    if settings.settle:
        lines.append("settle: {}")
    if colliders or settings.self_contact:
        lines.append(f"contact: {{objects: true, self: {'true' if settings.self_contact else 'false'}}}")
    lines.append("objects:")
    for entry in objects:
        lines += [
            f"  - name: {json.dumps(entry['name'])}",
            f"    mesh: {{file: {json.dumps(os.path.basename(entry['obj']))}, up_axis: z}}",
            f"    material: {material_text(settings, entry['preset'])}",
        ]
        if settings.damping_ratio > 0:
            lines.append(f"    damping: {{axial_ratio: {settings.damping_ratio!r}}}")
        if entry["pins"]:
            lines.append(f"    pinned: {{indices: [{', '.join(str(i) for i in entry['pins'])}]}}")
        if entry.get("attach"):
            lines.append("    attach:")
            for indices, target in entry["attach"]:
                listed = ", ".join(str(i) for i in indices)
                lines.append(f"      - {{nodes: {{indices: [{listed}]}}, to: {json.dumps(target)}}}")
        lines += look_lines(entry.get("look", {}))
    for entry in colliders:
        lines += [
            f"  - name: {json.dumps(entry['name'])}",
            f"    mesh: {{file: {json.dumps(os.path.basename(entry['obj']))}, up_axis: z}}",
            "    role: collider",
            f"    contact: {{radius: {settings.collider_radius!r}}}",
        ]
        if entry["track"]:
            lines.append(
                f"    pin_motion: {{point_cache: {json.dumps(os.path.basename(entry['track']))}}}")
        lines += look_lines(entry.get("look", {}), collider=True)
    return "\n".join(lines) + "\n"
