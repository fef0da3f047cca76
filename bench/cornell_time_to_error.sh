#!/usr/bin/env bash
# Time-to-error curves on the Cornell box: lancer's path and radiosity integrators and Mitsuba 3
# (scalar_rgb, llvm_ad_rgb) against Mitsuba's 16384-spp reference, on 2 threads. Installs
# Mitsuba in build/mitsuba-venv (bench/setup-mitsuba.sh), brings bin/lancer up to date with the
# release preset (unless --lancer names another build), then runs bench/cornell_time_to_error.py
# with the given options (see its --help), which writes docs/bench/cornell-time-to-error.{csv,png}
# and prints a Markdown report. Exit status: the Python script's (1: the convergence check of
# lancer's path tracer failed).
#
#   bench/cornell_time_to_error.sh [--path-spp 4,16,...] [--mitsuba-spp ...] [--max-wait S] ...
set -euo pipefail
cd "$(dirname "$0")/.."

venv=build/mitsuba-venv
bench/setup-mitsuba.sh "$venv" >&2
# Bring bin/lancer up to date, unless the options name another lancer program.
if [[ " $* " != *" --lancer "* ]]; then
    { cmake --preset release > /dev/null && cmake --build --preset release --target lancer; } >&2
fi
DRJIT_LIBLLVM_PATH=$(dpkg -L libllvm19 | grep -m1 '/libLLVM-19\.so$')
export DRJIT_LIBLLVM_PATH
export PYTHONDONTWRITEBYTECODE=1  # no __pycache__ in bench/ from importing image_error.py
exec "$venv/bin/python" bench/cornell_time_to_error.py "$@"
