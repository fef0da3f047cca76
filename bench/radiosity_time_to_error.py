#!/usr/bin/env python3
"""Issue 12's curve of error against time on the Mitsuba Cornell box (tests/cli/data/cornell):
lancer's hierarchical radiosity at a few settings, beside lancer `path` at 4 to 1024 spp and
POV-Ray 3.7's radiosity (bench/cornell-radiosity.pov) at a few quality levels.

Every run is the whole process (scene loading, solve, render, writing the image), timed by the
wall clock on the given threads, once the exclusive lock /tmp/lancer-cpu.lock is held and the CPUs
are idle (bench/time_to_error.py's gate); runs under 5 s are timed three times and their median
kept (lancer's images are the same each time; POV-Ray's radiosity, on 2 threads, differs a
little from run to run: the last run's image is measured). The error is issue 12's
(bench/radiosity_methods.py): the RMSE against the reference without a depth limit
(`mitsuba-path-unbounded-16384spp.exr`, every bounce, as radiosity holds) over the image without
the lamp's box (rows 30-42, columns 103-152), and that RMSE relative to the reference's mean
there; also the image's mean there against the reference's (a bias shows in it). Writes
docs/bench/radiosity-time-to-error.csv and .png (log-log, with the issue's aim: 0.002 in 2 s) and
prints a Markdown table.

    build/mitsuba-venv/bin/python bench/radiosity_time_to_error.py [--threads 2] \\
        [--lancer bin/lancer] [--out docs/bench]

Needs NumPy, matplotlib and Mitsuba (to read the EXR images; bench/setup-mitsuba.sh) and
/usr/bin/povray (POV-Ray 3.7, with OpenEXR output). About 5 minutes on 2 cores.
"""

from __future__ import annotations

import argparse
import csv
import fcntl
import json
import re
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from radiosity_methods import errors, read_exr  # bench/, beside this script
from time_to_error import CpuGate

ROOT = Path(__file__).resolve().parent.parent
CORNELL = ROOT / "tests" / "cli" / "data" / "cornell"
POV_SCENE = ROOT / "bench" / "cornell-radiosity.pov"
CPU_LOCK = Path("/tmp/lancer-cpu.lock")
AIM_RMSE, AIM_SECONDS = 0.002, 2.0  # issue 12: at most 0.002 in at most 2 s
REPEAT_BELOW_SECONDS = 5.0

PATH_SPP = [4, 16, 64, 256, 1024]
PATH_MAX_DEPTH = 100  # the reference's paths end only by Russian roulette

# (setting, its label on the plot, the scene's "radiosity" block besides "method", spp)
LANCER_RADIOSITY: list[tuple[str, str, dict, int]] = [
    ("hierarchical, refinement_tolerance 0.05", "0.05", {"refinement_tolerance": 0.05}, 16),
    ("hierarchical, defaults (refinement_tolerance 0.02)", "defaults", {}, 16),
    ("hierarchical, refinement_tolerance 0.01", "0.01", {"refinement_tolerance": 0.01}, 16),
    ("hierarchical, refinement_tolerance 0.005", "0.005", {"refinement_tolerance": 0.005}, 16),
    ("hierarchical, final_gather 64", "4 spp", {"final_gather": 64}, 4),
    ("hierarchical, final_gather 64", "16 spp", {"final_gather": 64}, 16),
]

# POV-Ray's quality levels, fast to slow: the Declare= values of bench/cornell-radiosity.pov
# (the others at the file's defaults: recursion_limit 12, pretrace_end 0.01, minimum_reuse
# 0.005, adc_bailout 0.001); on the plot count/nearest/error_bound. The first is POV-Ray's own
# count, nearest_count and error_bound.
POV_QUALITY: list[dict[str, float]] = [
    {"COUNT": 35, "NEAREST": 5, "ERROR_BOUND": 1.8},
    {"COUNT": 100, "NEAREST": 10, "ERROR_BOUND": 1.0},
    {"COUNT": 200, "NEAREST": 10, "ERROR_BOUND": 0.5},
    {"COUNT": 400, "NEAREST": 10, "ERROR_BOUND": 0.5},
    {"COUNT": 400, "NEAREST": 20, "ERROR_BOUND": 0.25},
    {"COUNT": 1000, "NEAREST": 20, "ERROR_BOUND": 0.5},
    {"COUNT": 1600, "NEAREST": 20, "ERROR_BOUND": 0.25},
]
# Every pixel supersampled on a 3 x 3 grid, not jittered: averaged over the pixel as the
# reference is (its box filter), without noise of its own.
POV_ANTIALIASING = ["+AM1", "+A0.0", "+R3", "-J"]


