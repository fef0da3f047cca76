#!/usr/bin/env python3
"""What the time-to-error benchmarks (bench/cornell_time_to_error.py,
bench/envmap_time_to_error.py) share: running lancer and Mitsuba 3 with timing, waiting for idle
CPUs, the error measure, the CSV, the log-log plot and the Markdown tables.

The error measure, the same for every renderer (and bench/image_error.py's):
    relative RMSE = sqrt(mean over pixels and channels of (image - reference)^2) / mean(reference)

What the times measure:
- lancer: the wall clock of the whole process (start-up, scene loading and BVH, radiosity solve,
  rendering, writing the EXR), as a user waits for it.
- Mitsuba: the wall clock of mi.render() alone, until the image is a NumPy array. The scene is
  loaded before the clock starts, and llvm_ad_rgb renders each configuration once untimed first,
  so that Python start-up, scene loading and JIT compilation are left out (the timed run reuses
  the compiled kernel). This favours Mitsuba slightly.
"""

from __future__ import annotations

import argparse
import csv
import math
import os
import re
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import image_error  # bench/image_error.py, beside this script
import numpy as np

ROOT = Path(__file__).resolve().parent.parent

def relative_rmse(image: np.ndarray, reference: np.ndarray) -> float:
    """The measure of bench/image_error.py (the adaptive-sampling benchmark's), the same code."""
    return image_error.errors(reference.ravel().tolist(), image.ravel().tolist())[2]


def read_exr(path: Path) -> np.ndarray:
    """An RGB EXR as an array of shape (height, width, 3), top row first. (EXR rather than PFM:
    FreeImage, which lancer writes images with, stores PFM rows top row first, against the
    format's bottom-to-top order, so other readers see lancer's PFMs upside down.)"""
    import mitsuba as mi

    if not mi.variant():
        mi.set_variant("scalar_rgb")
    return np.array(mi.Bitmap(str(path)), dtype=np.float32)


@dataclass
class Run:
    renderer: str  # "lancer path", "mitsuba llvm_ad_rgb", ...
    setting: str  # "64 spp", "patch_size 0.1, threshold 0.01", ...
    spp: int
    seconds: float  # see the module's docstring for what this includes
    rel_rmse: float
    reported_seconds: float = math.nan  # lancer's own render time, from its summary line
    note: str = ""  # radiosity: lancer's line about the solution (patches, shots, solve time)


class CpuGate:
    """Waits, before each timed run, for the CPUs to be idle, so that other work on a shared
    machine does not land in the timings; counts the runs that had to start anyway."""

    def __init__(self, max_wait: float):
        self.max_wait = max_wait
        self.busy_starts = 0

    @staticmethod
    def _busy_percent(interval: float = 0.5) -> float:
        def sample() -> tuple[int, int]:
            with open("/proc/stat") as stat:
                fields = [int(x) for x in stat.readline().split()[1:9]]
            return sum(fields), fields[3] + fields[4]  # total, idle + iowait

        total1, idle1 = sample()
        time.sleep(interval)
        total2, idle2 = sample()
        return 100.0 * (1 - (idle2 - idle1) / max(total2 - total1, 1))

    def wait(self) -> None:
        deadline = time.monotonic() + self.max_wait
        while self._busy_percent() > 10:
            if time.monotonic() >= deadline:
                self.busy_starts += 1
                return
            time.sleep(2)

def run_lancer(binary: Path, scene: Path, output: Path, options: list[str], gate: CpuGate):
    """Renders scene with lancer (options: --spp, --threads...) into the EXR output, after waiting
    for idle CPUs: (the image, the process's wall clock, lancer's reported render time, its
    stderr)."""
    output.unlink(missing_ok=True)
    command = [str(binary), str(scene), "-o", str(output), *options]
    gate.wait()
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - start
    if result.returncode != 0:
        sys.exit(f"{Path(sys.argv[0]).stem}: {' '.join(command)} failed:\n{result.stderr}")
    # The summary line: "lancer: FILE: 256x256, 64 spp, 2 threads, 1.23 s, ..."
    reported = re.findall(r", ([0-9.]+) s, ", result.stderr)
    reported_seconds = float(reported[-1]) if reported else math.nan
    return read_exr(output), seconds, reported_seconds, result.stderr


