#!/usr/bin/env python3
"""Writes assets/frame_tower.obj: a five-storey moment frame, the classic model building of a
shaking-table demonstration, as OBJ line elements ('l'). Standard library only.

Four columns rise from the corners of a 0.8 m square, 0.6 m per storey; at each floor four beams
and two crossing diagonals make the floor stiff in its plane, while the storeys themselves have
no bracing, so the building sways by bending its columns. Columns are cut into three segments
per storey, beams and half-diagonals into segments of about 0.2 m. The feet are at z = 0.

    python3 scripts/make-frame-tower.py
"""
from pathlib import Path

from wire_mesh import WireMesh

STOREYS, STOREY_HEIGHT, HALF = 5, 0.6, 0.4
COLUMN_SEGMENTS, SEGMENT = 3, 0.2

mesh = WireMesh(SEGMENT)
member = mesh.member

corners = [(-HALF, -HALF), (HALF, -HALF), (HALF, HALF), (-HALF, HALF)]
for floor in range(1, STOREYS + 1):
    z0, z1 = (floor - 1) * STOREY_HEIGHT, floor * STOREY_HEIGHT
    for x, y in corners:
        member((x, y, z0), (x, y, z1), COLUMN_SEGMENTS)
    for k in range(4):
        member((*corners[k], z1), (*corners[(k + 1) % 4], z1))
    for x, y in corners:  # two diagonals, meeting at the floor's centre
        member((x, y, z1), (0.0, 0.0, z1))

mesh.check()
vertices, edges = mesh.vertices, mesh.edges
lines = ["# dinam scripts/make-frame-tower.py: a five-storey moment frame, z up, feet at z = 0"]
lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in vertices]
lines += [f"l {a + 1} {b + 1}" for a, b in edges]
out = Path(__file__).resolve().parent.parent / "assets" / "frame_tower.obj"
out.write_text("\n".join(lines) + "\n")
print(f"wrote {out}: {len(vertices)} vertices, {len(edges)} edges")
