#!/usr/bin/env python3
"""Time-to-error on the Cornell box: lancer (path, radiosity) and Mitsuba 3 (scalar_rgb,
llvm_ad_rgb) against Mitsuba's 16384-spp reference, in the same run, on the same threads.

Run it through bench/cornell_time_to_error.sh, which installs Mitsuba and brings lancer up to
date; see bench/README.md. Before each timed run it waits (a while) for idle CPUs. It writes a CSV and a log-log plot of the relative RMSE
against time, prints a Markdown report (the table, the ratios against Mitsuba at equal time and
at equal error, and the convergence check of lancer's path tracer), and exits with status 1 when
the convergence check fails. The error measure and what the times measure: bench/time_to_error.py.
"""

from __future__ import annotations

import argparse
import math
import os
import re
import sys
import tempfile
import time
from pathlib import Path

from time_to_error import (  # bench/time_to_error.py, beside this script
    CpuGate,
    MitsubaRenderer,
    Run,
    convergence_check,
    plot,
    add_run,
    print_conditions,
    print_convergence,
    print_ratios,
    print_runs,
    read_exr,
    render_interleaved,
    relative_rmse,
    run_lancer,
    spp_list,
    write_csv,
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

# Radiosity quality settings, coarse to fine: (patch_size, threshold) of the scene's "radiosity"
# block (docs/SCENE-FORMAT.md; the defaults for this box: 0.43 and 0.01), and camera rays per
# pixel. The rays only anti-alias, but the lamp's edges (radiance 18 against 0.5) need many: at
# 16 spp they alone give a relative RMSE of about 10%.
RADIOSITY_SETTINGS: list[tuple[float, float, int]] = [
    (1.0, 0.01, 64),
    (0.5, 0.01, 64),
    (0.5, 0.001, 256),
]


class LancerRenderer:
    def __init__(self, binary: Path, threads: int, workdir: Path, gate: CpuGate):
        self.binary, self.threads, self.workdir, self.gate = binary, threads, workdir, gate
        self.scene_text = REFERENCE_SCENE.read_text()

    def scene_with_radiosity(self, patch_size: float, threshold: float) -> Path:
        """The reference scene with a "radiosity" block added (the original has none)."""
        block = f'"radiosity": {{"patch_size": {patch_size}, "threshold": {threshold}}},'
        text = re.sub(r"^\{", "{\n  " + block, self.scene_text, count=1, flags=re.MULTILINE)
        path = self.workdir / f"cornell-radiosity-{patch_size}-{threshold}.json"
        path.write_text(text)
        return path

    def render(self, integrator: str, spp: int, scene: Path = REFERENCE_SCENE):
        options = ["--integrator", integrator, "--spp", str(spp), "--threads", str(self.threads),
                   "--seed", str(SEED)]
        output = self.workdir / f"lancer-{integrator}.exr"
        return run_lancer(self.binary, scene, output, options, self.gate)


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
    parser.add_argument("--lancer", type=Path, default=ROOT / "bin" / "lancer")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--path-spp", type=spp_list, default=spp_list("4,16,64,256,1024,4096"))
    parser.add_argument("--mitsuba-spp", type=spp_list, default=spp_list("4,16,64,256,1024"))
    parser.add_argument("--no-mitsuba", action="store_true", help="lancer only (no Mitsuba curves)")
    parser.add_argument("--no-radiosity", action="store_true", help="no radiosity runs")
    parser.add_argument(
        "--out",
        type=Path,
        default=ROOT / "docs" / "bench",
        help="folder for cornell-time-to-error.{csv,png}",
    )
    parser.add_argument(
        "--max-wait",
        type=float,
        default=60,
        help="before each timed run, wait up to this many seconds for idle CPUs",
    )
    parser.add_argument(
        "--max-error",
        type=float,
        default=0.01,
        help="convergence check: lancer path's error at the highest spp",
    )
    parser.add_argument(
        "--slope-tolerance",
        type=float,
        default=0.1,
        help="convergence check: allowed distance of the fitted slope from -0.5",
    )
    parser.add_argument(
        "--slope-from",
        type=int,
        default=64,
        help="convergence check: fit the slope to the path runs from this spp on",
    )
    args = parser.parse_args()

    if not os.access(args.lancer, os.X_OK):
        sys.exit(f"cornell_time_to_error: no lancer program at {args.lancer}")
    gate = CpuGate(args.max_wait)
    load_before = Path("/proc/loadavg").read_text().split()[:3]
    reference = read_exr(REFERENCE_IMAGE)
    runs: list[Run] = []

    def record(*run, **details):
        add_run(runs, reference, *run, **details)

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
        render_interleaved(
            lambda spp: lancer.render("path", spp), mitsuba, args.path_spp, args.mitsuba_spp, record
        )
        for patch_size, threshold, spp in [] if args.no_radiosity else RADIOSITY_SETTINGS:
            scene = lancer.scene_with_radiosity(patch_size, threshold)
            image, seconds, reported, log = lancer.render("radiosity", spp, scene)
            # "lancer: radiosity: 690 patches, 12753 elements, ... solved in 42.79 s"
            note = "".join(re.findall(r"radiosity: (.*)", log)[-1:])
            record(
                "lancer radiosity",
                f"patch_size {patch_size}, threshold {threshold}, {spp} spp",
                spp,
                image,
                seconds,
                reported,
                note,
            )

    args.out.mkdir(parents=True, exist_ok=True)
    write_csv(runs, args.out / "cornell-time-to-error.csv")
    check = convergence_check(runs, REFERENCE_SPP, args.max_error, args.slope_tolerance, args.slope_from)
    plot(
        runs,
        args.out / "cornell-time-to-error.png",
        f"Cornell box 256x256, max depth 7 (Mitsuba 8), {args.threads} threads",
        check["reference_noise"],
        "Mitsuba 16384 spp",
    )
    load_after = Path("/proc/loadavg").read_text().split()[:3]

    print("## Cornell box: time to error\n")
    print_conditions(args.threads, load_before, load_after, gate)
    print(
        f"- written: {args.out / 'cornell-time-to-error.csv'}, "
        f"{args.out / 'cornell-time-to-error.png'}\n"
    )
    print_runs(runs)
    print_ratios(runs, ["lancer path", "lancer radiosity"], ["mitsuba scalar_rgb", "mitsuba llvm_ad_rgb"])
    print_convergence(check, args.slope_tolerance, args.max_error)
    return 0 if check["passed"] else 1


if __name__ == "__main__":
    sys.exit(main())
