#!/usr/bin/env python3
"""Renders the Mitsuba 3 references of the rough-material tests (tests/cli/RoughMaterialTest.cpp):
a rough gold sphere (roughconductor, ggx, alpha 0.3, Mitsuba's own "Au" data, which
metal_table.py shows is lancer's "gold") and a rough glass sphere (roughdielectric, ggx, alpha
0.2, int_ior 1.5) under a constant environment of radiance 1, seen as rough-gold.json and
rough-glass.json describe: 64 x 64, box filter, independent sampler, path tracer with max_depth
17 (Mitsuba counts the camera ray's segment: lancer's 16). The scenes are symmetric about the view
axis, so Mitsuba's and lancer's image orientation need not be compared.

    bench/setup-mitsuba.sh && build/mitsuba-venv/bin/python tests/cli/data/rough/make_references.py
"""
import os
import sys

import mitsuba as mi

mi.set_variant("scalar_rgb")
SPP = int(sys.argv[1]) if len(sys.argv) > 1 else 8192
HERE = os.path.dirname(os.path.abspath(__file__))

MATERIALS = {
    "gold": {"type": "roughconductor", "distribution": "ggx", "alpha": 0.3, "material": "Au"},
    "glass": {"type": "roughdielectric", "distribution": "ggx", "alpha": 0.2,
              "int_ior": 1.5, "ext_ior": 1.0},
}

for name, bsdf in MATERIALS.items():
    scene = mi.load_dict({
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 17},
        "sensor": {
            "type": "perspective", "fov": 32, "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=[0, 0, 4], target=[0, 0, 0],
                                                       up=[0, 1, 0]),
            "sampler": {"type": "independent", "sample_count": SPP},
            "film": {"type": "hdrfilm", "width": 64, "height": 64, "rfilter": {"type": "box"},
                     "pixel_format": "rgb", "component_format": "float32"},
        },
        "environment": {"type": "constant", "radiance": {"type": "rgb", "value": 1.0}},
        "sphere": {"type": "sphere", "center": [0, 0, 0], "radius": 1, "bsdf": bsdf},
    })
    image = mi.render(scene, spp=SPP)
    path = os.path.join(HERE, f"mitsuba-rough-{name}-{SPP}spp.exr")
    mi.Bitmap(image).write(path)
    print("wrote", path)
