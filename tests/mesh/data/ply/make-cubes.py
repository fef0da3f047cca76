#!/usr/bin/env python3
"""Writes the unit cube [0,1]^3 of the PLY tests as cube.obj and as PLY in each encoding.

Each face is a quad of its own 4 vertices (24 in all), with the face's normal and the uvs
(0,0) (1,0) (1,1) (0,1), counter-clockwise seen from outside. cube-positions.obj and .ply are
the same cube of its 8 corners alone (no normals, no uvs). Run from this folder.
"""
import struct

# Each face: its normal and its 4 corners, counter-clockwise seen from outside.
FACES = [
    ((1, 0, 0), [(1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)]),
    ((-1, 0, 0), [(0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)]),
    ((0, 1, 0), [(0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)]),
    ((0, -1, 0), [(0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)]),
    ((0, 0, 1), [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]),
    ((0, 0, -1), [(0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)]),
]
UVS = [(0, 0), (1, 0), (1, 1), (0, 1)]
VERTICES = [(p, n, uv) for n, corners in FACES for p, uv in zip(corners, UVS)]


def header(fmt, uv_names):
    return (f"ply\nformat {fmt} 1.0\ncomment the unit cube of lancer's PLY tests\n"
            f"element vertex {len(VERTICES)}\n"
            + "".join(f"property float {a}\n" for a in ("x", "y", "z", "nx", "ny", "nz"))
            + "".join(f"property float {a}\n" for a in uv_names)
            + f"element face {len(FACES)}\nproperty list uchar int vertex_indices\nend_header\n")


def binary(order):
    body = b"".join(struct.pack(order + "8f", *p, *n, *uv) for p, n, uv in VERTICES)
    body += b"".join(struct.pack(order + "B4i", 4, *range(4 * f, 4 * f + 4))
                     for f in range(len(FACES)))
    return body


with open("cube-ascii.ply", "w", newline="\n") as f:
    f.write(header("ascii", ("s", "t")))
    for p, n, uv in VERTICES:
        f.write(" ".join(str(v) for v in (*p, *n, *uv)) + "\n")
    for i in range(len(FACES)):
        f.write("4 " + " ".join(str(4 * i + k) for k in range(4)) + "\n")
with open("cube-binary-le.ply", "wb") as f:
    f.write(header("binary_little_endian", ("u", "v")).encode() + binary("<"))
with open("cube-binary-be.ply", "wb") as f:
    f.write(header("binary_big_endian", ("texture_u", "texture_v")).encode() + binary(">"))
with open("cube.obj", "w", newline="\n") as f:
    f.write("# the unit cube of lancer's PLY tests\n")
    for p, n, uv in VERTICES:
        f.write("v %d %d %d\nvn %d %d %d\nvt %d %d\n" % (*p, *n, *uv))
    for i in range(len(FACES)):
        f.write("f " + " ".join(f"{4 * i + k + 1}/{4 * i + k + 1}/{4 * i + k + 1}"
                                for k in range(4)) + "\n")

CORNERS = sorted({p for _, corners in FACES for p in corners})
with open("cube-positions.ply", "w", newline="\n") as f:
    f.write(f"ply\nformat ascii 1.0\nelement vertex {len(CORNERS)}\n"
            + "".join(f"property float {a}\n" for a in ("x", "y", "z"))
            + f"element face {len(FACES)}\nproperty list uchar int vertex_indices\nend_header\n")
    for p in CORNERS:
        f.write("%d %d %d\n" % p)
    for _, corners in FACES:
        f.write("4 " + " ".join(str(CORNERS.index(p)) for p in corners) + "\n")
with open("cube-positions.obj", "w", newline="\n") as f:
    f.write("# the unit cube of lancer's PLY tests, its corners alone\n")
    for p in CORNERS:
        f.write("v %d %d %d\n" % p)
    for _, corners in FACES:
        f.write("f " + " ".join(str(CORNERS.index(p) + 1) for p in corners) + "\n")
