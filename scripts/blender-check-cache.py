# Checks in Blender itself that a dinam motion cache opens there the way the README says:
#  - each object's OBJ imports (File > Import > Wavefront OBJ, Forward Y, Up Z: dinam is z-up
#    like Blender) with one vertex per node in node order and with its faces and loose edges;
#  - a Mesh Cache modifier reading the object's PC2 (and MDD) file, Frame Start 1, moves the
#    vertices to the cached positions at several frames, to float precision.
# The expected positions are read from the cache files here with Python's struct module, not by
# Blender and not by dinam.
#
#   blender -b --factory-startup --python-exit-code 1 --python scripts/blender-check-cache.py -- CACHE
#
# Prints one line per object and format, and "PASS" at the end; raises (exit code 1) otherwise.
import json
import os
import struct
import sys

import bpy


def read_obj(path):
    vertices, edges = [], set()
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":  # as float32, which Blender stores
                vertices.append(struct.unpack("3f", struct.pack("3f", *map(float, parts[1:4]))))
            elif parts[0] in ("f", "l"):
                ids = [int(p.split("/")[0]) - 1 for p in parts[1:]]
                pairs = zip(ids, ids[1:] + ids[:1]) if parts[0] == "f" else zip(ids, ids[1:])
                edges.update(tuple(sorted(p)) for p in pairs)
    return vertices, edges


def read_point_cache(path, fmt):
    with open(path, "rb") as f:
        data = f.read()
    if fmt == "pc2":
        signature, version, points, start, rate, samples = struct.unpack_from("<12siiffi", data)
        assert signature == b"POINTCACHE2\0" and version == 1, path
        offset, order = 32, "<"
    else:
        samples, points = struct.unpack_from(">ii", data)
        offset, order = 8 + 4 * samples, ">"
    assert len(data) == offset + samples * points * 12, f"{path}: wrong length"
    frame = struct.Struct(f"{order}{3 * points}f")
    caches = []
    for k in range(samples):
        values = frame.unpack_from(data, offset + k * frame.size)
        caches.append([values[3 * i:3 * i + 3] for i in range(points)])
    return caches


def evaluated_positions(obj, frame):
    bpy.context.scene.frame_set(frame)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    mesh = obj.evaluated_get(depsgraph).to_mesh()
    positions = [tuple(v.co) for v in mesh.vertices]
    obj.evaluated_get(depsgraph).to_mesh_clear()
    return positions


def largest_difference(a, b):
    return max(abs(x - y) for p, q in zip(a, b) for x, y in zip(p, q))


def main():
    cache = sys.argv[sys.argv.index("--") + 1]
    with open(os.path.join(cache, "manifest.json")) as f:
        manifest = json.load(f)
    frame_count = manifest["frame_count"]
    frames = sorted({1, 2, (frame_count + 1) // 2, frame_count})
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.context.scene.frame_start = 1
    bpy.context.scene.frame_end = frame_count
    checked = 0
    for entry in manifest["objects"]:
        obj_path = os.path.join(cache, entry["files"]["obj"])
        vertices, edges = read_obj(obj_path)
        bpy.ops.object.select_all(action="DESELECT")
        bpy.ops.wm.obj_import(filepath=obj_path, forward_axis="Y", up_axis="Z")
        obj = bpy.context.selected_objects[0]
        mesh = obj.data
        assert len(mesh.vertices) == entry["node_count"] == len(vertices), (
            f"{entry['name']}: {len(mesh.vertices)} vertices in Blender, "
            f"{entry['node_count']} nodes in the cache")
        imported = [tuple(v.co) for v in mesh.vertices]
        assert largest_difference(imported, vertices) == 0.0, f"{entry['name']}: vertex order"
        blender_edges = {tuple(sorted(e.vertices)) for e in mesh.edges}
        assert blender_edges == edges, (
            f"{entry['name']}: {len(blender_edges)} edges in Blender, {len(edges)} in the OBJ")
        extent = max(max(abs(c) for c in p) for p in vertices) or 1.0
        for fmt in ("pc2", "mdd"):
            if fmt not in entry["files"]:
                continue
            path = os.path.join(cache, entry["files"][fmt])
            expected = read_point_cache(path, fmt)
            assert len(expected) == frame_count
            modifier = obj.modifiers.new(name=f"dinam {fmt}", type="MESH_CACHE")
            modifier.cache_format = fmt.upper()
            modifier.filepath = path
            modifier.frame_start = 1.0  # scene frame 1 shows the first sample
            worst = 0.0
            for frame in frames:
                worst = max(worst, largest_difference(evaluated_positions(obj, frame),
                                                      expected[frame - 1]))
            # float32 through Blender's float32 vertices: exact, or off by rounding at most.
            assert worst <= 1e-6 * extent, f"{entry['name']} {fmt}: off by {worst} m"
            obj.modifiers.remove(modifier)
            print(f"blender-check: {entry['name']}: {len(vertices)} vertices in node order, "
                  f"{len(edges)} edges; {fmt.upper()} at frames {frames}: largest difference "
                  f"{worst:.3g} m")
            checked += 1
    assert checked > 0, "the cache has no point caches"
    print(f"blender-check: PASS ({checked} point caches, Blender {bpy.app.version_string})")


main()