@dataclass
class Run:
    renderer: str  # "lancer path", "lancer radiosity", "POV-Ray radiosity"...
    setting: str
    label: str  # the setting in short, beside its point on the plot
    seconds: float  # the median of the timed runs
    timed_runs: int
    rmse: float
    relative_rmse: float
    mean_vs_reference: float  # the image's mean off the lamp over the reference's
    note: str = ""


class Bench:
    def __init__(self, threads: int, max_wait: float, workdir: Path):
        self.threads, self.workdir = threads, workdir
        self.gate = CpuGate(max_wait)
        self.reference = read_exr(CORNELL / "mitsuba-path-unbounded-16384spp.exr")
        self.off_lamp = np.ones(self.reference.shape[:2], bool)
        self.off_lamp[30:43, 103:153] = False
        self.runs: list[Run] = []

    def timed(self, command: list[str]) -> tuple[float, str]:
        """Runs command holding the exclusive CPU lock, once the CPUs are idle: (its wall clock,
        its stderr and stdout)."""
        with open(CPU_LOCK, "a") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            self.gate.wait()
            start = time.perf_counter()
            result = subprocess.run(command, capture_output=True, text=True, cwd=self.workdir)
            seconds = time.perf_counter() - start
        if result.returncode != 0:
            sys.exit(f"radiosity_time_to_error: {' '.join(command)} failed:\n"
                     f"{result.stderr[-2000:]}{result.stdout[-2000:]}")
        return seconds, result.stderr + result.stdout

    def measure(self, renderer: str, setting: str, label: str, command: list[str], output: Path,
                note_of=lambda log: "") -> None:
        output.unlink(missing_ok=True)
        seconds, log = self.timed(command)
        times = [seconds]
        if seconds < REPEAT_BELOW_SECONDS:
            times += [self.timed(command)[0] for _ in range(2)]
        image = read_exr(output)
        rmse, relative = errors(image, self.reference)
        mean_ratio = float(image[self.off_lamp].mean() / self.reference[self.off_lamp].mean())
        run = Run(renderer, setting, label, statistics.median(times), len(times), rmse, relative,
                  mean_ratio, note_of(log))
        self.runs.append(run)
        print(f"  {renderer:32} {setting:55} {run.seconds:7.2f} s  RMSE {rmse:.5f}  "
              f"mean {mean_ratio:.3f}", file=sys.stderr, flush=True)

    def lancer(self, binary: Path, renderer: str, setting: str, label: str, scene: dict) -> None:
        path = self.workdir / "cornell.json"
        path.write_text(json.dumps(scene))
        output = self.workdir / "lancer.exr"
        command = [str(binary), str(path), "-o", str(output), "--threads", str(self.threads)]
        self.measure(renderer, setting, label, command, output,
                     lambda log: "".join(re.findall(r"radiosity: (.*)", log)[-1:]))

    def povray(self, quality: dict[str, float]) -> None:
        output = self.workdir / "povray.exr"
        declares = [f"Declare={name}={value}" for name, value in quality.items()]
        command = ["povray", f"+I{POV_SCENE}", f"+O{output}", "+FE", "+W256", "+H256",
                   *POV_ANTIALIASING, "-D", "-P", f"+WT{self.threads}", *declares]
        setting = ", ".join(f"{name.lower()} {value}" for name, value in quality.items())
        label = "/".join(str(value) for value in quality.values())
        self.measure("POV-Ray radiosity", setting, label, command, output,
                     lambda log: "".join(f"radiosity pretrace {seconds} s" for seconds in
                                         re.findall(r"Radiosity Time:.*\(([0-9.]+) seconds", log)))


def cornell_scene() -> dict:
    text = CORNELL.joinpath("cornell.json").read_text()
    return json.loads("\n".join(l for l in text.splitlines() if not l.lstrip().startswith("//")))


