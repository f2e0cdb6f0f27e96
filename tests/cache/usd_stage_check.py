#!/usr/bin/env python3
"""Checks the USD stage of a dinam motion cache against the cache's own OBJ and PC2 files.

    usd_stage_check.py CACHE [--expect PRIM=TYPE ...] [--width PRIM=METRES ...]
                       [--texture PRIM ...] [--seams PRIM ...]

The stage is read here by a parser of USD's text grammar (the subset a geometry layer uses:
layer and prim metadata, `def` prims, typed attributes with arrays, tuples and time samples),
written for this test from the grammar, sharing no code with dinam. It checks:
  - the layer: `#usda 1.0`, Z up, metres, time codes 1 .. frame_count at the cache's fps, a
    default prim that exists;
  - every object: its Mesh prim has the OBJ's faces, and its faces and BasisCurves segments
    together cover exactly the OBJ's edges (faces and lines); texture coordinates, where given,
    face-varying with indices, each face corner's the OBJ's (so a seam keeps a pair on each
    side); a prim whose name is not the object's has it as its displayName;
  - every prim's bound Material: a UsdPreviewSurface of its displayColor, or of a texture whose
    file lies beside the stage (a relative asset path), read through primvars:st;
  - the points at the first, the middle and the last frame equal the PC2's to 1e-6 m (a curve
    vertex through primvars:dinam:node), and each frame's extent holds them;
  - what the caller expects: prim types, widths, which prims wear a texture (the others must not),
    and which have more texture coordinates than points (a seam).
Prints one line per prim and "usd-check: PASS"; exits 1 with the reason otherwise.
Debian's Blender is built without USD (bpy.app.build_options.usd is False), so it cannot be the
reader here; a Blender from blender.org imports the same file with File > Import > USD.
"""
import json
import os
import re
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pc2_reader import read_pc2  # noqa: E402

TOKEN = re.compile(r"""
    (?P<space>\s+|\#[^\n]*)
  | (?P<string>"(?:[^"\\]|\\.)*")
  | (?P<path><[^<>\s]*>)
  | (?P<asset>@[^@]*@)
  | (?P<number>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![A-Za-z_]))
  | (?P<name>[A-Za-z_][A-Za-z0-9_:.]*)
  | (?P<punct>[()\[\]{},=:])
""", re.VERBOSE)


class UsdaError(Exception):
    pass


def tokenize(text):
    if not text.startswith("#usda 1.0"):
        raise UsdaError("the file does not start with '#usda 1.0'")
    pos = len("#usda 1.0")
    tokens = []
    while pos < len(text):
        m = TOKEN.match(text, pos)
        if not m:
            raise UsdaError(f"cannot read from character {pos}: {text[pos:pos + 40]!r}")
        pos = m.end()
        kind = m.lastgroup
        if kind == "space":
            continue
        value = m.group(kind)
        if kind in ("string", "path", "asset"):
            value = value[1:-1]
        elif kind == "number":
            value = float(value)
        tokens.append((kind, value))
    return tokens


