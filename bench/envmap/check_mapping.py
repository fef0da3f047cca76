#!/usr/bin/env python3
"""Checks mitsuba_scene.py's translation of the environment map: lancer and Mitsuba 3 render a
mirror (smooth silver) sphere under a small map of distinct texels (a gradient, with bright red and
green texels at different places), turned by `rotate` 30, seen with the map around it, 96 x 64;
the relative RMSE between the two must be below --tolerance. The same comparison with the
translation's two corrections undone in turn (no half turn about +y; the map given as it is, rows
not resampled) is printed too, to show that the check can fail.

    bench/setup-mitsuba.sh; cmake --build ... (bin/lancer)
    DRJIT_LIBLLVM_PATH=$(dpkg -L libllvm19 | grep -m1 '/libLLVM-19\\.so$') \\
        build/mitsuba-venv/bin/python bench/envmap/check_mapping.py [--lancer bin/lancer]
"""

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import mitsuba as mi
import numpy as np

import mitsuba_scene  # beside this script

mi.set_variant("scalar_rgb")
HERE = Path(__file__).resolve().parent
WIDTH, HEIGHT = 16, 8  # texels: one texel is 22.5 degrees, so a misplaced one cannot hide
ROTATE = 30
LANCER_SPP, MITSUBA_SPP = 256, 1024


def test_map() -> np.ndarray:
    texels = np.zeros((HEIGHT, WIDTH, 3), dtype=np.float32)
    texels[..., 0] = (np.arange(WIDTH) / WIDTH)[None, :]
    texels[..., 1] = (np.arange(HEIGHT) / HEIGHT)[:, None]
    texels[..., 2] = 0.2
    texels[2, 3] = [8, 0, 0]
    texels[5, 12] = [0, 8, 0]
    return texels


def relative_rmse(image, reference) -> float:
    return float(np.sqrt(np.mean((image - reference) ** 2)) / np.mean(reference))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--lancer", type=Path, default=HERE.parent.parent / "bin" / "lancer")
    # Measured 0.0034 (the pixels' sampling noise at the texels' edges): 0.01 leaves room for
    # other seeds and is still 14 times below the smaller convention error (0.138, the rows).
    parser.add_argument("--tolerance", type=float, default=0.01)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="lancer-envmap-check.") as workdir:
        work = Path(workdir)
        mi.Bitmap(test_map()).write(str(work / "map.exr"))
        scene = {
            "render": {"width": 96, "height": 64, "spp": LANCER_SPP, "max_depth": 4,
                       "integrator": "path"},
            "camera": {"position": [0, 0.8, 3], "look_at": [0, 0, 0], "up": [0, 1, 0],
                       "vfov": 60},
            "environment": {"file": "map.exr", "intensity": 1, "rotate": ROTATE},
            "materials": {"mirror": {"metal": "silver"}},
            "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                         "material": "mirror"}],
        }
        (work / "check.json").write_text(json.dumps(scene))
        subprocess.run([str(args.lancer), str(work / "check.json"), "-o", str(work / "l.exr"),
                        "--threads", "2"], check=True, capture_output=True)
        lancer = np.array(mi.Bitmap(str(work / "l.exr")), dtype=np.float32)

        T = mi.ScalarTransform4f
        translations = {}
        translations["mitsuba_scene.py"] = mitsuba_scene.mitsuba_dict(mi, work / "check.json")
        no_turn = mitsuba_scene.mitsuba_dict(mi, work / "check.json")
        no_turn["environment"]["to_world"] = T().rotate([0, 1, 0], ROTATE)
        translations["without the half turn"] = no_turn
        rows_as_given = mitsuba_scene.mitsuba_dict(mi, work / "check.json")
        rows_as_given["environment"]["bitmap"] = mi.Bitmap(test_map())
        translations["rows not resampled"] = rows_as_given
        errors = {}
        for name, description in translations.items():
            image = np.array(mi.render(mi.load_dict(description), spp=MITSUBA_SPP))
            errors[name] = relative_rmse(lancer, image)
            print(f"lancer {LANCER_SPP} spp against Mitsuba {MITSUBA_SPP} spp, {name}: "
                  f"relative RMSE {errors[name]:.4f}")
    passed = errors["mitsuba_scene.py"] < args.tolerance
    print(f"{'passed' if passed else 'FAILED'} (tolerance {args.tolerance})")
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
