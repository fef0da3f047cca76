#!/usr/bin/env bash
# Cluster rendering (docs/CLUSTER.md): whole-process time of the Whitted scene with 1 process of
# 1 thread, 2 processes of 1 thread (the aim: at least 1.9x on 2 cores), and 1 process of 2
# threads, measured by hyperfine in one run; and the tile protocol's overhead: 2 processes on a
# render of many cheap tiles (1 spp) against 1 process of 2 threads.
# Usage: bench/cluster_scaling.sh [runs]   (from the source tree, after a release build)
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-5}"
lancer="$PWD/bin/lancer"
scene="$PWD/scenes/whitted.json"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
lscpu | grep -E "Model name" | sed 's/^/# /'
echo "# SIMD: $(grep -o -E 'avx512[a-z]*|avx2' /proc/cpuinfo | sort -u | tr '\n' ' ')"
echo "# load: $(cut -d' ' -f1-3 /proc/loadavg)"
render=(--width 640 --height 480 --spp 16 --quiet)
hyperfine --runs "$runs" --warmup 1 --export-markdown "$out/render.md" \
    -n "1 process x 1 thread" "$lancer $scene -o $out/a.pfm --threads 1 ${render[*]}" \
    -n "2 processes x 1 thread" "mpirun --oversubscribe -np 2 $lancer $scene -o $out/b.pfm --threads 1 ${render[*]}" \
    -n "1 process x 2 threads" "$lancer $scene -o $out/c.pfm --threads 2 ${render[*]}"
cmp "$out/a.pfm" "$out/b.pfm" && cmp "$out/a.pfm" "$out/c.pfm" && echo "# the three images are byte-identical"
cat "$out/render.md"
cheap=(--width 1280 --height 960 --spp 1 --quiet)
hyperfine --runs "$runs" --warmup 1 --export-markdown "$out/cheap.md" \
    -n "1 process x 2 threads, 4800 tiles at 1 spp" "$lancer $scene -o $out/d.pfm --threads 2 ${cheap[*]}" \
    -n "2 processes x 1 thread, 4800 tiles at 1 spp" "mpirun --oversubscribe -np 2 $lancer $scene -o $out/e.pfm --threads 1 ${cheap[*]}" \
    -n "mpirun start-up (2 x lancer --version)" "mpirun --oversubscribe -np 2 $lancer --version"
cat "$out/cheap.md"
