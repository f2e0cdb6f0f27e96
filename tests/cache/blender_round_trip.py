# The round trip onto the artist's own object, in Blender itself (headless), in two calls:
#
#   blender -b --factory-startup --python-exit-code 1 --python THIS -- make OUT.obj OUT.blend
#   blender -b OUT.blend --python-exit-code 1 --python THIS -- check CACHE OBJECT_NAME
#
# `make` builds what an artist has: a plane subdivided in Blender (so that its faces meet its
# vertices out of order), its transforms applied, exported as OBJ the way the README says
# (File > Export > Wavefront (.obj): Forward Axis Y, Up Axis Z, UVs and materials on), and saved.
# `check` opens that saved file, gives the artist's own object (not the OBJ dinam wrote) a Mesh
# Cache modifier on the object's PC2 and compares its vertices at several frames with the PC2
# read here with Python's struct module. It passes only when the cache's points are the artist's
# vertices in their order. Prints "round-trip: PASS"; raises otherwise.
import json
import os
import sys

import bpy
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_banner import subdivided_banner  # noqa: E402  (beside this file)
from pc2_reader import read_pc2  # noqa: E402  (beside this file)


def make(out_obj, out_blend):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    plane = subdivided_banner((0, 0, 1.5))
    bpy.ops.object.transform_apply(location=True, rotation=True, scale=True)
    bpy.ops.wm.obj_export(filepath=out_obj, forward_axis="Y", up_axis="Z", export_uv=True,
                          export_materials=True, export_selected_objects=True)
    # The test means something only if assimp's order (face corners, face by face) is not the
    # file's: check that the faces meet the vertices out of order.
    first_seen = []
    for polygon in plane.data.polygons:
        for v in polygon.vertices:
            if v not in first_seen:
                first_seen.append(v)
    assert first_seen != sorted(first_seen), "the subdivided plane's faces meet its vertices in order"
    bpy.ops.wm.save_as_mainfile(filepath=out_blend)
    print(f"round-trip: made {len(plane.data.vertices)} vertices")


def check(cache, object_name):
    with open(os.path.join(cache, "manifest.json")) as f:
        manifest = json.load(f)
    entry = next(o for o in manifest["objects"] if o["name"] == object_name)
    assert "source_vertices" not in entry, "the cache maps its points: they are not in file order"
    obj = bpy.data.objects["Banner"]
    cached = read_pc2(os.path.join(cache, entry["files"]["pc2"]))
    assert len(cached[0]) == len(obj.data.vertices), (len(cached[0]), len(obj.data.vertices))
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, manifest["frame_count"]
    modifier = obj.modifiers.new("dinam", "MESH_CACHE")
    modifier.cache_format = "PC2"
    modifier.filepath = os.path.join(cache, entry["files"]["pc2"])
    modifier.frame_start = 1
    frame_count = manifest["frame_count"]
    for frame in sorted({1, 2, (frame_count + 1) // 2, frame_count}):
        scene.frame_set(frame)
        evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
        mesh = evaluated.to_mesh()
        worst = max(abs(a - b) for v, p in zip(mesh.vertices, cached[frame - 1])
                    for a, b in zip(v.co, p))
        evaluated.to_mesh_clear()
        print(f"round-trip: frame {frame}: the artist's vertices are the cache's to {worst:.2g} m")
        assert worst <= 1e-6, f"frame {frame}: {worst} m"
    moved = max(abs(a - b) for p, q in zip(cached[0], cached[-1]) for a, b in zip(p, q))
    assert moved > 0.01, f"the banner hardly moved ({moved} m): the check would prove nothing"
    print("round-trip: PASS")


args = sys.argv[sys.argv.index("--") + 1:]
{"make": make, "check": check}[args[0]](*args[1:])
