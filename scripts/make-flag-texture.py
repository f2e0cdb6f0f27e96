#!/usr/bin/env python3
"""Writes assets/flag.png: the shipped flag's picture, 1024 x 640, drawn here so that no image is
downloaded. Three horizontal bands with a gold disc near the hoist; the disc's edge is
anti-aliased (each pixel on it takes the share of 8 x 8 samples inside the disc, mixed in linear
light), so that it stays smooth when a 720p frame shows the flag at about its own size. Standard
library only."""
import struct
import zlib
from pathlib import Path

WIDTH, HEIGHT = 1024, 640
BANDS = [(20, 60, 140), (245, 245, 240), (200, 40, 40)]  # top to bottom, sRGB
DISC = (250, 200, 40)  # gold, sRGB
CENTER = (WIDTH * 40 / 160, HEIGHT / 2)  # as the first, 160 x 100 picture had it
RADIUS = WIDTH * 18 / 160
SAMPLES = 8


def to_linear(c):
    c /= 255
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def to_srgb(c):
    c = 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055
    return round(255 * min(max(c, 0.0), 1.0))


def coverage(x, y):
    """The share of pixel (x, y) inside the disc."""
    dx, dy = x + 0.5 - CENTER[0], y + 0.5 - CENTER[1]
    distance = (dx * dx + dy * dy) ** 0.5
    if distance <= RADIUS - 1:
        return 1.0
    if distance >= RADIUS + 1:
        return 0.0
    inside = 0
    for i in range(SAMPLES):
        for j in range(SAMPLES):
            sx = x + (i + 0.5) / SAMPLES - CENTER[0]
            sy = y + (j + 0.5) / SAMPLES - CENTER[1]
            inside += sx * sx + sy * sy <= RADIUS * RADIUS
    return inside / SAMPLES ** 2


def pixel(x, y):
    band = BANDS[min(2, y * 3 // HEIGHT)]
    share = coverage(x, y)
    if share == 0.0:
        return band
    return tuple(to_srgb(share * to_linear(d) + (1 - share) * to_linear(b))
                 for d, b in zip(DISC, band))


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
