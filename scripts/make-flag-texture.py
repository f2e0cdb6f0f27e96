#!/usr/bin/env python3
"""Writes assets/flag.png: the shipped flag's picture, 160 x 100, drawn here so that no image is
downloaded. Three horizontal bands with a white disc near the hoist. Standard library only."""
import struct
import zlib
from pathlib import Path

WIDTH, HEIGHT = 160, 100
BANDS = [(20, 60, 140), (245, 245, 240), (200, 40, 40)]  # top to bottom, sRGB


def pixel(x, y):
    r = BANDS[min(2, y * 3 // HEIGHT)]
    dx, dy = x - 40, y - 50
    if dx * dx + dy * dy <= 18 * 18:
        return (250, 200, 40)  # a gold disc
    return r


def png(width, height, rows):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + bytes(v for p in row for v in p) for row in rows)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9))
            + chunk(b"IEND", b""))


rows = [[pixel(x, y) for x in range(WIDTH)] for y in range(HEIGHT)]
out = Path(__file__).resolve().parent.parent / "assets" / "flag.png"
out.write_bytes(png(WIDTH, HEIGHT, rows))
print(f"wrote {out} ({out.stat().st_size} bytes)")
