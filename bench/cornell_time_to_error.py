#!/usr/bin/env python3
"""Time-to-error on the Cornell box: lancer's path tracer and Mitsuba 3 (scalar_rgb,
llvm_ad_rgb) against Mitsuba's 16384-spp reference, in the same run, on the same threads.
(Radiosity's curve on this box, against the reference without a depth limit and beside POV-Ray's
radiosity, is bench/radiosity_time_to_error.py's.)

Run it through bench/cornell_time_to_error.sh, which installs Mitsuba and brings lancer up to
date; see bench/README.md. Before each timed run it waits (a while) for idle CPUs. It writes a CSV and a log-log plot of the relative RMSE
against time, prints a Markdown report (the table, the ratios against Mitsuba at equal time and
at equal error, and the convergence check of lancer's path tracer), and exits with status 1 when
the convergence check fails. The error measure and what the times measure: bench/time_to_error.py.
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
REFERENCE_DIR = ROOT.parent / "shared" / "references" / "cornell"
REFERENCE_SCENE = REFERENCE_DIR / "cornell.json"
REFERENCE_IMAGE = REFERENCE_DIR / "mitsuba-path-16384spp.exr"
REFERENCE_SPP = 16384
MITSUBA_MAX_DEPTH = 8  # Mitsuba counts the camera ray: its 8 is the 7 of cornell.json
# The reference was rendered with Mitsuba's default seed 0; other seeds keep our Mitsuba runs
# independent of its samples.
SEED = 7

class LancerRenderer:
    def __init__(self, binary: Path, threads: int, workdir: Path, gate: CpuGate):
        self.binary, self.threads, self.workdir, self.gate = binary, threads, workdir, gate

    def render(self, spp: int):
        options = ["--integrator", "path", "--spp", str(spp), "--threads", str(self.threads),
                   "--seed", str(SEED)]
        output = self.workdir / "lancer-path.exr"
        return run_lancer(self.binary, REFERENCE_SCENE, output, options, self.gate)


def mitsuba_cornell_box(mi) -> dict:
    description = mi.cornell_box()
    description["integrator"]["max_depth"] = MITSUBA_MAX_DEPTH
    film = description["sensor"]["film"]
    film["width"] = film["height"] = 256
    film["rfilter"] = {"type": "box"}
    description["sensor"]["sampler"] = {"type": "independent"}
    return description


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_common_arguments(parser, "4,16,64,256,1024,4096", "cornell-time-to-error", 0.01, 64)
    parser.add_argument("--no-mitsuba", action="store_true", help="lancer only (no Mitsuba curves)")
    args = parser.parse_args()

    measurements = Measurements(args, REFERENCE_IMAGE)
    gate, record = measurements.gate, measurements.record

    mitsuba = (
        []
        if args.no_mitsuba
        else [
            MitsubaRenderer(v, args.threads, gate, mitsuba_cornell_box, SEED)
            for v in ("scalar_rgb", "llvm_ad_rgb")
        ]
    )
    with tempfile.TemporaryDirectory(prefix="lancer-cornell-bench.") as workdir:
        lancer = LancerRenderer(args.lancer, args.threads, Path(workdir), gate)
        render_interleaved(lancer.render, mitsuba, args.path_spp, args.mitsuba_spp, record)
    return measurements.report(
        args,
        "cornell-time-to-error",
        "Cornell box: time to error",
        f"Cornell box 256x256, max depth 7 (Mitsuba 8), {args.threads} threads",
        REFERENCE_SPP,
        ["lancer path"],
        ["mitsuba scalar_rgb", "mitsuba llvm_ad_rgb"],
    )


if __name__ == "__main__":
    sys.exit(main())
