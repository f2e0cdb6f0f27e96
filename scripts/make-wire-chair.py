#!/usr/bin/env python3
"""Writes assets/wire_chair.ply: a chair bent from one gauge of wire, as PLY two-vertex faces
(line elements, which assimp reads as edges). Every straight member is cut into segments of about
7.5 cm so that it can bend at their joints. Standard library only.

The chair stands on the plane z = 0 with its seat centred on the z axis, 0.45 m up, its back
towards +y.

    python3 scripts/make-wire-chair.py
"""
import math
from pathlib import Path

from wire_mesh import WireMesh

SEGMENT = 0.075      # m, longest segment
SEAT, HALF = 0.45, 0.22
FOOT = 0.25          # half-spread of the feet: the legs lean out a little
BACK_TOP = 0.95
BACK_RAIL = SEAT + 4 * (BACK_TOP - SEAT) / 7   # on the 4th of the uprights' 7 joints

mesh = WireMesh(SEGMENT)
member = mesh.member

corners = [(sx * HALF, sy * HALF, SEAT) for sx in (-1, 1) for sy in (-1, 1)]
for (x, y, z) in corners:                               # legs
    member((math.copysign(FOOT, x), math.copysign(FOOT, y), 0.0), (x, y, z))
for a, b in ((0, 1), (1, 3), (3, 2), (2, 0)):           # the seat's frame
    member(corners[a], corners[b])
member((-HALF, -HALF / 3, SEAT), (HALF, -HALF / 3, SEAT))  # two slats across the seat
member((-HALF, HALF / 3, SEAT), (HALF, HALF / 3, SEAT))
for x in (-HALF, HALF):                                 # the back's uprights
    member((x, HALF, SEAT), (x, HALF, BACK_TOP))
member((-HALF, HALF, BACK_TOP), (HALF, HALF, BACK_TOP))  # its top rail and a middle rail
member((-HALF, HALF, BACK_RAIL), (HALF, HALF, BACK_RAIL))

# Slats and rails meet the seat's sides and the uprights at joints they share: one piece of wire.
mesh.check()
vertices, edges = mesh.vertices, mesh.edges

lines = ["ply", "format ascii 1.0", "comment dinam scripts/make-wire-chair.py: a wire chair",
         f"element vertex {len(vertices)}", "property float x", "property float y",
         "property float z", f"element face {len(edges)}",
         "property list uchar int vertex_indices", "end_header"]
lines += [f"{x:.6f} {y:.6f} {z:.6f}" for x, y, z in vertices]
lines += [f"2 {a} {b}" for a, b in edges]
out = Path(__file__).resolve().parent.parent / "assets" / "wire_chair.ply"
out.write_text("\n".join(lines) + "\n")
print(f"wrote {out}: {len(vertices)} vertices, {len(edges)} edges")