def write_csv(runs: list[Run], path: Path) -> None:
    with open(path, "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["renderer", "setting", "seconds", "timed_runs", "rmse_off_lamp",
                         "relative_rmse", "mean_vs_reference", "note"])
        for r in runs:
            writer.writerow([r.renderer, r.setting, f"{r.seconds:.3f}", r.timed_runs,
                             f"{r.rmse:.6f}", f"{r.relative_rmse:.5f}",
                             f"{r.mean_vs_reference:.4f}", r.note])


def plot(runs: list[Run], path: Path, title: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    style = {
        "lancer radiosity": ("C2", "s"),
        "lancer radiosity, final gather": ("C4", "D"),
        "lancer path": ("C0", "o"),
        "POV-Ray radiosity": ("C3", "^"),
    }
    figure, axes = plt.subplots(figsize=(7.5, 5.5), dpi=110)
    for renderer, (colour, marker) in style.items():
        points = sorted((r.seconds, r.rmse) for r in runs if r.renderer == renderer)
        if points:
            axes.loglog(*zip(*points), marker=marker, color=colour, label=renderer)
    for r in runs:
        axes.annotate(r.label, (r.seconds, r.rmse), textcoords="offset points", xytext=(5, -3),
                      fontsize=6.5, color=style[r.renderer][0])
    axes.plot([AIM_SECONDS], [AIM_RMSE], marker="*", markersize=14, color="black", linestyle="",
              label=f"issue 12's aim: {AIM_RMSE} in {AIM_SECONDS:g} s")
    axes.axhline(AIM_RMSE, color="black", linewidth=0.6, linestyle=":")
    axes.axvline(AIM_SECONDS, color="black", linewidth=0.6, linestyle=":")
    axes.set_xlabel("whole process, wall clock (s)")
    axes.set_ylabel("RMSE off the lamp against Mitsuba, 16384 spp, every bounce")
    axes.set_title(title, fontsize=9)
    axes.grid(True, which="both", linewidth=0.3)
    axes.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--lancer", type=Path, default=ROOT / "bin" / "lancer")
    parser.add_argument("--out", type=Path, default=ROOT / "docs" / "bench",
                        help="folder for radiosity-time-to-error.{csv,png}")
    parser.add_argument("--max-wait", type=float, default=30,
                        help="before each timed run, wait up to this many seconds for idle CPUs")
    args = parser.parse_args()
    load_before = Path("/proc/loadavg").read_text().split()[:3]
    started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    with tempfile.TemporaryDirectory(prefix="lancer-radiosity-time.") as workdir:
        bench = Bench(args.threads, args.max_wait, Path(workdir))
        for setting, label, block, spp in LANCER_RADIOSITY:
            scene = cornell_scene()
            scene["render"].update({"integrator": "radiosity", "spp": spp})
            scene["radiosity"] = {"method": "hierarchical", **block}
            renderer = "lancer radiosity" + (", final gather" if "final_gather" in block else "")
            bench.lancer(args.lancer, renderer, f"{setting}, {spp} spp", label, scene)
        for spp in PATH_SPP:
            scene = cornell_scene()
            scene["render"].update({"integrator": "path", "spp": spp, "max_depth": PATH_MAX_DEPTH})
            bench.lancer(args.lancer, "lancer path", f"{spp} spp, max_depth {PATH_MAX_DEPTH}",
                         f"{spp} spp", scene)
        for quality in POV_QUALITY:
            bench.povray(quality)
    load_after = Path("/proc/loadavg").read_text().split()[:3]
    args.out.mkdir(parents=True, exist_ok=True)
    write_csv(bench.runs, args.out / "radiosity-time-to-error.csv")
    plot(bench.runs, args.out / "radiosity-time-to-error.png",
         f"Mitsuba Cornell box, 256 x 256, {args.threads} threads ({started})")
    print(f"- {started}; {args.threads} threads; load average before {' '.join(load_before)}, "
          f"after {' '.join(load_after)}; runs that started on a busy CPU: "
          f"{bench.gate.busy_starts}\n")
    print("| renderer | setting | time | timed runs | RMSE off the lamp | relative | "
          "mean / reference's | notes |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | --- |")
    for r in bench.runs:
        print(f"| {r.renderer} | {r.setting} | {r.seconds:.2f} s | {r.timed_runs} | "
              f"{r.rmse:.5f} | {r.relative_rmse:.4f} | {r.mean_vs_reference:.3f} | {r.note} |")


if __name__ == "__main__":
    main()
