#!/usr/bin/env python3
"""Writes assets/rope_coil.obj: a rope of about 3.5 m paid out in loose turns, as a hand lays a rope down
onto a pile, for scenes/rope_heap.yaml. OBJ line elements ('l'); standard library only.

Six turns rise from 3 cm above the floor, 8 cm apart, so the lowest lands first and each turn
then falls onto those below: the way a heap forms, turn on turn. A hand's turns are not
circles: the radius wanders between about 6 and 11.5 cm and the centre drifts, so turns land
partly inside and partly across the ones below instead of stacking into a neat coil. 150
segments of equal length (2.3 cm).

    python3 scripts/make-rope-coil.py
"""
import math
from pathlib import Path

TURNS, SEGMENTS = 6.0, 150
BOTTOM, RISE = 0.03, 0.08  # m: the lowest point, and the height gained per turn


def point(t):
    """The rope's centreline at parameter t in [0, 1] (not yet of uniform speed)."""
    angle = 2.0 * math.pi * TURNS * t
    radius = 0.085 + 0.022 * math.sin(1.7 * angle + 0.4) + 0.008 * math.sin(3.1 * angle)
    cx = 0.025 * math.sin(0.45 * angle)
    cy = 0.02 * math.cos(0.6 * angle + 1.0)
    return (cx + radius * math.cos(angle), cy + radius * math.sin(angle),
            BOTTOM + RISE * TURNS * t)


# Resampled by arc length, so that every segment is as long.
fine = [point(k / 20000) for k in range(20001)]
arc = [0.0]
for a, b in zip(fine, fine[1:]):
    arc.append(arc[-1] + math.dist(a, b))
vertices, j = [], 0
for k in range(SEGMENTS + 1):
    s = arc[-1] * k / SEGMENTS
    while j < len(arc) - 2 and arc[j + 1] < s:
        j += 1
    w = (s - arc[j]) / (arc[j + 1] - arc[j])
    vertices.append(tuple(p + w * (q - p) for p, q in zip(fine[j], fine[j + 1])))

length = sum(math.dist(a, b) for a, b in zip(vertices, vertices[1:]))
lines = [f"# dinam scripts/make-rope-coil.py: a rope of {length:.3f} m in {TURNS:g} loose turns, "
         f"{SEGMENTS} segments, z up"]
lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in vertices]
lines += [f"l {k + 1} {k + 2}" for k in range(SEGMENTS)]
out = Path(__file__).resolve().parent.parent / "assets" / "rope_coil.obj"
out.write_text("\n".join(lines) + "\n")
print(f"wrote {out}: {len(vertices)} vertices, {SEGMENTS} edges, {length:.3f} m")
