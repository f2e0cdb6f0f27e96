# The Blender add-on (blender/dinam_blender), as an artist uses it, in Blender itself (headless):
#
#   blender -b --factory-startup --python-exit-code 1 --python THIS -- ADDON.zip DINAM WORK
#
#  1. installs the zip as Preferences > Add-ons > Install does, and enables it;
#  2. makes a plane subdivided in Blender, stood upright and moved by its object transform (not
#     applied), pinned along its top edge by a vertex group "pins";
#  3. runs Simulate (the operator, waiting for dinam as a script's call does) with the cotton preset
#     and a wind, and checks the Mesh Cache modifier it added (first, PC2, from the scene's start);
#  4. compares the object's vertices, as Blender evaluates them at the first, the middle and the
#     last frame and places them by the object's transform, with the cache's PC2 read here with
#     Python's struct module: to 1e-5 m (single precision through one more transform); the pins
#     stay where they were, and the rest moved;
#  5. refuses an object with a loose vertex, saying how to mend it, and leaves it as it was;
#     names a dinam program that exists but cannot run, a Pins group the object lacks and an
#     unsaved file's relative folder; says that a run with no pins falls freely; drops a square
#     onto a raised ground, a chosen floor object and a collider, and finds it resting on each,
#     then on a collider the animation lifts (its track written as a PC2, followed by dinam);
#  6. runs dinam as the panel does, its progress read from dinam's stderr up to 100 %, and cancels
#     a long run: dinam stops (exit 143, SIGTERM) and the cache of step 3 is as it was;
#  7. gives a second object a material and pins of its own, estimates (dinam info) without
#     simulating, then simulates both and finds each with its own preset and pins; refuses a
#     missing own pin group, and says what dinam refuses when estimating.
# The panel's own loop (a modal operator on a timer) needs Blender's interface, which a headless
# Blender does not run; it calls what steps 3 and 6 check.
# Prints "addon: PASS"; raises otherwise.
import json
import math
import os
import subprocess
import sys
import time

import addon_utils
import bpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cache"))
from blender_banner import subdivided_banner  # noqa: E402  (tests/cache/)
from pc2_reader import read_pc2  # noqa: E402  (tests/cache/pc2_reader.py)

zip_path, dinam, work = sys.argv[sys.argv.index("--") + 1:]

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
bpy.ops.preferences.addon_enable(module="dinam_blender")
assert addon_utils.check("dinam_blender")[1], "the add-on is not enabled"
from dinam_blender import dinam_run  # noqa: E402  (installed just above)

scene = bpy.context.scene
scene.frame_start, scene.frame_end = 1, 24
scene.render.fps, scene.render.fps_base = 24, 1.0

banner = subdivided_banner((0.3, 0.2, 1.5))  # its transform left unapplied
top = max((banner.matrix_world @ v.co).z for v in banner.data.vertices)
pins = [v.index for v in banner.data.vertices if (banner.matrix_world @ v.co).z > top - 1e-6]
banner.vertex_groups.new(name="pins").add(pins, 1.0, "REPLACE")
rest_world = [banner.matrix_world @ v.co for v in banner.data.vertices]

settings = scene.dinam
settings.program = dinam
settings.folder = work
settings.preset = "cotton"
settings.pin_group = "pins"
settings.wind = (0.0, 4.0, 0.0)
bpy.ops.object.select_all(action="DESELECT")
banner.select_set(True)
bpy.context.view_layer.objects.active = banner
assert bpy.ops.dinam.simulate() == {"FINISHED"}

modifier = banner.modifiers[0]
assert modifier.type == "MESH_CACHE" and modifier.cache_format == "PC2", modifier
assert modifier.frame_start == scene.frame_start
cache = os.path.join(work, "cache")
with open(os.path.join(cache, "manifest.json")) as f:
    manifest = json.load(f)