class MitsubaRenderer:
    """A Mitsuba 3 variant rendering one scene: describe(mi) gives its dictionary, made once the
    variant is set (a dictionary may hold objects of the variant, such as a Bitmap)."""

    def __init__(self, variant: str, threads: int, gate: CpuGate, describe, seed: int):
        import drjit as dr
        import mitsuba as mi

        self.mi, self.dr, self.gate, self.variant, self.seed = mi, dr, gate, variant, seed
        mi.set_variant(variant)
        dr.set_thread_count(threads)
        self.scene = mi.load_dict(describe(mi))

    def render(self, spp: int):
        self.mi.set_variant(self.variant)  # the runs of the variants are interleaved
        if self.variant.startswith("llvm"):
            self.render_untimed(spp)  # compiles the kernel (or loads it from Dr.Jit's cache)
        self.gate.wait()
        start = time.perf_counter()
        image = np.array(self.mi.render(self.scene, spp=spp, seed=self.seed))
        self.dr.sync_thread()
        return image, time.perf_counter() - start

    def render_untimed(self, spp: int) -> None:
        np.array(self.mi.render(self.scene, spp=spp, seed=self.seed + 1))


def interpolate_loglog(xs, ys, x):
    """y at x on the piecewise log-log line through (xs, ys) sorted by xs; None outside."""
    lx, ly = np.log(xs), np.log(ys)
    if not lx[0] <= math.log(x) <= lx[-1]:
        return None
    return float(np.exp(np.interp(math.log(x), lx, ly)))


def curve(runs: list[Run], renderer: str):
    points = sorted((r.seconds, r.rel_rmse) for r in runs if r.renderer == renderer)
    return [p[0] for p in points], [p[1] for p in points]


def fit_noise(runs: list[Run], renderer: str):
    """(a, c) of error^2 = a/spp + c fitted to a renderer's runs (relative residuals, so that the
    low-error runs count as much as the noisy ones): a/spp is the renderer's own noise, c what
    stays at any spp (the reference's noise, and any bias)."""
    points = sorted((r.spp, r.rel_rmse) for r in runs if r.renderer == renderer)
    if len(points) < 2:
        return None
    spp = np.array([p[0] for p in points], dtype=float)
    squared = np.array([p[1] for p in points]) ** 2
    design = np.stack([1 / spp, np.ones_like(spp)], axis=1) / squared[:, None]
    a, c = np.linalg.lstsq(design, np.ones_like(spp), rcond=None)[0]
    return float(a), float(c)

def convergence_check(
    runs: list[Run], reference_spp: int, max_error: float, slope_tolerance: float, slope_from: int
):
    """Checks that lancer path converges to the reference as 1/sqrt(spp), to below max_error.

    The reference has noise of its own (reference_spp, rendered by Mitsuba): Mitsuba's per-sample
    variance over reference_spp, a_mitsuba / reference_spp from the fit of Mitsuba's runs, is the square of that noise in our measure.
    Removing it from lancer's measured error (errors of independent images add in squares) gives
    lancer's error against the exact image, which must fall with slope -0.5 in log-log from
    slope_from spp on (below that, stratified pixel sampling makes it fall faster: edges converge
    sooner than the light paths) and end below max_error. Without Mitsuba runs, lancer's own
    fitted floor stands in for the reference's noise (it would hide a bias: the report says which
    was used)."""
    path = sorted((r.spp, r.rel_rmse) for r in runs if r.renderer == "lancer path")
    spp = np.array([p[0] for p in path], dtype=float)
    error = np.array([p[1] for p in path])
    c = fit_noise(runs, "lancer path")[1]
    mitsuba = fit_noise(runs, "mitsuba scalar_rgb") or fit_noise(runs, "mitsuba llvm_ad_rgb")
    if mitsuba:
        reference_noise = math.sqrt(mitsuba[0] / reference_spp)
        source = f"Mitsuba's variance / {reference_spp}"
    else:
        reference_noise, source = math.sqrt(max(c, 0.0)), "lancer's fitted floor"
    against_exact = np.sqrt(np.maximum(error**2 - reference_noise**2, 1e-12))
    tail = spp >= slope_from
    if tail.sum() < 2:
        sys.exit(
            f"{Path(sys.argv[0]).stem}: the convergence check needs two path runs of at least "
            f"{slope_from} spp"
        )
    slope = float(np.polyfit(np.log(spp[tail]), np.log(against_exact[tail]), 1)[0])
    return {
        "raw_slope": float(np.polyfit(np.log(spp), np.log(error), 1)[0]),
        "reference_noise": reference_noise,
        "reference_noise_source": source,
        "floor": math.sqrt(max(c, 0.0)),
        "bias": math.sqrt(max(c - reference_noise**2, 0.0)),
        "slope": slope,
        "slope_from": slope_from,
        "highest_spp": int(spp[-1]),
        "raw_error_at_highest_spp": float(error[-1]),
        "error_at_highest_spp": float(against_exact[-1]),
        "passed": abs(slope + 0.5) <= slope_tolerance and against_exact[-1] < max_error,
    }


def write_csv(runs: list[Run], path: Path) -> None:
    with open(path, "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(
            ["renderer", "setting", "spp", "seconds", "rel_rmse", "reported_seconds", "note"]
        )
        for r in runs:
            writer.writerow(
                [
                    r.renderer,
                    r.setting,
                    r.spp,
                    f"{r.seconds:.4f}",
                    f"{r.rel_rmse:.6f}",
                    "" if math.isnan(r.reported_seconds) else f"{r.reported_seconds:.2f}",
                    r.note,
                ]
            )


