#!/usr/bin/env python3
"""Renders the reference of bench/envmap_time_to_error.py: rough-metals.json translated for
Mitsuba 3 by mitsuba_scene.py, in passes of 128 spp with seeds 0, 1, 2, ... averaged (one call of
many thousand spp would hold every sample's path state in memory at once).

    bench/setup-mitsuba.sh
    DRJIT_LIBLLVM_PATH=$(dpkg -L libllvm19 | grep -m1 '/libLLVM-19\\.so$') \\
        build/mitsuba-venv/bin/python bench/envmap/make_reference.py [SPP]   (default 16384)
"""

import sys
import time
from pathlib import Path

import drjit as dr
import mitsuba as mi
import numpy as np

import mitsuba_scene  # beside this script

HERE = Path(__file__).resolve().parent
PASS_SPP = 128

mi.set_variant("llvm_ad_rgb")
dr.set_thread_count(2)
spp = int(sys.argv[1]) if len(sys.argv) > 1 else 16384
passes = max(spp // PASS_SPP, 1)
scene = mi.load_dict(mitsuba_scene.mitsuba_dict(mi, HERE / "rough-metals.json"))
total = None
start = time.perf_counter()
for seed in range(passes):
    image = np.array(mi.render(scene, spp=PASS_SPP, seed=seed), dtype=np.float64)
    total = image if total is None else total + image
    print(f"pass {seed + 1}/{passes}, {time.perf_counter() - start:.0f} s", file=sys.stderr)
path = HERE / f"mitsuba-{passes * PASS_SPP}spp.exr"
mi.Bitmap((total / passes).astype(np.float32)).write(str(path))
print("wrote", path)