assert manifest["frame_count"] == 24 and manifest["fps"] == 24, manifest["frame_count"]
cached = read_pc2(os.path.join(cache, manifest["objects"][0]["files"]["pc2"]))
for frame in (1, 12, 24):
    scene.frame_set(frame)
    evaluated = banner.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    world = [banner.matrix_world @ v.co for v in mesh.vertices]
    evaluated.to_mesh_clear()
    worst = max(abs(a - b) for p, q in zip(world, cached[frame - 1]) for a, b in zip(p, q))
    print(f"addon: frame {frame}: the object's vertices are the cache's to {worst:.2g} m")
    assert worst <= 1e-5, worst
    if frame == 24:
        still = max((world[i] - rest_world[i]).length for i in pins)
        moved = max((world[i] - rest_world[i]).length for i in range(len(world)))
        print(f"addon: pins moved {still:.2g} m, the banner up to {moved:.3f} m")
        assert still <= 1e-5 and moved > 0.01, (still, moved)

bpy.ops.mesh.primitive_plane_add(size=1.0, location=(3, 0, 1))
loose = bpy.context.active_object
loose.data.vertices.add(1)  # a vertex on no edge
bpy.ops.object.select_all(action="DESELECT")
loose.select_set(True)
try:
    bpy.ops.dinam.simulate()
    raise AssertionError("an object with a loose vertex was simulated")
except RuntimeError as e:
    assert "Delete Loose" in str(e), e
    print("addon: a loose vertex is refused: " + str(e).strip().splitlines()[-1])
assert len(loose.modifiers) == 0

# A program that exists but cannot run (not built for this machine, a broken script) is said so,
# with no Python traceback.
not_a_program = os.path.join(work, "not-a-program")
with open(not_a_program, "w") as f:
    f.write("this is no program\n")
os.chmod(not_a_program, 0o755)
settings.program = not_a_program
bpy.ops.object.select_all(action="DESELECT")
banner.select_set(True)
try:
    bpy.ops.dinam.simulate()
    raise AssertionError("a program that cannot run was run")
except RuntimeError as e:
    assert "cannot run the dinam program" in str(e) and "Traceback" not in str(e), e
    print("addon: a program that cannot run is named: " + str(e).strip().splitlines()[-1])
settings.program = dinam

# A Pins group the object does not have is refused, naming the groups it has; an unsaved file
# with the default folder (relative to the .blend) asks for a save or a folder; neither runs dinam.
bpy.ops.object.select_all(action="DESELECT")
banner.select_set(True)
for key, value, expected in (("pin_group", "pinz", "has no vertex group 'pinz' (its groups: pins)"),
                             ("folder", "//dinam", "which is not saved yet")):
    kept = getattr(settings, key)
    setattr(settings, key, value)
    try:
        bpy.ops.dinam.simulate()
        raise AssertionError(f"{key} = {value!r} was simulated")
    except RuntimeError as e:
        assert expected in str(e), e
        print("addon: refused: " + str(e).strip().splitlines()[-1])
    setattr(settings, key, kept)

# With no pins the run goes on, and says so; what dinam printed is kept for the panel.
settings.pin_group = ""
assert bpy.ops.dinam.simulate() == {"FINISHED"}
assert "'Banner' has no pinned vertex (no Pins group chosen): it falls freely" in \
    settings.last_report, settings.last_report
print("addon: a run with no pins says so: " + settings.last_report.splitlines()[0])
settings.pin_group = "pins"

# The ground where the artist puts it, and obstacles: a square of cloth dropped from 1 m lands
# on a ground raised to 0.4 m, on the top of a chosen floor object (a box whose top is at 0.3 m)
# and on a collider (a plane at 0.6 m, marked in its Object properties, not selected, not moved).
def lowest_at_last_frame(obj):
    scene.frame_set(scene.frame_end)
    evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    lowest = min((obj.matrix_world @ v.co).z for v in mesh.vertices)
    evaluated.to_mesh_clear()
    return lowest


scene_file = os.path.join(work, "input", "scene.yaml")
with open(scene_file) as f:
    banner_scene = f.read()  # the long run below is the banner's
