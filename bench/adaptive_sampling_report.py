#!/usr/bin/env python3
"""The report of bench/adaptive_sampling.sh: errors against the reference, and adaptive against
uniform sampling at equal cost.

    bench/adaptive_sampling_report.py RUNS.csv [--setup TEXT]

For each scene, each render's relative RMSE against the reference (see image_error.py). The
uniform renders make a curve of error against cost; each adaptive render is compared with that
curve interpolated (linearly in log-log) at the adaptive render's own cost, once with cost = CPU
seconds and once with cost = rays traced. A ratio above 1 means adaptive sampling has the lower
error at equal cost. Adaptive renders whose cost falls outside the uniform curve are shown
without a ratio.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from collections import defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from image_error import errors, read_pfm  # noqa: E402


def interpolate_loglog(xs: list[float], ys: list[float], x: float) -> float | None:
    points = sorted(zip(xs, ys))
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        if x0 <= x <= x1:
            t = (math.log(x) - math.log(x0)) / (math.log(x1) - math.log(x0))
            return math.exp(math.log(y0) + t * (math.log(y1) - math.log(y0)))
    return None


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("runs")
    parser.add_argument("--setup", default="")
    args = parser.parse_args()

    rows = list(csv.DictReader(open(args.runs)))
    references: dict[str, object] = {}
    by_scene: dict[str, list[dict]] = defaultdict(list)
    for row in rows:
        if row["reference"] not in references:
            references[row["reference"]] = read_pfm(row["reference"])[2]
        row["error"] = errors(references[row["reference"]], read_pfm(row["image"])[2])[2]
        by_scene[row["scene"]].append(row)

    if args.setup:
        print(f"Setup: {args.setup}.\n")
    for scene, runs in by_scene.items():
        uniform = [r for r in runs if r["mode"] == "uniform"]
        adaptive = [r for r in runs if r["mode"] == "adaptive"]
        print(f"#### {scene}\n")
        print("| sampling | spp (mean) | CPU s | rays (M) | relative RMSE |")
        print("| --- | ---: | ---: | ---: | ---: |")
        for r in runs:
            w, h, _ = read_pfm(r["image"])
            pixels = w * h
            spp = int(r["samples"]) / pixels
            label = f"uniform {r['parameter']} spp" if r["mode"] == "uniform" \
                else f"adaptive, threshold {r['parameter']}"
            print(f"| {label} | {spp:.1f} | {float(r['cpu_seconds']):.2f} | "
                  f"{int(r['rays']) / 1e6:.2f} | {r['error']:.5f} |")
        print()
        print("| adaptive threshold | relative RMSE | uniform at equal CPU time | ratio | "
              "uniform at equal rays | ratio |")
        print("| --- | ---: | ---: | ---: | ---: | ---: |")
        for r in adaptive:
            cells = [r["parameter"], f"{r['error']:.5f}"]
            for cost in ("cpu_seconds", "rays"):
                u = interpolate_loglog([float(x[cost]) for x in uniform],
                                       [x["error"] for x in uniform], float(r[cost]))
                cells += [f"{u:.5f}", f"{u / r['error']:.2f}"] if u else ["outside", ""]
            print("| " + " | ".join(cells) + " |")
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
