#!/usr/bin/env python3
"""Writes assets/wire_ball.obj: a wireframe sphere of meridians and parallels as OBJ line elements
('l'), the soft ball of the paper's second example. Standard library only.

    python3 scripts/make-ball-mesh.py [--meridians 16] [--parallels 7] [--radius 0.5]
"""
import argparse
import math
from pathlib import Path

parser = argparse.ArgumentParser()
parser.add_argument("--meridians", type=int, default=16)
parser.add_argument("--parallels", type=int, default=7, help="rings between the two poles")
parser.add_argument("--radius", type=float, default=0.5)
args = parser.parse_args()

m, p, r = args.meridians, args.parallels, args.radius
vertices = [(0.0, 0.0, r)]  # north pole: vertex 1
for ring in range(1, p + 1):
    theta = math.pi * ring / (p + 1)
    for k in range(m):
        phi = 2 * math.pi * k / m
        vertices.append((r * math.sin(theta) * math.cos(phi), r * math.sin(theta) * math.sin(phi),
                         r * math.cos(theta)))
vertices.append((0.0, 0.0, -r))  # south pole
north, south = 1, len(vertices)


def ring_vertex(ring, k):  # 1-based OBJ index
    return 2 + (ring - 1) * m + (k % m)


lines = []
for k in range(m):  # meridians, pole to pole
    lines.append([north] + [ring_vertex(ring, k) for ring in range(1, p + 1)] + [south])
for ring in range(1, p + 1):  # parallels, closed loops
    lines.append([ring_vertex(ring, k) for k in range(m + 1)])

out = Path(__file__).resolve().parent.parent / "assets" / "wire_ball.obj"
with out.open("w") as f:
    f.write(f"# Wireframe sphere, radius {r} m: {m} meridians and {p} parallels as line elements.\n")
    f.write(f"# {len(vertices)} nodes, {m * (p + 1) + m * p} bars. Made by scripts/make-ball-mesh.py.\n")
    for x, y, z in vertices:
        f.write(f"v {x:.6f} {y:.6f} {z:.6f}\n")
    for line in lines:
        f.write("l " + " ".join(str(i) for i in line) + "\n")
print(f"wrote {out}: {len(vertices)} vertices, {m * (p + 1) + m * p} bars")