bpy.ops.mesh.primitive_plane_add(size=0.5, location=(5, 0, 1.0))
square = bpy.context.active_object
square.name = "Square"
bpy.ops.mesh.primitive_cube_add(size=0.6, location=(5, 0, 0.0))  # its top at 0.3 m
floor = bpy.context.active_object
bpy.ops.mesh.primitive_plane_add(size=2.0, location=(5, 0, 0.6))
shelf = bpy.context.active_object
settings.pin_group = ""
for what, expected in (("ground", 0.4), ("floor", 0.3), ("collider", 0.6)):
    settings.ground_height = 0.4 if what == "ground" else 0.0
    settings.floor = floor if what == "floor" else None
    shelf.dinam_collider = what == "collider"
    bpy.ops.object.select_all(action="DESELECT")
    square.select_set(True)
    assert bpy.ops.dinam.simulate() == {"FINISHED"}
    lowest = lowest_at_last_frame(square)
    print(f"addon: the square dropped on the {what} rests at z = {lowest:.4f} m "
          f"(the {what} at {expected} m)")
    # Resting on it, within the contact's reach (the collider's 1 cm shell and the cloth's own
    # radius, less the penalty's give under its weight), never through it.
    reach = settings.collider_radius if what == "collider" else 0.0
    assert expected + reach - 0.005 <= lowest <= expected + reach + 0.005, (what, lowest)
    assert shelf.modifiers.get("dinam") is None, "the collider was given a cache"
    with open(scene_file) as f:
        assert "point_cache" not in f.read(), "a collider that stays put was given a track"
# A collider the animation moves: the shelf keyed from 0.6 m at the first frame to 0.9 m at the
# last lifts the square with it, through the track dinam reads from the PC2 the add-on wrote.
shelf.location.z = 0.6
shelf.keyframe_insert("location", index=2, frame=scene.frame_start)
shelf.location.z = 0.9
shelf.keyframe_insert("location", index=2, frame=scene.frame_end)
scene.frame_set(scene.frame_start)
bpy.ops.object.select_all(action="DESELECT")
square.select_set(True)
assert bpy.ops.dinam.simulate() == {"FINISHED"}, settings.last_report
with open(scene_file) as f:
    written = f.read()
assert f'pin_motion: {{point_cache: "{shelf.name}.pc2"}}' in written, written
lowest = lowest_at_last_frame(square)
print(f"addon: the square on the rising collider rests at z = {lowest:.4f} m (the collider at "
      "0.9 m at the last frame)")
assert 0.9 + settings.collider_radius - 0.005 <= lowest <= 0.9 + settings.collider_radius + 0.005, \
    lowest
shelf.animation_data_clear()
shelf.location.z = 0.6
shelf.dinam_collider = False
# Turbulence, gusts, self-contact and a settle first reach the scene, and dinam takes them.
settings.wind, settings.turbulence, settings.gust = (0.0, 3.0, 0.0), 0.5, 1.0
settings.self_contact, settings.settle = True, True
bpy.ops.object.select_all(action="DESELECT")
square.select_set(True)
assert bpy.ops.dinam.simulate() == {"FINISHED"}, settings.last_report
with open(scene_file) as f:
    written = f.read()
for line in ("wind: {velocity: [0.0, 3.0, 0.0], turbulence: {amplitude: 0.5}, "
             "gust: {amplitude: 1.0}}", "settle: {}", "contact: {objects: true, self: true}"):
    assert line in written, (line, written)
print("addon: turbulence, gusts, self-contact and settle reach the scene")
settings.wind, settings.turbulence, settings.gust = (0.0, 4.0, 0.0), 0.0, 0.0
settings.self_contact, settings.settle = False, False
with open(scene_file, "w") as f:
    f.write(banner_scene)
settings.floor = None
settings.ground_height = 0.0
settings.pin_group = "pins"

# The progress the panel shows comes from dinam's lines on stderr.
short = dinam_run.DinamRun(dinam_run.find_dinam(dinam), os.path.join(work, "input", "scene.yaml"),
                           os.path.join(work, "again"))
assert short.wait() == 0 and short.fraction == 1.0, (short.fraction, short.message())
print("addon: the progress reached 100 %")

with open(os.path.join(cache, "manifest.json")) as f:
    before = f.read()
long_scene = os.path.join(work, "input", "scene.yaml")
with open(long_scene) as f:
    text = f.read().replace("duration: 1.0", "duration: 600.0")
with open(long_scene, "w") as f:
    f.write(text)
run = dinam_run.DinamRun(dinam_run.find_dinam(dinam), long_scene, cache)
time.sleep(1.0)
assert run.poll() is None, "the long run ended by itself: " + run.message()
code = run.cancel()
assert code == 143, (code, run.message())
with open(os.path.join(cache, "manifest.json")) as f:
    assert f.read() == before, "a cancelled run changed the cache"
