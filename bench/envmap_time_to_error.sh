#!/usr/bin/env bash
# Time-to-error curves under an environment map: rough metal spheres lit by the project's sky
# (bench/envmap/rough-metals.json), lancer's path tracer and Mitsuba 3 (llvm_ad_rgb) against
# Mitsuba's 16384-spp reference (bench/envmap/mitsuba-16384spp.exr), on 2 threads. Installs
# Mitsuba and brings bin/lancer up to date (bench/time_to_error.sh), then runs
# bench/envmap_time_to_error.py with the given options (see its --help), which writes
# docs/bench/envmap-time-to-error.{csv,png} and prints a Markdown report. Exit status: the Python
# script's (1: lancer did not converge to the reference).
#
#   bench/envmap_time_to_error.sh [--path-spp 4,16,...] [--mitsuba-spp ...] [--variants ...] ...
exec "$(dirname "$0")/time_to_error.sh" envmap_time_to_error.py "$@"
