#!/usr/bin/env python3
"""Writes a Wavefront OBJ model (triangles or polygons, v/vt/vn, one material with Kd and map_Kd)
as glTF 2.0: NAME.gltf with NAME.bin beside it (the texture referenced by its file name) and
NAME.glb (everything in one file, the texture embedded).

    scripts/obj-to-gltf.py scenes/models/spot/spot_textured.obj scenes/models/spot/spot

Each distinct v/vt/vn corner becomes a vertex, in order of first use; polygons are cut into fans.
OBJ's v runs up the image, glTF's down: v becomes 1 - v. The material is a dielectric
(metallicFactor 0, roughnessFactor 1) of baseColorFactor Kd and baseColorTexture map_Kd, so that
lancer renders the glTF as it renders the OBJ. Standard library only.
"""
import json
import os
import struct
import sys


def read_obj(path):
    positions, uvs, normals, corners = [], [], [], []
    mtllib = None
    for line in open(path, encoding="utf-8"):
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        if words[0] == "v":
            positions.append(tuple(float(w) for w in words[1:4]))
        elif words[0] == "vt":
            uvs.append(tuple(float(w) for w in words[1:3]))
        elif words[0] == "vn":
            normals.append(tuple(float(w) for w in words[1:4]))
        elif words[0] == "mtllib":
            mtllib = words[1]
        elif words[0] == "f":
            face = []
            for word in words[1:]:
                parts = (word.split("/") + ["", ""])[:3]
                index = [int(p) if p else 0 for p in parts]
                counts = (len(positions), len(uvs), len(normals))
                face.append(tuple(i - 1 if i > 0 else (c + i if i < 0 else -1)
                                  for i, c in zip(index, counts)))
            for k in range(1, len(face) - 1):
                corners += [face[0], face[k], face[k + 1]]
    return positions, uvs, normals, corners, mtllib


def read_mtl(path):
    material = {"Kd": (0.8, 0.8, 0.8), "map_Kd": None}
    if path and os.path.exists(path):
        for line in open(path, encoding="utf-8"):
            words = line.split()
            if len(words) >= 4 and words[0] == "Kd":
                material["Kd"] = tuple(float(w) for w in words[1:4])
            elif len(words) >= 2 and words[0] == "map_Kd":
                material["map_Kd"] = words[-1]
    return material


def pad(data, fill=b"\0"):
    return data + fill * (-len(data) % 4)


def main(obj_path, out_stem):
    positions, uvs, normals, corners, mtllib = read_obj(obj_path)
    folder = os.path.dirname(obj_path)
    material = read_mtl(os.path.join(folder, mtllib) if mtllib else None)

    vertices, indices, index_of = [], [], {}
    for corner in corners:
        if corner not in index_of:
            index_of[corner] = len(vertices)
            vertices.append(corner)
        indices.append(index_of[corner])
    has_uv = all(c[1] >= 0 for c in vertices) and uvs
    has_normal = all(c[2] >= 0 for c in vertices) and normals

    position_bytes = b"".join(struct.pack("<3f", *positions[c[0]]) for c in vertices)
    blobs = [("POSITION", position_bytes, "VEC3", 3)]
    if has_normal:
        blobs.append(("NORMAL", b"".join(struct.pack("<3f", *normals[c[2]]) for c in vertices),
                      "VEC3", 3))
    if has_uv:
        blobs.append(("TEXCOORD_0", b"".join(struct.pack("<2f", uvs[c[1]][0], 1 - uvs[c[1]][1])
                                             for c in vertices), "VEC2", 2))
    index_bytes = struct.pack("<%dI" % len(indices), *indices)

    binary, views, accessors, attributes = b"", [], [], {}
    for name, data, kind, _ in blobs:
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data),
                      "target": 34962})
        accessor = {"bufferView": len(views) - 1, "componentType": 5126,
                    "count": len(vertices), "type": kind}
        if name == "POSITION":
            accessor["min"] = [min(positions[c[0]][k] for c in vertices) for k in range(3)]
            accessor["max"] = [max(positions[c[0]][k] for c in vertices) for k in range(3)]
        attributes[name] = len(accessors)
        accessors.append(accessor)
        binary += pad(data)
    views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(index_bytes),
                  "target": 34963})
    accessors.append({"bufferView": len(views) - 1, "componentType": 5125,
                      "count": len(indices), "type": "SCALAR"})
    binary += pad(index_bytes)

    pbr = {"baseColorFactor": list(material["Kd"]) + [1.0], "metallicFactor": 0.0,
           "roughnessFactor": 1.0}
    document = {
        "asset": {"version": "2.0", "generator": "lancer scripts/obj-to-gltf.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": os.path.basename(out_stem)}],
        "meshes": [{"primitives": [{"attributes": attributes, "indices": len(accessors) - 1,
                                    "material": 0}]}],
        "materials": [{"name": "material", "pbrMetallicRoughness": pbr}],
        "accessors": accessors,
        "bufferViews": views,
    }
    texture = material["map_Kd"]
    if texture:
        pbr["baseColorTexture"] = {"index": 0}
        document["textures"] = [{"source": 0}]

    # NAME.gltf + NAME.bin, the image referenced by its file (beside the OBJ's MTL).
    gltf = json.loads(json.dumps(document))
    gltf["buffers"] = [{"uri": os.path.basename(out_stem) + ".bin", "byteLength": len(binary)}]
    if texture:
        gltf["images"] = [{"uri": texture}]
    with open(out_stem + ".gltf", "w", encoding="utf-8") as out:
        json.dump(gltf, out, indent=1)
        out.write("\n")
    with open(out_stem + ".bin", "wb") as out:
        out.write(binary)

    # NAME.glb: the image's bytes appended to the binary chunk.
    glb = json.loads(json.dumps(document))
    if texture:
        image = open(os.path.join(folder, texture), "rb").read()
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(image)})
        glb["bufferViews"] = views
        glb["images"] = [{"bufferView": len(views) - 1, "mimeType": "image/png"}]
        binary += pad(image)
    glb["buffers"] = [{"byteLength": len(binary)}]
    json_chunk = pad(json.dumps(glb, separators=(",", ":")).encode(), b" ")
    total = 12 + 8 + len(json_chunk) + 8 + len(binary)
    with open(out_stem + ".glb", "wb") as out:
        out.write(struct.pack("<4sII", b"glTF", 2, total))
        out.write(struct.pack("<I4s", len(json_chunk), b"JSON") + json_chunk)
        out.write(struct.pack("<I4s", len(binary), b"BIN\0") + binary)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: obj-to-gltf.py MODEL.obj OUT_STEM")
    main(sys.argv[1], sys.argv[2])
