#!/usr/bin/env python3
"""Writes the gallery's maps (made by the project, CC0) into scenes/maps/:

  domes-normal.png  a tangent-space normal map (OpenGL convention: red +u, green +v = up the
                    image, blue out) of hemispherical domes on a grid, 8 to a side
  bricks-bump.png   a height map of bricks in running bond, bevelled into the mortar lines

Standard library only (zlib for the PNG's pixels).

    scripts/make-gallery-maps.py
"""
import math
import os
import struct
import zlib

SIZE = 256


def write_png(path, pixels):
    """pixels: rows top to bottom, each a list of (r, g, b) bytes."""
    raw = b"".join(b"\0" + bytes(c for texel in row for c in texel) for row in pixels)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", len(pixels[0]), len(pixels), 8, 2, 0, 0, 0)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                  chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def byte(v):
    return max(0, min(255, round(v * 255)))


def domes():
    tile = SIZE // 8
    rows = []
    for row in range(SIZE):
        texels = []
        for column in range(SIZE):
            # Up the image is +v: rows grow downwards.
            dx = ((column % tile) + 0.5) / tile * 2 - 1
            dy = -(((row % tile) + 0.5) / tile * 2 - 1)
            r2 = (dx * dx + dy * dy) / 0.8 ** 2
            n = (dx / 0.8, dy / 0.8, math.sqrt(1 - r2)) if r2 < 1 else (0.0, 0.0, 1.0)
            texels.append(tuple(byte((c + 1) / 2) for c in n))
        rows.append(texels)
    return rows


def bricks():
    width, height, mortar, bevel = 64, 32, 3, 5
    rows = []
    for row in range(SIZE):
        course = row // height
        y = row % height
        texels = []
        for column in range(SIZE):
            x = (column + (width // 2 if course % 2 else 0)) % width
            # Distance into the brick from its nearest mortar line.
            d = min(x, width - 1 - x, y, height - 1 - y) - mortar
            h = 0.0 if d < 0 else min(1.0, (d + 1) / bevel)
            texels.append((byte(h),) * 3)
        rows.append(texels)
    return rows


def main():
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "maps")
    os.makedirs(folder, exist_ok=True)
    write_png(os.path.join(folder, "domes-normal.png"), domes())
    write_png(os.path.join(folder, "bricks-bump.png"), bricks())


if __name__ == "__main__":
    main()
