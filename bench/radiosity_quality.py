#!/usr/bin/env python3
"""Radiosity's image quality on McGuire's Cornell boxes (issue 12): lancer's `radiosity` against
lancer's `path` at many samples, on `scenes/cornell-original.json` and `scenes/cornell-glossy.json`.

    build/mitsuba-venv/bin/python bench/radiosity_quality.py [--size 200] [--reference-spp 4096]
        [--threads 2] [--lancer bin/lancer] [--cache /tmp/lancer-radiosity-quality] [--images DIR]

For each box and each radiosity setting (SETTINGS), the whole process is timed and the image is
measured against the path-traced reference (rendered once, kept in --cache; its paths are not cut
at the scene's max_depth, see --reference-depth):
- relative RMSE: sqrt(mean((image - reference)^2)) / mean(reference), over pixels and channels,
  off the lamp (every pixel but the lamp's and its edge's, whose coverage is anti-aliasing noise
  next to radiances 100 times the walls') and over the diffuse surfaces alone;
- the 99th percentile, over the pixels of diffuse surfaces, of the per-pixel relative error
  |image - reference| / (reference + 1% of the reference's mean), on the mean of the channels
  (the 1% keeps the darkest corners from dividing by noise).
Issue 12's aim: relative RMSE at most 3% and that percentile at most 10% (blotches and dark dots
fail it). The diffuse surfaces are found by rendering a copy of the box whose diffuse materials
emit white and reflect nothing, and whose glossy materials and lamp are black: a pixel counts
when it is all white (not at an edge). With --images, writes for each box the reference, the
radiosity image of the first setting and their difference amplified 8 times, side by side (PNG).

Needs NumPy (and Matplotlib for --images): bench/setup-mitsuba.sh's venv has both.
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
BOXES = ["original", "glossy"]
# (label, the scene's "radiosity" block, spp)
SETTINGS: list[tuple[str, dict, int]] = [
    ("hierarchical, defaults, 16 spp", {"method": "hierarchical"}, 16),
    ("hierarchical, defaults, 64 spp", {"method": "hierarchical"}, 64),
    ("hierarchical, direct_samples 16, 16 spp", {"method": "hierarchical", "direct_samples": 16}, 16),
    ("hierarchical, direct_samples 16, 64 spp", {"method": "hierarchical", "direct_samples": 16}, 64),
    ("hierarchical, final_gather 64, 16 spp", {"method": "hierarchical", "final_gather": 64}, 16),
    ("progressive, defaults, 16 spp", {}, 16),
]


def read_pfm(path: Path) -> np.ndarray:
    """A colour PFM as rows top to bottom, RGB."""
    data = path.read_bytes()
    header = data.split(maxsplit=4)
    if header[0] != b"PF":
        raise ValueError(f"{path}: not a colour PFM")
    width, height, scale = int(header[1]), int(header[2]), float(header[3])
    raster = data[len(data) - width * height * 12 :]
    pixels = np.frombuffer(raster, dtype="<f4" if scale < 0 else ">f4").reshape(height, width, 3)
    return pixels[::-1].astype(np.float64)  # PFM stores the bottom row first


def read_scene(path: Path) -> dict:
    lines = path.read_text().splitlines()
    return json.loads("\n".join(l for l in lines if not l.lstrip().startswith("//")))


def render(lancer: Path, scene: dict, folder: Path, output: Path, options: list[str]) -> tuple[float, str]:
    """Renders `scene` (its relative paths resolved from `folder`); returns the whole process's
    seconds and lancer's line about the radiosity solution (if any)."""
    path = folder / f"{output.stem}.json"
    path.write_text(json.dumps(scene))
    start = time.perf_counter()
    run = subprocess.run([str(lancer), str(path), "-o", str(output), *options],
                         capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - start
    if run.returncode != 0:
        sys.exit(f"lancer failed on {output.stem}: {run.stderr}")
    return seconds, "".join(re.findall(r"radiosity: (.*)", run.stderr)[-1:])


def diffuse_mask(lancer: Path, scene: dict, box: str, size: int, workdir: Path) -> np.ndarray:
    """Pixels whose whole footprint is on diffuse surfaces (no specular term, no emission)."""
    model = Path(scene["objects"][0]["file"])
    diffuse: dict[str, bool] = {}  # per material of the box's MTL
    for line in model.with_suffix(".mtl").read_text().splitlines():
        words = line.split()
        if words and words[0] == "newmtl":
            name = words[1]
            diffuse[name] = True
        elif words and words[0] in ("Ks", "Ke") and any(float(w) > 0 for w in words[1:4]):
            diffuse[name] = False
    copy = workdir / f"mask-{box}"
    copy.mkdir()
    shutil.copy(model, copy / model.name)
    (copy / model.with_suffix(".mtl").name).write_text("".join(
        f"newmtl {name}\nKd 0 0 0\nKs 0 0 0\nKe {'1 1 1' if white else '0 0 0'}\n"
        for name, white in diffuse.items()))
    mask_scene = json.loads(json.dumps(scene))
    mask_scene["objects"][0]["file"] = str(copy / model.name)
    mask_scene["render"].update({"integrator": "path", "spp": 16, "max_depth": 1})
    output = workdir / f"mask-{box}.pfm"
    render(lancer, mask_scene, workdir, output, ["--width", str(size), "--height", str(size), "--quiet"])
    return read_pfm(output).min(axis=2) > 0.999


def off_the_lamp(reference: np.ndarray) -> np.ndarray:
    """Every pixel but the lamp's and their neighbours (the lamp's edge: a pixel partly on a
    surface 100 times brighter than the walls is anti-aliasing noise at any spp)."""
    lamp = reference.mean(axis=2) > 2
    near = lamp.copy()
    for dy, dx in ((-1, 0), (1, 0), (0, -1), (0, 1), (-1, -1), (-1, 1), (1, -1), (1, 1)):
        near |= np.roll(lamp, (dy, dx), axis=(0, 1))
    return ~near


def errors(image: np.ndarray, reference: np.ndarray, diffuse: np.ndarray) -> tuple[float, float, float]:
    def relative_rmse(mask: np.ndarray) -> float:
        return float(np.sqrt(np.mean((image - reference)[mask] ** 2)) / reference[mask].mean())

    luminance_image, luminance_reference = image.mean(axis=2), reference.mean(axis=2)
    per_pixel = np.abs(luminance_image - luminance_reference) / (
        luminance_reference + 0.01 * luminance_reference.mean())
    return (relative_rmse(off_the_lamp(reference)), relative_rmse(diffuse),
            float(np.percentile(per_pixel[diffuse], 99)))


def to_display(image: np.ndarray) -> np.ndarray:
    c = np.clip(image, 0, 1)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=200)
    parser.add_argument("--reference-spp", type=int, default=4096)
    # Radiosity carries every bounce of light: a reference cut at the scenes' 8 misses what the
    # others bring (a few percent, more in the corners), so its paths end by Russian roulette
    # alone (lancer's largest max_depth).
    parser.add_argument("--reference-depth", type=int, default=1024)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--lancer", type=Path, default=ROOT / "bin" / "lancer")
    parser.add_argument("--cache", type=Path, default=Path("/tmp/lancer-radiosity-quality"))
    parser.add_argument("--images", type=Path)
    args = parser.parse_args()
    args.cache.mkdir(parents=True, exist_ok=True)
    size = ["--width", str(args.size), "--height", str(args.size)]
    print(f"{args.size} x {args.size}, {args.threads} threads; reference: lancer path at "
          f"{args.reference_spp} spp, max_depth {args.reference_depth}\n")
    print("| box | radiosity setting | whole process | relative RMSE off the lamp | on diffuse surfaces "
          "| 99th percentile of per-pixel relative error (diffuse) | solution |")
    print("| --- | --- | ---: | ---: | ---: | ---: | --- |")
    with tempfile.TemporaryDirectory(prefix="lancer-radiosity-quality.") as tmp:
        workdir = Path(tmp)
        for box in BOXES:
            scene = read_scene(ROOT / "scenes" / f"cornell-{box}.json")
            scene["objects"][0]["file"] = str(ROOT / "scenes" / scene["objects"][0]["file"])
            reference_path = (args.cache / f"{box}-path-{args.size}-{args.reference_spp}spp-"
                              f"depth{args.reference_depth}.pfm")
            if not reference_path.exists():
                path_scene = json.loads(json.dumps(scene))
                path_scene["render"].update({"integrator": "path", "spp": args.reference_spp,
                                             "max_depth": args.reference_depth})
                render(args.lancer, path_scene, workdir, reference_path,
                       size + ["--threads", str(args.threads), "--quiet"])
            reference = read_pfm(reference_path)
            mask = diffuse_mask(args.lancer, scene, box, args.size, workdir)
            print(f"| cornell-{box} | (diffuse pixels: {int(mask.sum())} of {mask.size}) | | | | | |")
            first_image = None
            for label, block, spp in SETTINGS:
                radiosity_scene = json.loads(json.dumps(scene))
                radiosity_scene["render"].update({"integrator": "radiosity", "spp": spp})
                radiosity_scene["radiosity"] = block
                output = workdir / f"{box}-radiosity.pfm"
                seconds, note = render(args.lancer, radiosity_scene, workdir, output,
                                       size + ["--threads", str(args.threads)])
                image = read_pfm(output)
                first_image = image if first_image is None else first_image
                off_lamp, on_diffuse, p99 = errors(image, reference, mask)
                print(f"| cornell-{box} | {label} | {seconds:.2f} s | {off_lamp:.4f} | "
                      f"{on_diffuse:.4f} | {p99:.4f} | {note} |", flush=True)
            if args.images:
                import matplotlib.pyplot as plt

                args.images.mkdir(parents=True, exist_ok=True)
                difference = np.clip(8 * np.abs(first_image - reference), 0, 1)
                plt.imsave(args.images / f"radiosity-quality-{box}.png",
                           np.concatenate([to_display(reference), to_display(first_image),
                                           to_display(difference)], axis=1))


if __name__ == "__main__":
    main()
