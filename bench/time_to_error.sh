#!/usr/bin/env bash
# Runs a time-to-error benchmark script of bench/ (cornell_time_to_error.py,
# envmap_time_to_error.py) with the given options: installs Mitsuba in build/mitsuba-venv
# (bench/setup-mitsuba.sh), brings bin/lancer up to date with the release preset (unless --lancer
# names another build), and runs the script with that environment's Python. Exit status: the
# script's.
#
#   bench/time_to_error.sh SCRIPT.py [OPTIONS...]
set -euo pipefail
cd "$(dirname "$0")/.."
script=$1
shift

venv=build/mitsuba-venv
bench/setup-mitsuba.sh "$venv" >&2
# Bring bin/lancer up to date, unless the options name another lancer program.
if [[ " $* " != *" --lancer "* ]]; then
    { cmake --preset release > /dev/null && cmake --build --preset release --target lancer; } >&2
fi
DRJIT_LIBLLVM_PATH=$(dpkg -L libllvm19 | grep -m1 '/libLLVM-19\.so$')
export DRJIT_LIBLLVM_PATH
export PYTHONDONTWRITEBYTECODE=1  # no __pycache__ in bench/ from importing the shared module
exec "$venv/bin/python" "bench/$script" "$@"
