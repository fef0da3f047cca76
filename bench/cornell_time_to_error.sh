#!/usr/bin/env bash
# Time-to-error curves on the Cornell box: lancer's path and radiosity integrators and Mitsuba 3
# (scalar_rgb, llvm_ad_rgb) against Mitsuba's 16384-spp reference, on 2 threads. Installs
# Mitsuba and brings bin/lancer up to date (bench/time_to_error.sh), then runs
# bench/cornell_time_to_error.py with the given options (see its --help), which writes
# docs/bench/cornell-time-to-error.{csv,png} and prints a Markdown report. Exit status: the Python
# script's (1: the convergence check of lancer's path tracer failed).
#
#   bench/cornell_time_to_error.sh [--path-spp 4,16,...] [--mitsuba-spp ...] [--max-wait S] ...
exec "$(dirname "$0")/time_to_error.sh" cornell_time_to_error.py "$@"
