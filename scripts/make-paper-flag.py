#!/usr/bin/env python3
"""Writes assets/paper_flag.gltf: the flag of the paper's first example, its cloth and its tie
ropes as one mesh of exactly 245 nodes and 579 bars (edges). Standard library only.

The cloth is a 15 × 11 grid of 0.1 m cells, each split by one diagonal (two triangles), which
gives 192 nodes and 521 edges. The ropes are line elements:
  - five ties, each a loop from a node of the hoist edge around the pole and back to it
    (5 new nodes and 6 edges each, three of the new nodes on the pole, to be pinned);
  - the halyard: from the top corner up to the pole's top (3 edges), from the bottom corner down
    to a cleat on the pole (14 edges), and its loose end hanging from the cleat (11 edges).
That is 192 + 25 + 28 = 245 nodes and 521 + 30 + 28 = 579 edges; the script checks both. The
cloth's triangles have the material "cloth" (with the texture), the rope's lines "rope", so a scene
can give each its own physical material (`parts: [{mesh_material: rope, ...}]`).

The cloth bows 1 cm out of its plane (a sine across its length), as a real flag never hangs
perfectly flat. A flat cloth hanging in its own plane is a symmetric problem: when it buckles
under its own weight, the side it folds to is decided by rounding, so its settled shape would
change with the last bits of a sum; the bow decides it instead.

glTF is y-up, so the file holds (x, z, -y) of dinam's z-up world; scenes turn it upright with
`rotation: [90, 0, 0]`. The pole's axis is the world z axis, and every node to be pinned lies
within 0.032 m of it in x and y; no other node does.

    python3 scripts/make-paper-flag.py
"""
import base64
import json
import math
import struct
from pathlib import Path

COLUMNS, ROWS, CELL = 15, 11, 0.1
HOIST_X, BOTTOM_Z = 0.08, 2.6           # the cloth's hoist edge and its lower edge, m
TIE_ROWS = (0, 3, 6, 8, 11)             # hoist nodes with a tie around the pole
RING = 0.03                             # radius of a tie's loop around the pole, m
POLE_TOP, CLEAT_Z, CLEAT_X = 4.0, 1.2, 0.03
TAIL_SEGMENTS, TAIL_X = 11, 0.06
CAMBER = 0.01                           # the cloth's bow out of its plane, m (see below)

# --- the cloth: vertices (x, z) in its plane y = 0, u along the flag, v down from the top
cloth = []
uvs = []
for j in range(ROWS + 1):
    for i in range(COLUMNS + 1):
        cloth.append((HOIST_X + CELL * i, CAMBER * math.sin(math.pi * i / COLUMNS),
                      BOTTOM_Z + CELL * j))
        uvs.append((i / COLUMNS, 1.0 - j / ROWS))


def cloth_id(i, j):
    return j * (COLUMNS + 1) + i


triangles = []
for j in range(ROWS):
    for i in range(COLUMNS):
        a, b = cloth_id(i, j), cloth_id(i + 1, j)
        c, d = cloth_id(i + 1, j + 1), cloth_id(i, j + 1)
        triangles += [(a, b, c), (a, c, d)]

# --- the ropes: their own vertex list; cloth nodes they start from are repeated there (welded)
rope = []
lines = []


def rope_vertex(p):
    rope.append(p)
    return len(rope) - 1


def polyline(points):
    ids = [rope_vertex(p) for p in points]
    lines.extend(zip(ids[:-1], ids[1:]))
    return ids


def lerp(p, q, t):
    return tuple(a + (b - a) * t for a, b in zip(p, q))


for row in TIE_ROWS:
    z = BOTTOM_Z + CELL * row
    hoist = (HOIST_X, 0.0, z)
    polyline([hoist, (0.045, 0.025, z), (0.0, RING, z), (-RING, 0.0, z), (0.0, -RING, z),
              (0.045, -0.025, z), hoist])

