#!/usr/bin/env python3
"""What lancer's auxiliary outputs (--aov albedo,normal) do for Intel Open Image Denoise.

    python -m venv build/oidn-venv && build/oidn-venv/bin/pip install pyoidn OpenEXR numpy
    build/oidn-venv/bin/python bench/aov_denoise.py [SCENE] [--spp N] [--reference-spp M] [--size S]

renders SCENE (default scenes/cornell-spheres.json) with the path tracer at N samples per pixel
(default 8) with --aov albedo,normal, and at M (default 512) as the reference, S x S pixels
(default 160), then denoises the noisy image with OIDN (through PyPI's pyoidn, which bundles the
library) without and with the auxiliary images, and prints the RMSE of each against the
reference (which has its own noise, about sqrt(N / M) of the noisy image's). Needs bin/lancer.
"""

from __future__ import annotations

import argparse
import pathlib
import subprocess
import sys
import tempfile

import numpy as np
import OpenEXR
import pyoidn

ROOT = pathlib.Path(__file__).resolve().parent.parent


def read_pfm(path: pathlib.Path) -> np.ndarray:
    """A colour PFM as lancer writes it (one whitespace character after each header line)."""
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            raise ValueError(f"{path}: not a colour PFM")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        pixels = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    # PFM stores the bottom row first.
    return np.ascontiguousarray(pixels.reshape(height, width, 3)[::-1], dtype=np.float32)


def read_exr(path: pathlib.Path) -> np.ndarray:
    with OpenEXR.File(str(path)) as f:
        channels = f.channels()
        if "RGB" in channels:
            return np.ascontiguousarray(channels["RGB"].pixels, dtype=np.float32)
        return np.ascontiguousarray(
            np.stack([channels[c].pixels for c in "RGB"], axis=-1), dtype=np.float32
        )


def render(scene: str, output: pathlib.Path, spp: int, size: int, extra: list[str]) -> None:
    subprocess.run(
        [str(ROOT / "bin/lancer"), scene, "-o", str(output), "--integrator", "path",
         "--spp", str(spp), "--width", str(size), "--height", str(size), "--quiet", *extra],
        check=True,
    )


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("scene", nargs="?", default=str(ROOT / "scenes/cornell-spheres.json"))
    parser.add_argument("--spp", type=int, default=8)
    parser.add_argument("--reference-spp", type=int, default=512)
    parser.add_argument("--size", type=int, default=160)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="lancer-aov-denoise.") as folder:
        out = pathlib.Path(folder)
        render(args.scene, out / "noisy.pfm", args.spp, args.size, ["--aov", "albedo,normal"])
        render(args.scene, out / "reference.pfm", args.reference_spp, args.size, [])
        noisy, reference = read_pfm(out / "noisy.pfm"), read_pfm(out / "reference.pfm")
        albedo, normal = read_exr(out / "noisy.albedo.exr"), read_exr(out / "noisy.normal.exr")

    def rmse(image: np.ndarray) -> float:
        return float(np.sqrt(np.mean((image - reference) ** 2)))

    print(f"OIDN {pyoidn.version.oidn_version}, {args.size}x{args.size}, {args.spp} spp "
          f"against {args.reference_spp} spp")
    print(f"noisy:                          RMSE {rmse(noisy):.4f}")
    print(f"denoised, colour only:          RMSE {rmse(pyoidn.denoise(noisy, hdr=True)):.4f}")
    denoised = pyoidn.denoise(noisy, albedo, normal, hdr=True)
    print(f"denoised with albedo and normal: RMSE {rmse(denoised):.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