class Parser:
    def __init__(self, tokens):
        self.tokens = tokens
        self.i = 0

    def peek(self):
        return self.tokens[self.i] if self.i < len(self.tokens) else (None, None)

    def take(self, kind=None, value=None):
        token = self.peek()
        if token[0] is None or (kind and token[0] != kind) or (value is not None and token[1] != value):
            raise UsdaError(f"expected {value or kind} at token {self.i}, got {token}")
        self.i += 1
        return token[1]

    def at(self, value):
        return self.peek()[1] == value and self.peek()[0] == "punct"

    def value(self):
        kind, v = self.peek()
        if kind in ("number", "string", "name"):
            self.i += 1
            return v
        if kind in ("path", "asset"):
            self.i += 1
            return (kind, v)
        if self.at("("):
            return tuple(self.sequence("(", ")"))
        if self.at("["):
            return self.sequence("[", "]")
        if self.at("{"):  # time samples: {time: value, ...}
            self.take("punct", "{")
            samples = {}
            while not self.at("}"):
                time = self.take("number")
                self.take("punct", ":")
                samples[time] = self.value()
                if self.at(","):
                    self.take("punct", ",")
            self.take("punct", "}")
            return samples
        raise UsdaError(f"expected a value at token {self.i}, got {self.peek()}")

    def sequence(self, open_, close):
        self.take("punct", open_)
        items = []
        while not self.at(close):
            items.append(self.value())
            if self.at(","):
                self.take("punct", ",")
        self.take("punct", close)
        return items

    def metadata(self):
        entries = {}
        self.take("punct", "(")
        while not self.at(")"):
            if self.peek()[0] == "string":  # a layer's doc string may stand alone
                entries["doc"] = self.take("string")
                continue
            key = self.take("name")
            if key in ("prepend", "append", "delete"):  # a list edit: prepend apiSchemas = [...]
                key = self.take("name")
            self.take("punct", "=")
            entries[key] = self.value()
        self.take("punct", ")")
        return entries

    def layer(self):
        meta = self.metadata() if self.at("(") else {}
        prims = []
        while self.peek()[0] is not None:
            prims.append(self.prim())
        return meta, prims

    def prim(self):
        self.take("name", "def")
        type_name = self.take("name") if self.peek()[0] == "name" else ""
        name = self.take("string")
        meta = self.metadata() if self.at("(") else {}
        self.take("punct", "{")
        attributes, children = {}, []
        while not self.at("}"):
            if self.peek() == ("name", "def"):
                children.append(self.prim())
                continue
            variability = ""
            if self.peek()[1] in ("uniform", "custom"):
                variability = self.take("name")
            type_ = self.take("name")
            if self.at("["):
                self.take("punct", "[")
                self.take("punct", "]")
                type_ += "[]"
            attr = self.take("name")
            value = None  # a declaration without a value: a shader's output
            if self.at("="):
                self.take("punct", "=")
                value = self.value()
            attr_meta = self.metadata() if self.at("(") else {}
            attributes[attr] = {"type": type_, "variability": variability, "value": value,
                                "meta": attr_meta}
        self.take("punct", "}")
        return {"type": type_name, "name": name, "meta": meta, "attributes": attributes,
                "children": children}


def fail(message):
    print(f"usd-check: FAIL: {message}")
    sys.exit(1)


