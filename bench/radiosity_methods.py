#!/usr/bin/env python3
"""Radiosity methods on the Cornell box: lancer's progressive and hierarchical radiosity at a few
settings, each the whole process timed (solve and a 16-spp render, 256 x 256) on the given
threads, against Mitsuba 3's 16384-spp path-traced references, with the measure of issue 12: the
RMSE over the image without the lamp's box (rows 30-42, columns 103-152), and the relative RMSE
(that RMSE over the reference's mean there). Two references: the stored one, whose paths are cut
at 7 bounces (Mitsuba's max_depth 8), and the one without a cut
(`mitsuba-path-unbounded-16384spp.exr`, made by bench/mitsuba_cornell_unbounded.py), which holds
every bounce of light, as radiosity does: the cut takes up to 20% of the light from the dark
corners. Prints a Markdown table for docs/BENCHMARKS.md.

    build/mitsuba-venv/bin/python bench/radiosity_methods.py [--threads 2] [--lancer bin/lancer]

Needs NumPy and Mitsuba (to read the EXR images): bench/setup-mitsuba.sh installs both.
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
CORNELL = ROOT / "tests" / "cli" / "data" / "cornell"

# (label, the scene's "radiosity" block)
SETTINGS: list[tuple[str, dict]] = [
    ("progressive, defaults", {}),
    ("progressive, patch_size 0.7, subdivision_levels 1", {"patch_size": 0.7, "subdivision_levels": 1}),
    ("hierarchical, defaults", {"method": "hierarchical"}),
    ("hierarchical, refinement_tolerance 0.05", {"method": "hierarchical", "refinement_tolerance": 0.05}),
    ("hierarchical, refinement_tolerance 0.01", {"method": "hierarchical", "refinement_tolerance": 0.01}),
    ("hierarchical, visibility_rays 16", {"method": "hierarchical", "visibility_rays": 16}),
    ("hierarchical, clusters", {"method": "hierarchical", "clusters": True}),
    ("hierarchical, direct_samples 4", {"method": "hierarchical", "direct_samples": 4}),
    ("hierarchical, direct_samples 16", {"method": "hierarchical", "direct_samples": 16}),
    ("progressive, direct_samples 16", {"direct_samples": 16}),
]


def read_exr(path: Path) -> np.ndarray:
    import mitsuba as mi

    if not mi.variant():
        mi.set_variant("scalar_rgb")
    return np.array(mi.Bitmap(str(path)), dtype=np.float64)[..., :3]


def errors(image: np.ndarray, reference: np.ndarray) -> tuple[float, float]:
    mask = np.ones(reference.shape[:2], bool)
    mask[30:43, 103:153] = False  # the lamp's box
    rmse = float(np.sqrt(np.mean((image - reference)[mask] ** 2)))
    return rmse, rmse / float(reference[mask].mean())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--lancer", type=Path, default=ROOT / "bin" / "lancer")
    args = parser.parse_args()
    reference = read_exr(CORNELL / "mitsuba-path-16384spp.exr")
    unbounded = read_exr(CORNELL / "mitsuba-path-unbounded-16384spp.exr")
    text = CORNELL.joinpath("cornell.json").read_text()
    scene = json.loads("\n".join(l for l in text.splitlines() if not l.lstrip().startswith("//")))
    scene["render"].update({"integrator": "radiosity", "spp": 16})
    print("| method and settings | whole process | RMSE off the lamp, every bounce | relative | "
          "against 7 bounces | relative | solution |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory(prefix="lancer-radiosity-bench.") as workdir:
        for label, block in SETTINGS:
            scene["radiosity"] = block
            path = Path(workdir) / "cornell.json"
            path.write_text(json.dumps(scene))
            output = Path(workdir) / "out.exr"
            start = time.perf_counter()
            run = subprocess.run(
                [str(args.lancer), str(path), "-o", str(output), "--threads", str(args.threads)],
                capture_output=True, text=True, check=True)
            seconds = time.perf_counter() - start
            image = read_exr(output)
            rmse, relative = errors(image, unbounded)
            rmse7, relative7 = errors(image, reference)
            note = "".join(re.findall(r"radiosity: (.*)", run.stderr)[-1:])
            print(f"| {label} | {seconds:.2f} s | {rmse:.5f} | {relative:.4f} | {rmse7:.5f} | "
                  f"{relative7:.4f} | {note} |", flush=True)


if __name__ == "__main__":
    main()
