#!/usr/bin/env bash
# Cluster rendering (docs/CLUSTER.md), measured by hyperfine in one run:
# - whole-process time of the Whitted scene with 1 process of 1 thread, 2 processes of 1 thread
#   (the aim: at least 1.9x on 2 cores) and 1 process of 2 threads, at 640 x 480 and 1280 x 960
#   (16 spp), where mpirun's start-up weighs less, or at the sizes given (WIDTHxHEIGHT);
# - the same 2 processes with `--mca pml ob1`: Open MPI's default first tries its cm PML, whose
#   probes of libfabric, PSM and PSM2 (Omni-Path and TrueScale adapters) take about 0.2 s of each
#   run on a machine without them (docs/CLUSTER.md);
# - mpirun's start-up (2 x lancer --version), by default and with `--mca pml ob1`;
# - the tile protocol's rate: a scene of nothing (each tile a few tens of microseconds) at
#   4096 x 4096, 1 spp (65,536 tiles), in 1 process of 1 and 2 threads and in 2 processes of 1.
# Usage: bench/cluster_scaling.sh [runs] [WIDTHxHEIGHT...]   (from the source tree, after a
# release build)
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-3}"
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(640x480 1280x960)
lancer="$PWD/bin/lancer"
scene="$PWD/scenes/whitted.json"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
lscpu | grep -E "Model name" | sed 's/^/# /'
echo "# SIMD: $(grep -o -E 'avx512[a-z]*|avx2' /proc/cpuinfo | sort -u | tr '\n' ' ')"
echo "# load: $(cut -d' ' -f1-3 /proc/loadavg)"
for size in "${sizes[@]}"; do
    set -- ${size/x/ }
    render=(--width "$1" --height "$2" --spp 16 --quiet)
    hyperfine --runs "$runs" --warmup 1 --export-markdown "$out/render.md" \
        -n "$1 x $2: 1 process x 1 thread" "$lancer $scene -o $out/a.pfm --threads 1 ${render[*]}" \
        -n "$1 x $2: 2 processes x 1 thread" "mpirun --oversubscribe -np 2 $lancer $scene -o $out/b.pfm --threads 1 ${render[*]}" \
        -n "$1 x $2: 2 processes x 1 thread, --mca pml ob1" "mpirun --oversubscribe --mca pml ob1 -np 2 $lancer $scene -o $out/f.pfm --threads 1 ${render[*]}" \
        -n "$1 x $2: 1 process x 2 threads" "$lancer $scene -o $out/c.pfm --threads 2 ${render[*]}"
    cmp "$out/a.pfm" "$out/b.pfm" && cmp "$out/a.pfm" "$out/c.pfm" && cmp "$out/a.pfm" "$out/f.pfm" &&
        echo "# the four images are byte-identical"
    cat "$out/render.md"
done
echo '{"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "background": 0.5}' > "$out/nothing.json"
cheap=(--width 4096 --height 4096 --spp 1)
for run in "1 process x 1 thread:$lancer $out/nothing.json -o $out/d.pfm --threads 1" \
           "1 process x 2 threads:$lancer $out/nothing.json -o $out/d.pfm --threads 2" \
           "2 processes x 1 thread:mpirun --oversubscribe -np 2 $lancer $out/nothing.json -o $out/e.pfm --threads 1"; do
    for _ in $(seq "$runs"); do
        echo "# 65,536 tiles of nothing, ${run%%:*}: $(${run#*:} "${cheap[@]}" 2>&1 | tail -1 | grep -o '[0-9.]* s,' | head -1) (render)"
    done
done
cmp "$out/d.pfm" "$out/e.pfm" && echo "# byte-identical"
hyperfine --runs "$runs" --warmup 1 -n "mpirun start-up (2 x lancer --version)" \
    "mpirun --oversubscribe -np 2 $lancer --version" \
    -n "mpirun start-up, --mca pml ob1" "mpirun --oversubscribe --mca pml ob1 -np 2 $lancer --version" |
    grep -E "Benchmark|Time|Range"
