#!/usr/bin/env python3
"""Time-to-error under an environment: rough gold, copper and silver spheres on a diffuse disk lit
only by the project's sky (bench/envmap/rough-metals.json), lancer's path tracer against Mitsuba 3
(llvm_ad_rgb, optionally scalar_rgb) rendering the same scene as bench/envmap/mitsuba_scene.py
translates it, both measured against Mitsuba's 16384-spp reference, on the same threads.

Run it through bench/envmap_time_to_error.sh, which installs Mitsuba and brings lancer up to date;
see bench/README.md. It writes docs/bench/envmap-time-to-error.{csv,png}, prints a Markdown report
(the table, the ratios against Mitsuba at equal time and at equal error, and the check that
lancer converges to Mitsuba's reference), and exits with status 1 when that check fails. The
error measure and what the times measure: bench/time_to_error.py.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

from time_to_error import (  # bench/time_to_error.py, beside this script
    MitsubaRenderer,
    Measurements,
    add_common_arguments,
    render_interleaved,
    run_lancer,
)

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "bench" / "envmap"))
import mitsuba_scene  # noqa: E402 (bench/envmap/mitsuba_scene.py)

SCENE = ROOT / "bench" / "envmap" / "rough-metals.json"
REFERENCE_SPP = 16384
REFERENCE_IMAGE = ROOT / "bench" / "envmap" / f"mitsuba-{REFERENCE_SPP}spp.exr"
# The reference's passes used Mitsuba's seeds 0 to 127: a seed beyond them keeps our Mitsuba runs
# independent of its samples.
SEED = 1000


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_common_arguments(parser, "4,16,64,256,1024", "envmap-time-to-error", 0.05, 16)
    parser.add_argument(
        "--variants",
        default="llvm_ad_rgb",
        help="comma-separated Mitsuba variants (llvm_ad_rgb, scalar_rgb)",
    )
    args = parser.parse_args()

    measurements = Measurements(args, REFERENCE_IMAGE)
    gate, record = measurements.gate, measurements.record

    def describe(mi):
        return mitsuba_scene.mitsuba_dict(mi, SCENE)

    mitsuba = [
        MitsubaRenderer(variant, args.threads, gate, describe, SEED)
        for variant in args.variants.split(",")
        if variant
    ]
    with tempfile.TemporaryDirectory(prefix="lancer-envmap-bench.") as workdir:
        output = Path(workdir) / "lancer-path.exr"

        def lancer_path(spp: int):
            options = ["--spp", str(spp), "--threads", str(args.threads), "--seed", str(SEED)]
            return run_lancer(args.lancer, SCENE, output, options, gate)

        render_interleaved(lancer_path, mitsuba, args.path_spp, args.mitsuba_spp, record)

    return measurements.report(
        args,
        "envmap-time-to-error",
        "Rough metals under an environment: time to error",
        f"Rough metals under the sky 320x240, max depth 8 (Mitsuba 9), {args.threads} threads",
        REFERENCE_SPP,
        ["lancer path"],
        [f"mitsuba {m.variant}" for m in mitsuba],
    )


if __name__ == "__main__":
    sys.exit(main())
