#!/usr/bin/env python3
"""Time-to-error on the Cornell box: lancer (path, radiosity) and Mitsuba 3 (scalar_rgb,
llvm_ad_rgb) against Mitsuba's 16384-spp reference, in the same run, on the same threads.

Run it through bench/cornell_time_to_error.sh, which installs Mitsuba and brings lancer up to
date; see bench/README.md. Before each timed run it waits (a while) for idle CPUs. It writes a CSV and a log-log plot of the relative RMSE
against time, prints a Markdown report (the table, the ratios against Mitsuba at equal time and
at equal error, and the convergence check of lancer's path tracer), and exits with status 1 when
the convergence check fails.

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
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import image_error  # bench/image_error.py, beside this script
import numpy as np

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
        output = self.workdir / f"lancer-{integrator}.exr"
        output.unlink(missing_ok=True)
        command = [
            str(self.binary),
            str(scene),
            "-o",
            str(output),
            "--integrator",
            integrator,
            "--spp",
            str(spp),
            "--threads",
            str(self.threads),
            "--seed",
            str(SEED),
        ]
        self.gate.wait()
        start = time.perf_counter()
        result = subprocess.run(command, capture_output=True, text=True, check=False)
        seconds = time.perf_counter() - start
        if result.returncode != 0:
            sys.exit(f"cornell_time_to_error: {' '.join(command)} failed:\n{result.stderr}")
        # The summary line: "lancer: FILE: 256x256, 64 spp, 2 threads, 1.23 s, ..."
        reported = re.findall(r", ([0-9.]+) s, ", result.stderr)
        reported_seconds = float(reported[-1]) if reported else math.nan
        return read_exr(output), seconds, reported_seconds, result.stderr


class MitsubaRenderer:
    def __init__(self, variant: str, threads: int, gate: CpuGate):
        import drjit as dr
        import mitsuba as mi

        self.mi, self.dr, self.gate, self.variant = mi, dr, gate, variant
        mi.set_variant(variant)
        dr.set_thread_count(threads)
        description = mi.cornell_box()
        description["integrator"]["max_depth"] = MITSUBA_MAX_DEPTH
        film = description["sensor"]["film"]
        film["width"] = film["height"] = 256
        film["rfilter"] = {"type": "box"}
        description["sensor"]["sampler"] = {"type": "independent"}
        self.scene = mi.load_dict(description)

    def render(self, spp: int):
        self.mi.set_variant(self.variant)  # the runs of the variants are interleaved
        if self.variant.startswith("llvm"):
            self.render_untimed(spp)  # compiles the kernel (or loads it from Dr.Jit's cache)
        self.gate.wait()
        start = time.perf_counter()
        image = np.array(self.mi.render(self.scene, spp=spp, seed=SEED))
        self.dr.sync_thread()
        return image, time.perf_counter() - start

    def render_untimed(self, spp: int) -> None:
        np.array(self.mi.render(self.scene, spp=spp, seed=SEED + 1))


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


def convergence_check(runs: list[Run], max_error: float, slope_tolerance: float, slope_from: int):
    """Checks that lancer path converges to the reference as 1/sqrt(spp), to below max_error.

    The reference has noise of its own (16384 spp): Mitsuba's per-sample variance over 16384,
    a_mitsuba / 16384 from the fit of Mitsuba's runs, is the square of that noise in our measure.
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
        reference_noise = math.sqrt(mitsuba[0] / REFERENCE_SPP)
        source = "Mitsuba's variance / 16384"
    else:
        reference_noise, source = math.sqrt(max(c, 0.0)), "lancer's fitted floor"
    against_exact = np.sqrt(np.maximum(error**2 - reference_noise**2, 1e-12))
    tail = spp >= slope_from
    if tail.sum() < 2:
        sys.exit(
            f"cornell_time_to_error: the convergence check needs two path runs of at least "
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


def plot(runs: list[Run], path: Path, title: str, reference_noise: float) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    style = {
        "lancer path": ("C0", "o"),
        "lancer radiosity": ("C2", "s"),
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
    axes.set_ylabel("relative RMSE against Mitsuba 16384 spp")
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

    def record(renderer, setting, spp, image, seconds, reported=math.nan, note=""):
        run = Run(renderer, setting, spp, seconds, relative_rmse(image, reference), reported, note)
        runs.append(run)
        print(
            f"  {renderer:20} {setting:34} {seconds:8.2f} s  rel. RMSE {run.rel_rmse:.4f} {note}",
            file=sys.stderr,
            flush=True,
        )

    mitsuba = (
        []
        if args.no_mitsuba
        else [MitsubaRenderer(v, args.threads, gate) for v in ("scalar_rgb", "llvm_ad_rgb")]
    )
    with tempfile.TemporaryDirectory(prefix="lancer-cornell-bench.") as workdir:
        lancer = LancerRenderer(args.lancer, args.threads, Path(workdir), gate)
        # The renderers take turns at each spp, so that a change of the machine's load during the
        # run weighs on all of them alike.
        for spp in sorted(set(args.path_spp) | set(args.mitsuba_spp)):
            if spp in args.path_spp:
                image, seconds, reported, _ = lancer.render("path", spp)
                record("lancer path", f"{spp} spp", spp, image, seconds, reported)
            for renderer in mitsuba if spp in args.mitsuba_spp else []:
                image, seconds = renderer.render(spp)
                record(f"mitsuba {renderer.variant}", f"{spp} spp", spp, image, seconds)
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
    check = convergence_check(runs, args.max_error, args.slope_tolerance, args.slope_from)
    plot(
        runs,
        args.out / "cornell-time-to-error.png",
        f"Cornell box 256x256, max depth 7 (Mitsuba 8), {args.threads} threads",
        check["reference_noise"],
    )
    load_after = Path("/proc/loadavg").read_text().split()[:3]

    print("## Cornell box: time to error\n")
    print(
        f"- date: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; {args.threads} threads; "
        f"load average before {' '.join(load_before)}, after {' '.join(load_after)}; "
        f"runs that started on a busy CPU: {gate.busy_starts}"
    )
    print(
        f"- written: {args.out / 'cornell-time-to-error.csv'}, "
        f"{args.out / 'cornell-time-to-error.png'}\n"
    )
    print("| renderer | setting | time | relative RMSE | lancer's reported render time | notes |")
    print("| --- | --- | ---: | ---: | ---: | --- |")
    for r in runs:
        reported = "" if math.isnan(r.reported_seconds) else f"{r.reported_seconds:.2f} s"
        print(
            f"| {r.renderer} | {r.setting} | {r.seconds:.2f} s | {r.rel_rmse:.4f} | {reported} "
            f"| {r.note} |"
        )
    rows = [
        row
        for ours in ("lancer path", "lancer radiosity")
        for theirs in ("mitsuba scalar_rgb", "mitsuba llvm_ad_rgb")
        for row in ratios(runs, ours, theirs)
    ]
    if rows:
        print("\nAgainst Mitsuba (interpolated on its log-log curve; above 1: lancer is better):\n")
        print(
            "| lancer run | against | time | relative RMSE | their error / ours at equal time "
            "| their time / ours at equal error |"
        )
        print("| --- | --- | ---: | ---: | ---: | ---: |")
        print("\n".join(rows))
    print(
        f"\nConvergence of lancer path against the reference: the reference's own noise is "
        f"{check['reference_noise']:.4f} (from {check['reference_noise_source']}); lancer's "
        f"fitted floor {check['floor']:.4f}, so a bias of at most {check['bias']:.4f}. "
        f"Without the reference's noise, lancer's error falls with spp (from "
        f"{check['slope_from']} spp on) with a log-log slope of {check['slope']:.3f} (expected "
        f"-0.5 within {args.slope_tolerance}; over all runs and as measured "
        f"{check['raw_slope']:.3f}) and is {check['error_at_highest_spp']:.4f} at "
        f"{check['highest_spp']} spp ({check['raw_error_at_highest_spp']:.4f} as measured; it "
        f"must be below {args.max_error}): **{'passed' if check['passed'] else 'FAILED'}**"
    )
    return 0 if check["passed"] else 1


if __name__ == "__main__":
    sys.exit(main())
