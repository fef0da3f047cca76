"""The Mitsuba 3 translation of a lancer scene made of what bench/envmap's scenes use: a camera,
an `environment` map, `disk` and `sphere` objects, `diffuse` (a grey or RGB constant) and `metal`
(roughness 0 or GGX) materials. Anything else is refused, so that a scene edited beyond what this
translates fails loudly instead of rendering something else.

The conventions matched (docs/SCENE-FORMAT.md against Mitsuba 3.9.1, measured by
check_mapping.py with a map of distinct texels, seen directly and in a mirror sphere):
- Mitsuba's `envmap` looks a direction d (in its local frame) up at u = atan2(d.x, -d.z) / (2 pi),
  lancer at u = 0.5 + atan2(d.x, -d.z) / (2 pi): half a turn about +y apart, to which lancer's
  `rotate` (right-handed about +y, as Mitsuba's rotate) adds. Across, both interpolate between
  texel centres (i + 0.5) / width, wrapping around.
- Down, Mitsuba puts row i at v = i / (height - 1) (the first and last rows on the poles), lancer
  at the texel centres (i + 0.5) / height (constant from the poles to the first and last centres).
  Mitsuba is therefore given the map resampled to 2 height + 1 rows, at v = i / (2 height): these
  include lancer's centres, so that Mitsuba's linear interpolation between them is lancer's exactly.
- `max_depth`: Mitsuba counts the camera ray's segment, so its max_depth is lancer's + 1.
- `metal`: `roughconductor` (`ggx`, the same alpha, visible normals sampled) or `conductor` with
  the RGB eta and k of the table in docs/SCENE-FORMAT.md, read from that table.
- Pixels: the box filter and the independent sampler (lancer's pixels are boxes too).
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent.parent


def read_scene(path: Path) -> dict:
    """A lancer scene file: JSON with // comment lines."""
    lines = [line for line in path.read_text().splitlines() if not line.lstrip().startswith("//")]
    return json.loads("\n".join(lines))


def metal_table() -> dict[str, tuple[list[float], list[float]]]:
    """name -> (eta, k) from the table of named metals in docs/SCENE-FORMAT.md."""
    text = (ROOT / "docs" / "SCENE-FORMAT.md").read_text()
    table = {}
    for name, eta, k in re.findall(r"^\| `(\w+)` \| ([0-9., ]+) \| ([0-9., ]+) \|", text, re.M):
        table[name] = ([float(x) for x in eta.split(",")], [float(x) for x in k.split(",")])
    return table


def grey_or_rgb(value) -> list[float]:
    return [float(value)] * 3 if isinstance(value, (int, float)) else [float(x) for x in value]


def resampled_for_mitsuba(texels: np.ndarray) -> np.ndarray:
    """The map (rows top first) at v = i / (2 height), i = 0 .. 2 height, as lancer looks it up:
    odd rows are lancer's texel centres, even ones halfway between them (the poles: the end rows)."""
    height = texels.shape[0]
    out = np.empty((2 * height + 1,) + texels.shape[1:], dtype=np.float32)
    out[1::2] = texels
    out[2:-1:2] = 0.5 * (texels[:-1] + texels[1:])
    out[0], out[-1] = texels[0], texels[-1]
    return out


def bsdf(material: dict, metals) -> dict:
    allowed = {"diffuse", "metal", "roughness"}
    if set(material) - allowed:
        raise ValueError(f"mitsuba_scene: cannot translate the material keys {set(material) - allowed}")
    if "metal" in material:
        eta, k = metals[material["metal"]]
        result = {
            "eta": {"type": "rgb", "value": eta},
            "k": {"type": "rgb", "value": k},
        }
        alpha = float(material.get("roughness", 0))
        if alpha == 0:
            return {"type": "conductor", **result}
        return {"type": "roughconductor", "distribution": "ggx", "alpha": alpha,
                "sample_visible": True, **result}
    return {"type": "diffuse",
            "reflectance": {"type": "rgb", "value": grey_or_rgb(material["diffuse"])}}


def disk_to_world(mi, center, normal, radius):
    """Mitsuba's disk is the unit disk in the xy plane facing +z."""
    n = np.array(normal, dtype=float)
    n /= np.linalg.norm(n)
    z = np.array([0.0, 0.0, 1.0])
    axis = np.cross(z, n)
    angle = np.degrees(np.arctan2(np.linalg.norm(axis), float(z @ n)))
    if np.linalg.norm(axis) < 1e-9:
        axis = np.array([1.0, 0.0, 0.0])  # n is +z or -z: any axis in the plane
    T = mi.ScalarTransform4f
    return (T().translate(list(map(float, center))) @ T().rotate(axis.tolist(), float(angle))
            @ T().scale([radius, radius, 1.0]))


def mitsuba_dict(mi, scene_path: Path) -> dict:
    """The scene as a Mitsuba 3 dictionary for mi.load_dict (the variant must be set)."""
    scene = read_scene(scene_path)
    render, camera, environment = scene["render"], scene["camera"], scene["environment"]
    if render.get("integrator", "whitted") != "path":
        raise ValueError("mitsuba_scene: only the path integrator is translated")
    texels = np.array(mi.Bitmap(str(scene_path.parent / environment["file"])), dtype=np.float32)
    T = mi.ScalarTransform4f
    metals = metal_table()
    result = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": int(render["max_depth"]) + 1},
        "sensor": {
            "type": "perspective",
            "fov": float(camera["vfov"]),
            "fov_axis": "y",
            "to_world": T().look_at(origin=camera["position"], target=camera["look_at"],
                                    up=camera.get("up", [0, 1, 0])),
            "sampler": {"type": "independent", "sample_count": int(render["spp"])},
            "film": {"type": "hdrfilm", "width": int(render["width"]),
                     "height": int(render["height"]), "rfilter": {"type": "box"},
                     "pixel_format": "rgb", "component_format": "float32"},
        },
        "environment": {
            "type": "envmap",
            "bitmap": mi.Bitmap(resampled_for_mitsuba(texels[..., :3])),
            "scale": float(environment.get("intensity", 1)),
            "to_world": T().rotate([0, 1, 0], 180.0 + float(environment.get("rotate", 0))),
        },
    }
    for i, obj in enumerate(scene["objects"]):
        material = bsdf(scene["materials"][obj["material"]], metals)
        if obj["type"] == "sphere":
            shape = {"type": "sphere", "center": obj["center"], "radius": float(obj["radius"])}
        elif obj["type"] == "disk" and "inner_radius" not in obj:
            shape = {"type": "disk",
                     "to_world": disk_to_world(mi, obj["center"], obj["normal"], obj["radius"])}
        else:
            raise ValueError(f"mitsuba_scene: cannot translate the object {obj}")
        result[f"object-{i}"] = {**shape, "bsdf": material}
    return result
