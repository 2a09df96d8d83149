#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes the two small images examples/scenes/images.pov uses (python3 and its zlib only):
#   images_hills.png: 65 x 65 16-bit grey heights, rolling hills with a crater (a height field);
#   images_tiles.png: 64 x 64 8-bit RGB, a 4 x 4 board of hues with a white ring (an image map).
import math, struct, zlib, os

def png(path, width, height, colour_type, bit_depth, rows):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    raw = b"".join(b"\0" + r for r in rows)
    data = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    with open(path, "wb") as f:
        f.write(data)

here = os.path.dirname(os.path.abspath(__file__))

n = 65
rows = []
for j in range(n):
    row = b""
    for i in range(n):
        x, z = i / (n - 1), j / (n - 1)
        h = 0.35 + 0.18 * math.sin(6.0 * x) * math.cos(5.0 * z) + 0.12 * math.sin(11.0 * (x + z))
        r = math.hypot(x - 0.62, z - 0.4)
        h += 0.3 * math.exp(-((r - 0.16) / 0.05) ** 2) - 0.25 * math.exp(-(r / 0.1) ** 2)  # crater rim and bowl
        row += struct.pack(">H", max(0, min(65535, int(h * 65535))))
    rows.append(row)
png(os.path.join(here, "images_hills.png"), n, n, 0, 16, rows)

n = 64
rows = []
for y in range(n):
    row = b""
    for x in range(n):
        tile = (x // 16) + 4 * (y // 16)
        hue = tile / 16.0
        r, g, b = (0.5 + 0.5 * math.cos(2 * math.pi * (hue + k / 3.0)) for k in (0, 1, 2))
        if (x // 16 + y // 16) % 2:
            r, g, b = 0.35 * r, 0.35 * g, 0.35 * b
        d = math.hypot(x - 31.5, y - 31.5)
        if 18 < d < 24:
            r = g = b = 1.0
        row += bytes(int(round(255 * c)) for c in (r, g, b))
    rows.append(row)
png(os.path.join(here, "images_tiles.png"), n, n, 2, 8, rows)
