"""The artist's mesh the Blender tests start from: a 1 m plane stood upright (its object turned 90°
about x) and subdivided in Blender with five cuts, so that its 49 vertices are numbered as
Blender numbers a subdivided mesh, which its faces do not meet in order."""
import bpy


def subdivided_banner(location):
    bpy.ops.mesh.primitive_plane_add(size=1.0, location=location, rotation=(1.5707963, 0, 0))
    banner = bpy.context.active_object
    banner.name = "Banner"
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.subdivide(number_cuts=5)
    bpy.ops.object.mode_set(mode="OBJECT")
    return banner