assert not [n for n in os.listdir(work) if ".part-" in n], os.listdir(work)
print("addon: a cancelled run leaves the cache as it was")

# The panel's Cancel never waits: request_cancel returns at once and poll() sees the end; a
# program that ignores SIGTERM is killed after the grace period.
stubborn = os.path.join(work, "stubborn")
with open(stubborn, "w") as f:
    # SIGTERM stays ignored in sleep; the marker says the trap is set.
    f.write("#!/bin/sh\ntrap '' TERM\n: > \"$0.ready\"\nexec sleep 60\n")
os.chmod(stubborn, 0o755)
run = dinam_run.DinamRun(stubborn, long_scene, os.path.join(work, "never"))
# Waits without a deadline that a busy machine could miss: a minute at most, never asserted on.
for _ in range(1200):
    if os.path.exists(stubborn + ".ready"):
        break
    time.sleep(0.05)
run.request_cancel(grace=0.5)
assert run.poll() is None, "the stubborn program ended at once"
code = None
for _ in range(1200):
    code = run.poll()
    if code is not None:
        break
    time.sleep(0.05)
assert code == -9, code  # killed (SIGKILL) once the grace had passed
print("addon: a program that ignores SIGTERM is killed after the grace period")

# Each object its own material and pins: a cape of denim pinned at its collar (its own vertex
# group, in its Object properties) beside the banner of the panel's cotton pinned by the panel's
# group. Before the motion, dinam's estimate; Estimate alone runs no simulation.
bpy.ops.mesh.primitive_grid_add(x_subdivisions=6, y_subdivisions=6, size=0.8,
                                location=(-2.0, 0.0, 1.5), rotation=(1.5708, 0.0, 0.0))
cape = bpy.context.active_object
cape.name = "Cape"
collar_top = max((cape.matrix_world @ v.co).z for v in cape.data.vertices)
collar = [v.index for v in cape.data.vertices if (cape.matrix_world @ v.co).z > collar_top - 1e-6]
cape.vertex_groups.new(name="collar").add(collar, 1.0, "REPLACE")
cape_rest = [cape.matrix_world @ v.co for v in cape.data.vertices]
cape.dinam_preset, cape.dinam_pin_group = "denim", "collar"
settings.preset, settings.pin_group = "cotton", "pins"
bpy.ops.object.select_all(action="DESELECT")
banner.select_set(True)
cape.select_set(True)
assert bpy.ops.dinam.estimate() == {"FINISHED"}
assert "estimate: " in settings.last_report and "to simulate" in settings.last_report and "dinam recommends integrator" in \
    settings.last_report, settings.last_report
assert cape.modifiers.get("dinam") is None, "Estimate simulated"
print("addon: " + settings.last_report.splitlines()[-1])
assert bpy.ops.dinam.simulate() == {"FINISHED"}, settings.last_report
assert "to simulate" in settings.last_report, settings.last_report
with open(scene_file) as f:
    written = f.read()
cape_entry = written[written.index('name: "Cape"'):]
banner_entry = written[written.index('name: "Banner"'):written.index('name: "Cape"')]
assert "material: {preset: denim}" in cape_entry, cape_entry
assert "material: {preset: cotton}" in banner_entry, banner_entry
assert f"pinned: {{indices: [{', '.join(str(i) for i in collar)}]}}" in cape_entry, cape_entry
scene.frame_set(scene.frame_end)
evaluated = cape.evaluated_get(bpy.context.evaluated_depsgraph_get())
mesh = evaluated.to_mesh()
cape_end = [cape.matrix_world @ v.co for v in mesh.vertices]
evaluated.to_mesh_clear()
collar_moved = max((cape_end[i] - cape_rest[i]).length for i in collar)
cape_moved = max((p - q).length for p, q in zip(cape_end, cape_rest))
print(f"addon: the cape (denim, its own collar pins) hangs: collar moved {collar_moved:.2g} m, "
      f"the cape up to {cape_moved:.3f} m")
assert collar_moved <= 1e-5 and cape_moved > 0.01, (collar_moved, cape_moved)
# Its own group, missing, is refused, naming where it was chosen.
cape.dinam_pin_group = "colar"
try:
    bpy.ops.dinam.simulate()
    raise AssertionError("a missing object pin group was simulated")
