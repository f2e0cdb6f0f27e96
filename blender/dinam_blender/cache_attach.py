"""Puts a dinam cache on the objects it was made from: a Mesh Cache modifier each, first in the
stack, reading the object's PC2 from its first frame at the scene's start.

The cache holds world coordinates; a modifier moves the mesh in the object's own space. An object
whose transform is not the identity gets a copy of its PC2 in that space (its matrix's inverse
applied to every point), beside the cache.
"""
import array
import json
import os
import sys

MODIFIER_NAME = "dinam"


class AttachError(Exception):
    pass


def read_manifest(cache):
    with open(os.path.join(cache, "manifest.json")) as f:
        return json.load(f)


def local_pc2(world_pc2, matrix, out_path):
    """Writes `world_pc2` with the inverse of `matrix` applied to every point (plain Python:
    Debian's Blender runs on the system's Python, which may have no numpy)."""
    with open(world_pc2, "rb") as f:
        header = f.read(32)
        values = array.array("f")
        values.frombytes(f.read())
    if sys.byteorder != "little":
        values.byteswap()
    m = [list(row) for row in matrix.inverted()]
    local = array.array("f", bytes(4 * len(values)))
    for k in range(0, len(values), 3):
        x, y, z = values[k], values[k + 1], values[k + 2]
        for c in range(3):
            local[k + c] = m[c][0] * x + m[c][1] * y + m[c][2] * z + m[c][3]
    if sys.byteorder != "little":
        local.byteswap()
    with open(out_path, "wb") as f:
        f.write(header)
        f.write(local.tobytes())


def attach(context, objects, cache, local_folder):
    """Gives each of `objects` (by name in the cache) its Mesh Cache modifier."""
    import bpy

    manifest = read_manifest(cache)
    entries = {e["name"]: e for e in manifest["objects"]}
    for obj in objects:
        entry = entries.get(obj.name)
        if entry is None:
            raise AttachError(f"the cache has no object '{obj.name}'")
        if "source_vertices" in entry or entry["node_count"] != len(obj.data.vertices):
            raise AttachError(
                f"the cache of '{obj.name}' does not hold its vertices one for one (dinam welded "
                "vertices at the same place, or dropped loose ones): merge them by distance first")
        path = os.path.join(cache, entry["files"]["pc2"])
        identity = all(abs(obj.matrix_world[i][j] - (1.0 if i == j else 0.0)) < 1e-12
                       for i in range(4) for j in range(4))
        if not identity:
            os.makedirs(local_folder, exist_ok=True)
            local = os.path.join(local_folder, entry["files"]["pc2"])
            local_pc2(path, obj.matrix_world, local)
            path = local
        modifier = obj.modifiers.get(MODIFIER_NAME)
        if modifier is None or modifier.type != "MESH_CACHE":
            modifier = obj.modifiers.new(MODIFIER_NAME, "MESH_CACHE")
        modifier.cache_format = "PC2"
        modifier.filepath = path
        modifier.frame_start = context.scene.frame_start
        modifier.forward_axis = "POS_Y"
        modifier.up_axis = "POS_Z"
        if obj.modifiers[0] != modifier:
            with context.temp_override(object=obj, active_object=obj):
                bpy.ops.object.modifier_move_to_index(modifier=modifier.name, index=0)
