# docs/getting-started.md's cape, made in headless Blender through the add-on by the page's steps,
# each done as the page says (its operators, its panel values), on a character of our own:
#
#   blender -b --factory-startup --python-exit-code 1 --python THIS -- ADDON.zip DINAM WORK
#
# Checks what the page promises an artist: the cape moves (more than 5 cm from frame 1 at some
# frame) while its collar stays where it was modelled, and the frame range the page sets is the
# cache's. Prints "cape: PASS"; raises otherwise.
import json
import math
import os
import sys

import addon_utils
import bpy

zip_path, dinam, work = sys.argv[sys.argv.index("--") + 1:]
os.makedirs(work, exist_ok=True)

# 1. Install the add-on, and set the dinam program's path.
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
bpy.ops.preferences.addon_enable(module="dinam_blender")
assert addon_utils.check("dinam_blender")[1], "the add-on is not enabled"
scene = bpy.context.scene
settings = scene.dinam
settings.program = dinam

# 2. Save the .blend file (the add-on's folder, //dinam, is beside it: cape.blend's run in
#    //dinam/cape).
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(work, "cape.blend"))

# The character: a body 0.45 m wide, 0.25 m deep and 1.7 m tall standing on the floor at the
# origin, facing -y (Blender's front view looks along +y), so its back is at y = +0.125.
bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.0, 0.0, 0.85), scale=(0.45, 0.25, 1.7))
body = bpy.context.active_object
body.name = "Body"

# 3. Model the cape: a plane stood up (rotated 90° about X), scaled to 0.6 × 1.0 m, subdivided with
#    20 cuts, placed behind the shoulders (its top edge at 1.5 m, 3 cm behind the back).
bpy.ops.mesh.primitive_plane_add(size=1.0, location=(0.0, 0.155, 1.0),
                                 rotation=(math.radians(90.0), 0.0, 0.0))
cape = bpy.context.active_object
cape.name = "Cape"
cape.scale = (0.6, 1.0, 1.0)
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
bpy.ops.mesh.subdivide(number_cuts=20)
bpy.ops.object.mode_set(mode="OBJECT")
assert len(cape.data.vertices) == 22 * 22, len(cape.data.vertices)

# 4. Pin the collar: the top row of vertices in a group "Pins", chosen as the panel's Pins.
world = [cape.matrix_world @ v.co for v in cape.data.vertices]
top = max(p.z for p in world)
collar = [i for i, p in enumerate(world) if p.z > top - 1e-6]
assert len(collar) == 22, len(collar)
cape.vertex_groups.new(name="Pins").add(collar, 1.0, "REPLACE")
settings.pin_group = "Pins"

# 5. The character is a dinam collider.
body.dinam_collider = True

# 6. Material and settings: denim, self-contact, settle first, the ground kept on.
settings.preset = "denim"
settings.self_contact = True
settings.settle = True
assert settings.ground

# 7. Wind: from the front, with gusts, as the page gives it.
settings.wind = (0.0, 3.0, 0.0)
settings.gust = 1.5

# 8. The frame range: 96 frames at 24 fps.
scene.frame_start, scene.frame_end = 1, 96
assert scene.render.fps == 24 and scene.render.fps_base == 1.0

# 9. Estimate, then Simulate, with the cape selected.
bpy.ops.object.select_all(action="DESELECT")
cape.select_set(True)
bpy.context.view_layer.objects.active = cape
assert bpy.ops.dinam.estimate() == {"FINISHED"}
print("cape: estimate: " + settings.last_report.replace("\n", " | "))
assert bpy.ops.dinam.simulate() == {"FINISHED"}
print("cape: dinam said: " + settings.last_report.replace("\n", " | "))

# 10. The movie: the Mesh Cache modifier plays the motion over the frame range.
with open(os.path.join(work, "dinam", "cape", "cache", "manifest.json")) as f:
    manifest = json.load(f)
assert manifest["frame_count"] == 96 and manifest["fps"] == 24, manifest
assert cape.modifiers and cape.modifiers[0].type == "MESH_CACHE", list(cape.modifiers)


def cape_at(frame):
    scene.frame_set(frame)
    evaluated = cape.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    points = [cape.matrix_world @ v.co for v in mesh.vertices]
    evaluated.to_mesh_clear()
    return points


first = cape_at(1)
largest, at = 0.0, 1
for frame in range(2, 97):
    points = cape_at(frame)
    moved = max((p - q).length for p, q in zip(points, first))
    if moved > largest:
        largest, at = moved, frame
    if frame == 96:
        collar_moved = max((points[i] - world[i]).length for i in collar)
        behind = min(p.y for p in points)
print(f"cape: moves up to {100 * largest:.1f} cm from frame 1 (at frame {at}); the collar "
      f"{collar_moved:.2g} m from where it was modelled; nearest the body y = {behind:.3f} m")
assert largest > 0.05, f"the cape moves {100 * largest:.2f} cm at most: the page promises motion"
assert collar_moved <= 1e-5, collar_moved
# The body's back is at y = 0.125 and the collider pushes 1 cm out: the cape stays behind it.
assert behind > 0.125, behind
print("cape: PASS")
