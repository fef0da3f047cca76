#!/usr/bin/env python3
"""Errors of linear images against a reference, in plain Python (no NumPy).

    bench/image_error.py REFERENCE.pfm IMAGE.pfm [IMAGE.pfm ...]

prints, for each IMAGE, its mean absolute difference, its RMSE and its relative RMSE
(sqrt(mean((image - reference)^2)) / mean(reference), over pixels and channels) against
REFERENCE. Reads the PFM files lancer writes (colour "PF", little or big endian); all the
images must have the same size. Used by bench/adaptive_sampling.sh.
"""

from __future__ import annotations

import array
import math
import sys


def read_pfm(path: str) -> tuple[int, int, array.array]:
    """(width, height, the floats) of a colour PFM. Row order does not matter here: every image
    compared comes from the same writer."""
    with open(path, "rb") as f:
        data = f.read()
    tokens: list[bytes] = []
    position = 0
    while len(tokens) < 4:  # "PF", width, height, scale
        while data[position : position + 1].isspace():
            position += 1
        start = position
        while not data[position : position + 1].isspace():
            position += 1
        tokens.append(data[start:position])
    position += 1  # the single whitespace character before the raster
    if tokens[0] != b"PF":
        raise ValueError(f"{path}: not a colour PFM")
    width, height, scale = int(tokens[1]), int(tokens[2]), float(tokens[3])
    pixels = array.array("f")
    pixels.frombytes(data[position : position + width * height * 12])
    if (scale < 0) != (sys.byteorder == "little"):
        pixels.byteswap()
    return width, height, pixels


def errors(reference: array.array, image: array.array) -> tuple[float, float, float]:
    n = len(reference)
    absolute = squared = total = 0.0
    for r, v in zip(reference, image):
        d = v - r
        absolute += abs(d)
        squared += d * d
        total += r
    rmse = math.sqrt(squared / n)
    return absolute / n, rmse, rmse / (total / n)


def main(arguments: list[str]) -> int:
    if len(arguments) < 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    width, height, reference = read_pfm(arguments[0])
    for path in arguments[1:]:
        w, h, image = read_pfm(path)
        if (w, h) != (width, height):
            print(f"{path}: {w}x{h}, the reference is {width}x{height}", file=sys.stderr)
            return 1
        mae, rmse, relative = errors(reference, image)
        print(f"{path}\tmae {mae:.6f}\trmse {rmse:.6f}\trelative_rmse {relative:.6f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
