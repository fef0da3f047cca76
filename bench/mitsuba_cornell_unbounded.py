#!/usr/bin/env python3
"""Renders the Cornell box reference without a depth limit: Mitsuba 3's `path` integrator with
`max_depth` -1 (paths end only by Russian roulette), otherwise exactly as the stored reference
(`tests/cli/data/cornell/mitsuba-path-16384spp.exr`: `mitsuba.cornell_box()`, 256 x 256, box
filter, independent sampler), at 16384 spp in passes of `--pass-spp` with seeds 0, 1, 2...,
averaged.

Radiosity solves for every bounce of light; the stored reference keeps 7 (Mitsuba's `max_depth`
8), and misses what the others bring: 14% of the light in the dark corner left of the tall block
(docs/BENCHMARKS.md). This one is what radiosity is measured against.

    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM-19.so \\
        build/mitsuba-venv/bin/python bench/mitsuba_cornell_unbounded.py OUT.exr [--spp 16384]

Before the long render it renders the same setup with `max_depth` 8 (`--check-spp`) and prints
its RMSE against the stored reference beside that of two such renders against each other: the
two agree when the setup is the stored reference's.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from cornell_time_to_error import mitsuba_cornell_box  # bench/, beside this script
from radiosity_methods import read_exr

ROOT = Path(__file__).resolve().parent.parent
STORED = ROOT / "tests" / "cli" / "data" / "cornell" / "mitsuba-path-16384spp.exr"


def render(mi, max_depth: int, spp: int, pass_spp: int, first_seed: int) -> np.ndarray:
    description = mitsuba_cornell_box(mi)
    description["integrator"]["max_depth"] = max_depth
    scene = mi.load_dict(description)
    passes = max(1, spp // pass_spp)
    return sum(np.array(mi.render(scene, spp=pass_spp, seed=first_seed + k), dtype=np.float64)
               for k in range(passes)) / passes


def rmse(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.sqrt(np.mean((a - b) ** 2)))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output", type=Path)
    parser.add_argument("--spp", type=int, default=16384)
    parser.add_argument("--pass-spp", type=int, default=256)
    parser.add_argument("--check-spp", type=int, default=1024)
    parser.add_argument("--variant", default="llvm_ad_rgb")
    args = parser.parse_args()
    import mitsuba as mi

    mi.set_variant(args.variant)
    stored = read_exr(STORED)
    # Seeds far from the long render's, so that the check's samples are its own.
    check = render(mi, 8, args.check_spp, args.pass_spp, 100000)
    again = render(mi, 8, args.check_spp, args.pass_spp, 200000)
    print(f"max_depth 8 at {args.check_spp} spp: RMSE {rmse(check, stored):.5f} against the stored "
          f"reference, {rmse(check, again):.5f} against a second render (noise)", flush=True)
    start = time.perf_counter()
    image = render(mi, -1, args.spp, args.pass_spp, 0)
    print(f"max_depth -1 at {args.spp} spp in {time.perf_counter() - start:.0f} s: RMSE "
          f"{rmse(image, stored):.5f} against the stored (depth 8) reference; mean "
          f"{image.mean():.5f} against {stored.mean():.5f}")
    mi.util.write_bitmap(str(args.output), image.astype(np.float32))


if __name__ == "__main__":
    main()