except RuntimeError as e:
    assert "has no vertex group 'colar'" in str(e) and "Object properties" in str(e), e
    print("addon: refused: " + str(e).strip().splitlines()[-1])
cape.dinam_pin_group = "collar"
# A scene dinam refuses is said by Estimate too, as dinam says it.
settings.preset, settings.youngs_modulus = "CUSTOM", 1e30
cape.dinam_preset = "PANEL"
try:
    bpy.ops.dinam.estimate()
    raise AssertionError("an impossible material was estimated")
except RuntimeError as e:
    assert "youngs_modulus" in str(e), e
    print("addon: Estimate says what dinam refuses: " + str(e).strip().splitlines()[-1][:120])
settings.preset, settings.youngs_modulus = "cotton", 2.0e7
cape.dinam_preset = "denim"

# The look travels: the banner's red material (Principled base colour, linear as Blender keeps
# it), the cape's image texture (its UVs with it), and a collider as modelled (a cylinder, flat
# shaded: no material, nothing subdivided). The scene is named after the .blend, whose run has a
# folder of its own within //dinam.
red = bpy.data.materials.new("Red")
red.use_nodes = True
red.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.8, 0.1, 0.05, 1.0)
banner.data.materials.append(red)
checker = bpy.data.images.new("Checker", 4, 4)
checker.pixels = [c for k in range(16) for c in ((1.0, 1.0, 1.0, 1.0) if (k + k // 4) % 2
                                                  else (0.1, 0.2, 0.6, 1.0))]
printed = bpy.data.materials.new("Printed")
printed.use_nodes = True
image_node = printed.node_tree.nodes.new("ShaderNodeTexImage")
image_node.image = checker
printed.node_tree.links.new(image_node.outputs["Color"],
                            printed.node_tree.nodes["Principled BSDF"].inputs["Base Color"])
cape.data.materials.append(printed)
assert cape.data.uv_layers.active is not None
bpy.ops.mesh.primitive_cylinder_add(vertices=24, radius=0.3, depth=0.6, location=(0.0, 2.0, 0.3))
post = bpy.context.active_object
post.name = "Post"
post.dinam_collider = True
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(work, "shot.blend"))
settings.folder = "//dinam"
bpy.ops.object.select_all(action="DESELECT")
banner.select_set(True)
cape.select_set(True)
assert bpy.ops.dinam.simulate() == {"FINISHED"}, settings.last_report
shot = os.path.join(work, "dinam", "shot")
with open(os.path.join(shot, "input", "scene.yaml")) as f:
    written = f.read()
banner_entry = written[written.index('name: "Banner"'):written.index('name: "Cape"')]
cape_entry = written[written.index('name: "Cape"'):written.index('name: "Post"')]
post_entry = written[written.index('name: "Post"'):]
assert 'name: "shot"' in written, written[:200]
colour = [float(c) for c in
          banner_entry.split("color: {linear: [")[1].split("]")[0].split(",")]
assert max(abs(a - b) for a, b in zip(colour, (0.8, 0.1, 0.05))) < 1e-6, banner_entry
assert 'texture: "Cape.png"' in cape_entry, cape_entry
assert os.path.getsize(os.path.join(shot, "input", "Cape.png")) > 0
with open(os.path.join(shot, "input", "Cape.obj")) as f:
    assert "\nvt " in f.read(), "the textured cape's OBJ has no UVs"
assert "role: collider" in post_entry and "material" not in post_entry, post_entry
assert "shading: flat" in post_entry, post_entry
assert os.path.exists(os.path.join(shot, "cache", "manifest.json"))
print(f"addon: the look travels: name \"shot\", the banner's colour {colour}, the cape's "
      f"texture, the post a flat-shaded collider; the run in {os.path.relpath(shot, work)}")
# dinam draws that scene from its cache: the movie is named after the .blend.
movie = os.path.join(work, "movie")
drawn = subprocess.run([dinam, "render", os.path.join(shot, "input", "scene.yaml"), "--cache",
                        os.path.join(shot, "cache"), "-o", movie, "--size", "160x90", "--quiet"],
                       capture_output=True, text=True)
