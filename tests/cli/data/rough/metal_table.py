#!/usr/bin/env python3
"""Prints the RGB complex indices of refraction (eta, k) of lancer's named metals, as Mitsuba 3
(scalar_rgb) makes them from its measured spectral data (resources/data/ior/{Au,Ag,Cu,Al,Cr}.*.spd,
after Palik's handbook): Mitsuba integrates each spectrum against the CIE 1931 matching functions
and converts it to linear sRGB (spectrum_from_file, spectrum_list_to_srgb). These are the values of
the table in src/materials/BlinnPhongMaterial.cpp and docs/SCENE-FORMAT.md.

    build/mitsuba-venv/bin/python tests/cli/data/rough/metal_table.py   (bench/setup-mitsuba.sh)
"""
import mitsuba as mi

mi.set_variant("scalar_rgb")
print("mitsuba", mi.__version__)
for lancer_name, mitsuba_name in [("gold", "Au"), ("silver", "Ag"), ("copper", "Cu"),
                                  ("aluminium", "Al"), ("chromium", "Cr")]:
    params = mi.traverse(mi.load_dict({"type": "conductor", "material": mitsuba_name}))
    eta, k = params["eta.value"], params["k.value"]
    print(f"{lancer_name:10s} eta {eta[0]:.4f} {eta[1]:.4f} {eta[2]:.4f}   k {k[0]:.4f} {k[1]:.4f} {k[2]:.4f}")
