#!/usr/bin/env python3
"""Clustered hierarchical radiosity against scene size: a model inside the Cornell box (its walls
and lamp, tests/cli/data/cornell, without the two blocks), solved with
{"method": "hierarchical", "clusters": true}, for the torus knot of
/work/shared/bench/mesh-knot/gen_mesh.py at 1k to 200k triangles and the Stanford bunny (69k,
/work/shared/assets/stanford_bunny, referenced in place). Each row is one run of bin/lancer on the
given threads (the solve, then a 64 x 64 image at 1 spp): the solve time and counts from lancer's
solution line, the whole process's time and peak memory (/usr/bin/time). Prints a Markdown
table for docs/BENCHMARKS.md.

    python3 bench/radiosity_scaling.py [--threads 2] [--lancer bin/lancer] [--python PY]
        [--sizes 1k,3k,10k,30k,bunny,100k,200k]

gen_mesh.py needs NumPy: --python names an interpreter that has it.
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORNELL = ROOT / "tests" / "cli" / "data" / "cornell" / "cornell.json"
KNOT = Path("/work/shared/bench/mesh-knot/gen_mesh.py")
BUNNY = Path("/work/shared/assets/stanford_bunny/stanford-bunny.obj")

# Knot sizes: (segments along the knot, segments around the tube); 2 triangles per quad.
KNOTS = {"1k": (20, 25), "3k": (60, 25), "10k": (100, 50), "30k": (300, 50),
         "100k": (400, 125), "200k": (800, 125)}


def bounds(obj: Path) -> tuple[list[float], list[float]]:
    low, high = [float("inf")] * 3, [float("-inf")] * 3
    with obj.open() as f:
        for line in f:
            if line.startswith("v "):
                p = [float(x) for x in line.split()[1:4]]
                low = [min(a, b) for a, b in zip(low, p)]
                high = [max(a, b) for a, b in zip(high, p)]
    return low, high


def model_scene(obj: Path) -> dict:
    """The Cornell box's walls and lamp with the model standing on its floor, 1.2 across."""
    text = CORNELL.read_text()
    scene = json.loads("\n".join(l for l in text.splitlines() if not l.lstrip().startswith("//")))
    scene["objects"] = scene["objects"][:12]  # the walls and the lamp, not the blocks
    low, high = bounds(obj)
    scale = 1.2 / max(h - l for l, h in zip(low, high))
    translate = [-scale * 0.5 * (low[0] + high[0]), -1 - scale * low[1],
                 -scale * 0.5 * (low[2] + high[2])]
    scene["objects"].append({"type": "mesh", "file": str(obj), "material": "white",
                             "transform": {"scale": scale, "translate": translate}})
    scene["render"].update({"integrator": "radiosity", "spp": 1, "width": 64, "height": 64})
    scene["radiosity"] = {"method": "hierarchical", "clusters": True}
    return scene


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--lancer", type=Path, default=ROOT / "bin" / "lancer")
    parser.add_argument("--python", default="python3", help="an interpreter with NumPy")
    parser.add_argument("--sizes", default="1k,3k,10k,30k,bunny,100k,200k")
    args = parser.parse_args()
    print("| model | triangles | solution | solve | whole process | peak memory |")
    print("| --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory(prefix="lancer-radiosity-scaling.") as workdir:
        work = Path(workdir)
        for size in args.sizes.split(","):
            if size == "bunny":
                obj, label, triangles = BUNNY, "Stanford bunny", 69451
            else:
                nseg, nring = KNOTS[size]
                folder = work / f"knot-{size}"
                subprocess.run([args.python, str(KNOT), "--outdir", str(folder), "--nseg",
                                str(nseg), "--nring", str(nring)], check=True,
                               capture_output=True)
                obj, label, triangles = folder / "knot.obj", "torus knot", 2 * nseg * nring
            path = work / "scene.json"
            path.write_text(json.dumps(model_scene(obj)))
            start = time.perf_counter()
            run = subprocess.run(["/usr/bin/time", "-f", "peak %M KB", str(args.lancer), str(path),
                                  "-o", str(work / "out.png"), "--threads", str(args.threads)],
                                 capture_output=True, text=True, check=True)
            seconds = time.perf_counter() - start
            line = re.findall(r"radiosity: (.*)", run.stderr)[-1]
            solve = re.search(r"solved in ([0-9.]+) s", line).group(1)
            counts = re.match(r"(.*?), \d+ shots", line).group(1)
            peak = int(re.search(r"peak (\d+) KB", run.stderr).group(1)) / 1024
            print(f"| {label} | {triangles:,} | {counts} | {solve} s | {seconds:.2f} s | "
                  f"{peak:.0f} MB |", flush=True)


if __name__ == "__main__":
    main()