assert drawn.returncode == 0, drawn.stderr
assert os.path.exists(os.path.join(movie, "shot.mp4")), os.listdir(movie)
print("addon: dinam render of the add-on's scene writes shot.mp4")

# Another .blend in the same folder has its run apart; the first's cache is left as it was. A
# .blend of the same name elsewhere, sharing an absolute folder, is refused.
with open(os.path.join(shot, "cache", "Banner.pc2"), "rb") as f:
    shot_motion = f.read()
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(work, "take2.blend"))
settings.wind = (0.0, -4.0, 0.0)
# The post shaded smooth with Auto Smooth at 40°: smooth sides, sharp rims, as Blender draws it.
for polygon in post.data.polygons:
    polygon.use_smooth = True
post.data.use_auto_smooth, post.data.auto_smooth_angle = True, math.radians(40.0)
assert bpy.ops.dinam.simulate() == {"FINISHED"}, settings.last_report
with open(os.path.join(work, "dinam", "take2", "input", "scene.yaml")) as f:
    post_entry = f.read().split('name: "Post"')[1]
assert "shading: auto" in post_entry and "sharp_angle: 40.0" in post_entry, post_entry
with open(os.path.join(shot, "cache", "Banner.pc2"), "rb") as f:
    assert f.read() == shot_motion, "another .blend's run changed the first's cache"
assert os.path.exists(os.path.join(work, "dinam", "take2", "cache", "manifest.json"))
os.makedirs(os.path.join(work, "elsewhere"))
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(work, "elsewhere", "shot.blend"))
settings.folder = os.path.join(work, "dinam")
try:
    bpy.ops.dinam.simulate()
    raise AssertionError("a folder holding another file's run was used")
except RuntimeError as e:
    assert "holds the run of" in str(e) and os.path.join(work, "shot.blend") in str(e), e
    print("addon: refused: " + str(e).strip().splitlines()[-1][:150])
with open(os.path.join(shot, "cache", "Banner.pc2"), "rb") as f:
    assert f.read() == shot_motion
print("addon: each .blend its own run: take2's apart, shot's cache as it was")
settings.wind = (0.0, 4.0, 0.0)
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(work, "tie.blend"))
settings.folder = "//dinam"

# A tie: the cape's collar tied to a hook (a collider, keyed to rise 0.3 m) instead of pinned
# moves up with it.
collar_z = max((cape.matrix_world @ v.co).z for v in cape.data.vertices)
bpy.ops.mesh.primitive_plane_add(size=1.0, location=(-2.0, 0.0, collar_z + 0.03))
hook = bpy.context.active_object
hook.name = "Hook"
hook.dinam_collider = True
hook.keyframe_insert("location", index=2, frame=scene.frame_start)
hook.location.z += 0.3
hook.keyframe_insert("location", index=2, frame=scene.frame_end)
scene.frame_set(scene.frame_start)
post.dinam_collider = False
settings.pin_group, cape.dinam_pin_group = "", ""
cape.dinam_attach_group, cape.dinam_attach_to = "collar", hook
bpy.ops.object.select_all(action="DESELECT")
cape.select_set(True)
assert bpy.ops.dinam.simulate() == {"FINISHED"}, settings.last_report
with open(os.path.join(work, "dinam", "tie", "input", "scene.yaml")) as f:
    written = f.read()
assert 'to: "Hook"' in written and "attach:" in written, written
scene.frame_set(scene.frame_end)
evaluated = cape.evaluated_get(bpy.context.evaluated_depsgraph_get())
mesh = evaluated.to_mesh()
rose = [(cape.matrix_world @ mesh.vertices[i].co).z - cape_rest[i].z for i in collar]
evaluated.to_mesh_clear()
print(f"addon: the collar tied to the hook rose {min(rose):.3f} to {max(rose):.3f} m with it "
      "(0.3 m)")
assert all(abs(r - 0.3) < 0.01 for r in rose), rose
# A tie to an object that is neither simulated nor a collider is refused.
hook.dinam_collider = False
try:
    bpy.ops.dinam.simulate()
    raise AssertionError("a tie to an object dinam does not see was simulated")
except RuntimeError as e:
    assert "which is not simulated" in str(e), e
    print("addon: refused: " + str(e).strip().splitlines()[-1])
print("addon: PASS")
