"""Reads a PC2 point cache with Python's struct module alone, for the tests that compare what
another program shows with a cache (in Blender's Python too): every sample's points, as float32
x, y, z triples read back as Python floats."""
import struct


def read_pc2(path):
    with open(path, "rb") as f:
        data = f.read()
    signature, version, points, _, _, samples = struct.unpack_from("<12siiffi", data)
    assert signature == b"POINTCACHE2\0" and version == 1, path
    frame = struct.Struct(f"<{3 * points}f")
    return [[frame.unpack_from(data, 32 + k * frame.size)[3 * i:3 * i + 3] for i in range(points)]
            for k in range(samples)]