def plot(runs: list[Run], path: Path, title: str, reference_noise: float, reference: str) -> None:
    """The log-log plot of error against time; reference names the reference image ("Mitsuba
    16384 spp")."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    style = {
        "lancer path": ("C0", "o"),
        "mitsuba scalar_rgb": ("C3", "^"),
        "mitsuba llvm_ad_rgb": ("C1", "v"),
    }
    # A run that failed outright (an error above 100%, worse than a black image) would squash the
    # curves: the table lists it, the plot leaves it out and says so.
    failed = [r for r in runs if r.rel_rmse > 1]
    runs = [r for r in runs if r.rel_rmse <= 1]
    if failed:
        title += "\nleft out, error above 1: " + "; ".join(
            f"{r.renderer} {r.setting}" for r in failed
        )
    figure, axes = plt.subplots(figsize=(7, 5), dpi=110)
    for renderer, (colour, marker) in style.items():
        xs, ys = curve(runs, renderer)
        if xs:
            axes.loglog(xs, ys, marker=marker, color=colour, label=renderer)
    for r in runs:
        if r.renderer in ("lancer path", "mitsuba llvm_ad_rgb"):
            axes.annotate(
                str(r.spp),
                (r.seconds, r.rel_rmse),
                textcoords="offset points",
                xytext=(4, 4),
                fontsize=7,
                color=style[r.renderer][0],
            )
    axes.axhline(0.01, color="grey", linewidth=0.8, linestyle=":")
    axes.axhline(
        reference_noise,
        color="black",
        linewidth=0.8,
        linestyle="--",
        label="the reference's own noise",
    )
    axes.set_xlabel("time (s), 2 threads")
    axes.set_ylabel(f"relative RMSE against {reference}")
    axes.set_title(title, fontsize=10)
    axes.grid(True, which="both", linewidth=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(path)


def ratios(runs: list[Run], ours: str, theirs: str) -> list[str]:
    """Markdown rows: Mitsuba's time / ours at equal error, Mitsuba's error / ours at equal time
    (above 1: lancer is better), on the part of the curves both cover."""
    their_t, their_e = curve(runs, theirs)
    if not their_t:
        return []
    rows = []
    for r in sorted((r for r in runs if r.renderer == ours), key=lambda r: r.seconds):
        their_error = interpolate_loglog(their_t, their_e, r.seconds)
        their_time = interpolate_loglog(*zip(*sorted(zip(their_e, their_t))), r.rel_rmse)
        if their_error is None and their_time is None:
            continue
        at_time = f"{their_error / r.rel_rmse:.2f}" if their_error else "-"
        at_error = f"{their_time / r.seconds:.2f}" if their_time else "-"
        rows.append(
            f"| {ours} {r.setting} | {theirs} | {r.seconds:.2f} s | {r.rel_rmse:.4f} "
            f"| {at_time} | {at_error} |"
        )
    return rows


def spp_list(text: str) -> list[int]:
    values = [int(v) for v in text.split(",") if v]
    if not values or min(values) < 1:
        raise argparse.ArgumentTypeError("expected a comma-separated list of positive integers")
    return sorted(values)

def print_runs(runs: list[Run]) -> None:
    print("| renderer | setting | time | relative RMSE | lancer's reported render time | notes |")
    print("| --- | --- | ---: | ---: | ---: | --- |")
    for r in runs:
        reported = "" if math.isnan(r.reported_seconds) else f"{r.reported_seconds:.2f} s"
        print(
            f"| {r.renderer} | {r.setting} | {r.seconds:.2f} s | {r.rel_rmse:.4f} | {reported} "
            f"| {r.note} |"
        )


def print_ratios(runs: list[Run], ours: list[str], theirs: list[str]) -> None:
    rows = [row for o in ours for t in theirs for row in ratios(runs, o, t)]
    if rows:
        print("\nAgainst Mitsuba (interpolated on its log-log curve; above 1: lancer is better):\n")
        print(
            "| lancer run | against | time | relative RMSE | their error / ours at equal time "
            "| their time / ours at equal error |"
        )
        print("| --- | --- | ---: | ---: | ---: | ---: |")
        print("\n".join(rows))


def print_convergence(check: dict, slope_tolerance: float, max_error: float) -> None:
    """The report of convergence_check."""
    print(
        f"\nConvergence of lancer path against the reference: the reference's own noise is "
        f"{check['reference_noise']:.4f} (from {check['reference_noise_source']}); lancer's "
        f"fitted floor {check['floor']:.4f}, so a bias of at most {check['bias']:.4f}. "
        f"Without the reference's noise, lancer's error falls with spp (from "
        f"{check['slope_from']} spp on) with a log-log slope of {check['slope']:.3f} (expected "
        f"-0.5 within {slope_tolerance}; over all runs and as measured "
        f"{check['raw_slope']:.3f}) and is {check['error_at_highest_spp']:.4f} at "
        f"{check['highest_spp']} spp ({check['raw_error_at_highest_spp']:.4f} as measured; it "
        f"must be below {max_error}): **{'passed' if check['passed'] else 'FAILED'}**"
    )


def print_conditions(threads: int, load_before: list[str], load_after: list[str], gate: CpuGate):
    """The report's line on the date, threads and load."""
    print(
        f"- date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; {threads} threads; "
        f"load average before {' '.join(load_before)}, after {' '.join(load_after)}; "
        f"runs that started on a busy CPU: {gate.busy_starts}"
    )