top_corner = (HOIST_X, 0.0, BOTTOM_Z + CELL * ROWS)
bottom_corner = (HOIST_X, 0.0, BOTTOM_Z)
cleat = (CLEAT_X, 0.0, CLEAT_Z)
polyline([lerp(top_corner, (CLEAT_X, 0.0, POLE_TOP), k / 3) for k in range(4)])
polyline([lerp(bottom_corner, cleat, k / 14) for k in range(15)])
tail_top = (TAIL_X, 0.0, CLEAT_Z - 0.08)
polyline([cleat] + [lerp(tail_top, (TAIL_X, 0.0, CLEAT_Z - 0.08 * TAIL_SEGMENTS), k / 10)
                    for k in range(TAIL_SEGMENTS)])


# --- check the counts as dinam will weld them
def key(p):
    return tuple(round(c, 9) for c in p)


nodes = {key(p) for p in cloth} | {key(p) for p in rope}
edges = set()
for t in triangles:
    for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
        edges.add(frozenset((key(cloth[a]), key(cloth[b]))))
for a, b in lines:
    edges.add(frozenset((key(rope[a]), key(rope[b]))))
assert len(nodes) == 245 and len(edges) == 579, (len(nodes), len(edges))
pinned = [p for p in nodes if abs(p[0]) <= 0.032 and abs(p[1]) <= 0.032 and 0.0 <= p[2] <= 5.0]
assert len(pinned) == 3 * len(TIE_ROWS) + 2, len(pinned)


# --- glTF: y-up, so (x, y, z) of dinam's world is stored as (x, z, -y)
def to_gltf(p):
    return (p[0], p[2], -p[1])


blob = bytearray()
views, accessors = [], []


def add_accessor(values, fmt, component_type, kind, target, with_bounds=False):
    while len(blob) % 4:
        blob.append(0)
    offset = len(blob)
    for v in values:
        blob.extend(struct.pack(fmt, *v))
    views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob) - offset,
                  "target": target})
    accessor = {"bufferView": len(views) - 1, "componentType": component_type,
                "count": len(values), "type": kind}
    if with_bounds:
        accessor["min"] = [min(v[k] for v in values) for k in range(3)]
        accessor["max"] = [max(v[k] for v in values) for k in range(3)]
    accessors.append(accessor)
    return len(accessors) - 1


FLOAT, UNSIGNED_SHORT, ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 5126, 5123, 34962, 34963
cloth_positions = add_accessor([to_gltf(p) for p in cloth], "<3f", FLOAT, "VEC3", ARRAY_BUFFER,
                               True)
cloth_uvs = add_accessor(uvs, "<2f", FLOAT, "VEC2", ARRAY_BUFFER)
cloth_indices = add_accessor([(i,) for t in triangles for i in t], "<H", UNSIGNED_SHORT,
                             "SCALAR", ELEMENT_ARRAY_BUFFER)
rope_positions = add_accessor([to_gltf(p) for p in rope], "<3f", FLOAT, "VEC3", ARRAY_BUFFER,
                              True)
rope_indices = add_accessor([(i,) for line in lines for i in line], "<H", UNSIGNED_SHORT,
                            "SCALAR", ELEMENT_ARRAY_BUFFER)

TRIANGLES, LINES = 4, 1
document = {
    "asset": {"version": "2.0", "generator": "dinam scripts/make-paper-flag.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "paper_flag", "mesh": 0}],
    "meshes": [{"name": "paper_flag", "primitives": [
        {"attributes": {"POSITION": cloth_positions, "TEXCOORD_0": cloth_uvs},
         "indices": cloth_indices, "mode": TRIANGLES, "material": 0},
        {"attributes": {"POSITION": rope_positions}, "indices": rope_indices, "mode": LINES,
         "material": 1},
    ]}],
    "materials": [{"name": "cloth",
                   "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                            "metallicFactor": 0.0}},
                  {"name": "rope", "pbrMetallicRoughness": {"metallicFactor": 0.0}}],
    "textures": [{"source": 0}],
    "images": [{"uri": "flag.png"}],
    "buffers": [{"byteLength": len(blob),
                 "uri": "data:application/octet-stream;base64," +
                        base64.b64encode(bytes(blob)).decode("ascii")}],
    "bufferViews": views,
    "accessors": accessors,
}
out = Path(__file__).resolve().parent.parent / "assets" / "paper_flag.gltf"
out.write_text(json.dumps(document, indent=1) + "\n")
print(f"wrote {out}: {len(nodes)} nodes, {len(edges)} edges, {len(pinned)} on the pole")