def read_obj(path):
    """The OBJ's faces and lines as vertex ids, its texture coordinates (vt), and each face
    corner's vt id in the order of the faces (empty where the file has none)."""
    faces, lines, vts, corner_vt = [], [], [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if parts and parts[0] == "vt":
                vts.append((float(parts[1]), float(parts[2])))
            if parts and parts[0] in ("f", "l"):
                ids = [int(p.split("/")[0]) - 1 for p in parts[1:]]
                (faces if parts[0] == "f" else lines).append(ids)
                if parts[0] == "f" and all("/" in p for p in parts[1:]):
                    corner_vt.extend(int(p.split("/")[1]) - 1 for p in parts[1:])
    return faces, lines, vts, corner_vt


def resolve(roots, path):
    """The prim at an absolute prim path, or None."""
    children, prim = roots, None
    for name in path.strip("/").split("/"):
        prim = next((p for p in children if p["name"] == name), None)
        if prim is None:
            return None
        children = prim["children"]
    return prim


def connection(roots, attrs, name):
    """The shader an input or output `name` connects to, through `name.connect`; or None."""
    link = attrs.get(name + ".connect")
    if link is None:
        return None
    kind, target = link["value"]
    return resolve(roots, target.split(".")[0]) if kind == "path" else None


def check_material(roots, cache, name, prim):
    """The prim's bound Material is a UsdPreviewSurface of its displayColor, or of a texture read
    through its st whose file lies in the cache folder. Returns whether it wears a texture."""
    attrs = prim["attributes"]
    if "MaterialBindingAPI" not in prim["meta"].get("apiSchemas", []):
        fail(f"{name}: no MaterialBindingAPI among its apiSchemas")
    binding = attrs.get("material:binding")
    if binding is None or binding["type"] != "rel" or binding["value"][0] != "path":
        fail(f"{name}: no material:binding relationship")
    material = resolve(roots, binding["value"][1])
    if material is None or material["type"] != "Material":
        fail(f"{name}: its material:binding {binding['value'][1]} is no Material")
    surface = connection(roots, material["attributes"], "outputs:surface")
    if surface is None or surface["attributes"]["info:id"]["value"] != "UsdPreviewSurface":
        fail(f"{name}: its material's surface is no UsdPreviewSurface")
    shading = surface["attributes"]
    for key in ("inputs:roughness", "inputs:metallic"):
        if not 0.0 <= shading[key]["value"] <= 1.0:
            fail(f"{name}: {key} {shading[key]['value']} is outside [0, 1]")
    texture = connection(roots, shading, "inputs:diffuseColor")
    if texture is None:
        color = tuple(shading["inputs:diffuseColor"]["value"])
        shown = tuple(attrs["primvars:displayColor"]["value"][0])
        if max(abs(a - b) for a, b in zip(color, shown)) > 1e-6:
            fail(f"{name}: diffuseColor {color} is not its displayColor {shown}")
        return False
    texture_attrs = texture["attributes"]
    if texture_attrs["info:id"]["value"] != "UsdUVTexture":
        fail(f"{name}: its diffuseColor comes from no UsdUVTexture")
    kind, file = texture_attrs["inputs:file"]["value"]
    if kind != "asset" or os.path.isabs(file) or not os.path.isfile(os.path.join(cache, file)):
        fail(f"{name}: its texture @{file}@ is not a file beside the stage")
    reader = connection(roots, texture_attrs, "inputs:st")
    if (reader is None or reader["attributes"]["info:id"]["value"] != "UsdPrimvarReader_float2"
            or reader["attributes"]["inputs:varname"]["value"] != "st"):
        fail(f"{name}: its texture is not read through primvars:st")
    if "primvars:st" not in attrs:
        fail(f"{name}: it wears a texture but has no primvars:st")
    return True


def edges_of(faces, lines):
    edges = set()
    for face in faces:
        edges.update(tuple(sorted(e)) for e in zip(face, face[1:] + face[:1]))
    for line in lines:
        edges.update(tuple(sorted(e)) for e in zip(line, line[1:]))
    return edges


def prim_name(object_name):
    name = re.sub(r"[^A-Za-z0-9_]", "_", object_name)
    return "_" + name if not name or name[0].isdigit() else name


def check_uvs(name, attrs, indices, vts, corner_vt, seams):
    """Face-varying texture coordinates, each face corner's the OBJ's own (so seams are kept)."""
    if "primvars:st" not in attrs:
        if corner_vt:
            fail(f"{name}: the OBJ has texture coordinates, the stage none")
        return
    st = attrs["primvars:st"]
    if st["meta"].get("interpolation") != "faceVarying":
        fail(f"{name}: primvars:st is not faceVarying")
    st_indices = [int(i) for i in attrs["primvars:st:indices"]["value"]]
    if len(st_indices) != len(indices) or len(corner_vt) != len(indices):
        fail(f"{name}: {len(st_indices)} st indices, {len(indices)} corners, "
             f"{len(corner_vt)} in the OBJ")
    for k, (i, vt) in enumerate(zip(st_indices, corner_vt)):
        uv = st["value"][i]
        if max(abs(a - b) for a, b in zip(uv, vts[vt])) > 1e-6:
            fail(f"{name}: corner {k} has st {uv}, the OBJ {vts[vt]}")
    if len(st["value"]) != len(set(corner_vt)):
        fail(f"{name}: {len(st['value'])} distinct st, the OBJ {len(set(corner_vt))}")
    points = len(set(indices))
    if seams and not len(st["value"]) > points:
        fail(f"{name}: {len(st['value'])} texture coordinates for {points} points: no seam")
    print(f"usd-check: {name}: {len(st['value'])} texture coordinates on {points} points")


def main():
    args = sys.argv[1:]
    cache = args[0]
    expect, widths, textured, seams = {}, {}, set(), set()
    for flag, value in zip(args[1::2], args[2::2]):
        key, _, wanted = value.partition("=")
        if flag in ("--expect", "--width"):
            (expect if flag == "--expect" else widths)[key] = wanted
        else:
            (textured if flag == "--texture" else seams).add(key)
    with open(os.path.join(cache, "manifest.json")) as f:
        manifest = json.load(f)
    if "usd" not in manifest:
        fail("the manifest names no USD stage")
    with open(os.path.join(cache, manifest["usd"])) as f:
        meta, roots = Parser(tokenize(f.read())).layer()

    frame_count, fps = manifest["frame_count"], manifest["fps"]
    wanted_meta = {"upAxis": "Z", "metersPerUnit": 1.0, "startTimeCode": 1.0,
                   "endTimeCode": float(frame_count), "timeCodesPerSecond": float(fps)}
    for key, value in wanted_meta.items():
        if meta.get(key) != value:
            fail(f"layer metadata {key} is {meta.get(key)!r}, not {value!r}")
    root = [p for p in roots if p["name"] == meta.get("defaultPrim")]
    if len(root) != 1:
        fail(f"the default prim {meta.get('defaultPrim')!r} is not a root prim")
    prims = {p["name"]: p for p in root[0]["children"] if p["name"] != "Looks"}
    for name, type_ in expect.items():
        if name not in prims or prims[name]["type"] != type_:
            fail(f"expected a {type_} prim {name!r}; the stage has {sorted(prims)}")

    frames = sorted({1, (frame_count + 1) // 2, frame_count})
    checked = set()
    for entry in manifest["objects"]:
        base = prim_name(entry["name"])
        faces, lines, vts, corner_vt = read_obj(os.path.join(cache, entry["files"]["obj"]))
        pc2 = read_pc2(os.path.join(cache, entry["files"]["pc2"]))
        covered = set()
        for name in (base, base + "_wires"):
            prim = prims.get(name)
            if prim is None:
                continue
            checked.add(name)
            attrs = prim["attributes"]
            points = attrs["points.timeSamples"]["value"]
            if sorted(points) != [float(k) for k in range(1, frame_count + 1)]:
                fail(f"{name}: points are not sampled at time codes 1 .. {frame_count}")
            if prim["type"] == "Mesh":
                counts = attrs["faceVertexCounts"]["value"]
                indices = [int(i) for i in attrs["faceVertexIndices"]["value"]]
                if sum(counts) != len(indices):
                    fail(f"{name}: faceVertexCounts sum to {sum(counts)}, indices {len(indices)}")
                mesh_faces, start = [], 0
                for c in counts:
                    mesh_faces.append(indices[start:start + int(c)])
                    start += int(c)
                if mesh_faces != faces:
                    fail(f"{name}: its faces are not the OBJ's")
                if attrs.get("subdivisionScheme", {}).get("value") != "none":
                    fail(f"{name}: a simulated mesh must not be subdivided")
                check_uvs(name, attrs, indices, vts, corner_vt, name in seams)
                node_of_point = list(range(entry["node_count"]))
                covered |= edges_of(mesh_faces, [])
            elif prim["type"] == "BasisCurves":
                counts = [int(c) for c in attrs["curveVertexCounts"]["value"]]
                node_of_point = [int(n) for n in attrs["primvars:dinam:node"]["value"]]
                if attrs["type"]["value"] != "linear" or sum(counts) != len(node_of_point):
                    fail(f"{name}: not linear, or curveVertexCounts do not match the nodes")
                start = 0
                for c in counts:
                    covered |= edges_of([], [node_of_point[start:start + c]])
                    start += c
                width = attrs["widths"]["value"]
                if len(width) != 1 or not width[0] > 0:
                    fail(f"{name}: widths {width} is not one positive width")
                if name in widths and abs(width[0] - float(widths[name])) > 1e-7:
                    fail(f"{name}: width {width[0]}, expected {widths[name]}")
            else:
                fail(f"{name}: a {prim['type']} prim")
            shown = entry["name"] if name == base else entry["name"] + " wires"
            if name != shown and prim["meta"].get("displayName") != shown:
                fail(f"{name}: displayName {prim['meta'].get('displayName')!r}, not {shown!r}")
            if check_material(roots, cache, name, prim) != (name in textured):
                fail(f"{name}: {'no' if name in textured else 'a'} texture, against expectation")
            for frame in frames:
                sample = points[float(frame)]
                if len(sample) != len(node_of_point):
                    fail(f"{name}: {len(sample)} points at frame {frame}, not {len(node_of_point)}")
                worst = max(abs(a - b) for p, n in zip(sample, node_of_point)
                            for a, b in zip(p, pc2[frame - 1][n]))
                if worst > 1e-6:
                    fail(f"{name}: frame {frame} differs from the PC2 by {worst:.3g} m")
                low, high = attrs["extent.timeSamples"]["value"][float(frame)]
                if any(not (low[c] <= p[c] <= high[c]) for p in sample for c in range(3)):
                    fail(f"{name}: the extent at frame {frame} does not hold the points")
            print(f"usd-check: {name}: {prim['type']}, {len(node_of_point)} points, frames "
                  f"{frames} equal the PC2")
        if covered != edges_of(faces, lines):
            fail(f"object {entry['name']!r}: its prims draw {len(covered)} edges, the OBJ has "
                 f"{len(edges_of(faces, lines))}")
    if set(prims) != checked:
        fail(f"prims that belong to no object: {sorted(set(prims) - checked)}")
    print("usd-check: PASS")


if __name__ == "__main__":
    main()