def add_run(runs: list[Run], reference, renderer, setting, spp, image, seconds, reported=math.nan,
            note=""):
    """Measures image against reference, appends the run to runs and logs it on stderr."""
    run = Run(renderer, setting, spp, seconds, relative_rmse(image, reference), reported, note)
    runs.append(run)
    print(
        f"  {renderer:20} {setting:34} {seconds:8.2f} s  rel. RMSE {run.rel_rmse:.4f} {note}",
        file=sys.stderr,
        flush=True,
    )



def render_interleaved(lancer_path, mitsuba: list[MitsubaRenderer], path_spp, mitsuba_spp, record):
    """lancer_path(spp) (run_lancer's result) at path_spp and the Mitsuba renderers at mitsuba_spp,
    each run passed to record(renderer, setting, spp, image, seconds[, reported])."""
    # The renderers take turns at each spp, so that a change of the machine's load during the
    # run weighs on all of them alike.
    for spp in sorted(set(path_spp) | set(mitsuba_spp)):
        if spp in path_spp:
            image, seconds, reported, _ = lancer_path(spp)
            record("lancer path", f"{spp} spp", spp, image, seconds, reported)
        for renderer in mitsuba if spp in mitsuba_spp else []:
            image, seconds = renderer.render(spp)
            record(f"mitsuba {renderer.variant}", f"{spp} spp", spp, image, seconds)


def add_common_arguments(
    parser: argparse.ArgumentParser, path_spp: str, out_name: str, max_error: float, slope_from: int
) -> None:
    """The options every time-to-error script takes; the arguments are their defaults."""
    parser.add_argument("--lancer", type=Path, default=ROOT / "bin" / "lancer")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--path-spp", type=spp_list, default=spp_list(path_spp))
    parser.add_argument("--mitsuba-spp", type=spp_list, default=spp_list("4,16,64,256,1024"))
    parser.add_argument(
        "--out",
        type=Path,
        default=ROOT / "docs" / "bench",
        help=f"folder for {out_name}.{{csv,png}}",
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
        default=max_error,
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
        default=slope_from,
        help="convergence check: fit the slope to the path runs from this spp on",
    )


class Measurements:
    """The runs of one benchmark against its reference image, with the gate before each run and
    the load average at the start."""

    def __init__(self, args: argparse.Namespace, reference_image: Path):
        if not os.access(args.lancer, os.X_OK):
            sys.exit(f"{Path(sys.argv[0]).stem}: no lancer program at {args.lancer}")
        self.gate = CpuGate(args.max_wait)
        self.load_before = Path("/proc/loadavg").read_text().split()[:3]
        self.reference = read_exr(reference_image)
        self.runs: list[Run] = []

    def record(self, *run, **details) -> None:
        add_run(self.runs, self.reference, *run, **details)

    def report(self, args, name: str, heading: str, title: str, reference_spp: int,
               ours: list[str], theirs: list[str]) -> int:
        """Writes name.{csv,png} into args.out, prints the Markdown report under heading (the
        plot's title: title) and returns the exit status: 1 if the convergence check failed."""
        args.out.mkdir(parents=True, exist_ok=True)
        write_csv(self.runs, args.out / f"{name}.csv")
        check = convergence_check(
            self.runs, reference_spp, args.max_error, args.slope_tolerance, args.slope_from
        )
        plot(
            self.runs,
            args.out / f"{name}.png",
            title,
            check["reference_noise"],
            f"Mitsuba {reference_spp} spp",
        )
        load_after = Path("/proc/loadavg").read_text().split()[:3]
        print(f"## {heading}\n")
        print_conditions(args.threads, self.load_before, load_after, self.gate)
        print(f"- written: {args.out / f'{name}.csv'}, {args.out / f'{name}.png'}\n")
        print_runs(self.runs)
        print_ratios(self.runs, ours, theirs)
        print_convergence(check, args.slope_tolerance, args.max_error)
        return 0 if check["passed"] else 1
