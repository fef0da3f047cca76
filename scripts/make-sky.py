#!/usr/bin/env python3
"""Writes scenes/skies/sky.hdr: an analytic clear sky with a sun, as a latitude-longitude map in
lancer's environment convention (docs/SCENE-FORMAT.md, "environment"): texel (x, y) of a W x H
map looks along the unit direction with u = (x + 0.5) / W = 0.5 + atan2(d.x, -d.z) / (2 pi) and
v = (y + 0.5) / H = acos(d.y) / pi, so the centre of the image is straight ahead (-z) and the top
row straight up.

The sky: a blue zenith fading to a pale horizon (a gradient in the sine of the elevation), a
glow around the sun, a plain brownish-grey ground below the horizon, and the sun itself, a disc
of 3 degrees' radius (larger than the real 0.27, so that a 256-texel-wide map resolves it) whose
radiance gives the sun three to four times the sky's irradiance on a level surface, as on a clear
day. Made by the project, released under CC0 1.0 (public domain).

Usage: scripts/make-sky.py [OUTPUT] (default scenes/skies/sky.hdr beside this script's project).
The file is written as Radiance RGBE without run-length encoding, rows top first ("-Y H +X W").
"""
import math
import os
import struct
import sys

WIDTH, HEIGHT = 256, 128
SUN_ELEVATION = math.radians(35)
SUN_AZIMUTH = math.radians(-40)  # from -z towards +x: the sun ahead and to the left
SUN_RADIUS = math.radians(3)
SUN_RADIANCE = (620.0, 570.0, 500.0)
ZENITH = (0.08, 0.17, 0.42)
HORIZON = (0.40, 0.45, 0.52)
GROUND = (0.09, 0.08, 0.07)


def direction(u, v):
    phi = (u - 0.5) * 2 * math.pi
    theta = v * math.pi
    s = math.sin(theta)
    return (s * math.sin(phi), math.cos(theta), -s * math.cos(phi))


def sky(d, sun):
    cos_sun = sum(a * b for a, b in zip(d, sun))
    if cos_sun >= math.cos(SUN_RADIUS):
        return SUN_RADIANCE
    if d[1] < 0:
        return GROUND
    t = d[1] ** 0.5  # the pale band stays near the horizon
    glow = 0.3 * max(cos_sun, 0.0) ** 16
    return tuple((1 - t) * h + t * z + glow for h, z in zip(HORIZON, ZENITH))


def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return bytes([int(c[0] * scale), int(c[1] * scale), int(c[2] * scale), exponent + 128])


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "scenes", "skies", "sky.hdr")
    sun = (math.cos(SUN_ELEVATION) * math.sin(SUN_AZIMUTH), math.sin(SUN_ELEVATION),
           -math.cos(SUN_ELEVATION) * math.cos(SUN_AZIMUTH))
    body = bytearray()
    for y in range(HEIGHT):
        for x in range(WIDTH):
            body += rgbe(sky(direction((x + 0.5) / WIDTH, (y + 0.5) / HEIGHT), sun))
    with open(out, "wb") as f:
        f.write(b"#?RADIANCE\n# an analytic sky made by lancer's scripts/make-sky.py, CC0 1.0\n")
        f.write(b"FORMAT=32-bit_rle_rgbe\n\n")
        f.write(b"-Y %d +X %d\n" % (HEIGHT, WIDTH))
        f.write(body)


if __name__ == "__main__":
    main()
