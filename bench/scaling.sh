#!/usr/bin/env bash
# How lancer's costs grow (issue 14): the knot scene of ../shared/bench/mesh-knot (a torus-knot
# tube over a ground, one directional light, 1 spp, a shadow ray per visible point) made at 1k to
# 5M triangles, then the 1M knot at four image sizes and at four sample counts. For each run:
# the whole process, and lancer's own split of it (--stats): reading the files, building the
# BVHs, rendering. Prints Markdown tables.
#
#   bench/scaling.sh [--runs N] [--threads T] [--lancer PATH] [--dir DIR]
#
# Each figure is the median of N runs (default 3). --dir (default /tmp/lancer-scaling) holds the
# generated meshes (gen_mesh.py needs NumPy: bench/setup-mitsuba.sh's venv has it, or any python3
# with it, as $PYTHON).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=3
threads=2
lancer="$PWD/bin/lancer"
dir=/tmp/lancer-scaling
while [ $# -gt 0 ]; do
    case "$1" in
        --runs) runs="$2"; shift 2 ;;
        --threads) threads="$2"; shift 2 ;;
        --lancer) lancer="$(realpath "$2")"; shift 2 ;;
        --dir) dir="$2"; shift 2 ;;
        *) echo "scaling.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
python="${PYTHON:-$PWD/build/mitsuba-venv/bin/python}"
shared="$(realpath ../shared/bench/mesh-knot)"

# mesh NAME NSEG NRING: a knot of 2 x NSEG x NRING triangles in $dir/NAME, with the scene.
mesh() {
    mkdir -p "$dir/$1"
    cp "$shared/knot.json" "$dir/$1/"
    [ -f "$dir/$1/knot.obj" ] || "$python" "$shared/gen_mesh.py" --outdir "$dir/$1" --nseg "$2" \
        --nring "$3" > /dev/null
}

# measure FOLDER OPTIONS...: "whole read build render" in seconds, medians of $runs runs.
measure() {
    local folder="$1"
    shift
    for _ in $(seq "$runs"); do
        local start end stats
        start=$(date +%s.%N)
        stats=$(cd "$folder" && "$lancer" knot.json -o /dev/null.png --threads "$threads" \
            --stats "$@" 2>&1 >/dev/null | grep -E "loaded in|Mrays/s" || true)
        end=$(date +%s.%N)
        # "scene loaded in L s (B s of it building BVHs)" and "..., R s, N M rays, ..."
        local load build render
        load=$(sed -n 's/.*loaded in \([0-9.]*\) s (\([0-9.]*\) s.*/\1/p' <<< "$stats")
        build=$(sed -n 's/.*loaded in \([0-9.]*\) s (\([0-9.]*\) s.*/\2/p' <<< "$stats")
        render=$(sed -n 's/.*, \([0-9.]*\) s, [0-9.]* M rays.*/\1/p' <<< "$stats")
        echo "$start $end $load $build $render"
    done | python3 -c '
import statistics, sys
rows = [list(map(float, line.split())) for line in sys.stdin]
whole = statistics.median(r[1] - r[0] for r in rows)
load, build, render = (statistics.median(r[i] for r in rows) for i in (2, 3, 4))
print(f"{whole:.3f} {load - build:.3f} {build:.3f} {render:.3f}")'
}

row() {  # row LABEL FOLDER OPTIONS...
    local label="$1"
    shift
    read -r whole read_ build render <<< "$(measure "$@")"
    echo "| $label | $whole | $read_ | $build | $render |"
}

lscpu | grep -E "Model name" | sed 's/^/# /'
echo "# SIMD: $(grep -o -E 'avx512[a-z]*|avx2|fma' /proc/cpuinfo | sort -u | tr '\n' ' ')"
echo "# lancer: $("$lancer" --version | head -1); $threads threads; medians of $runs runs"
echo "# load before: $(cut -d' ' -f1-3 /proc/loadavg)"
mesh 1k 20 25
mesh 10k 200 25
mesh 100k 1000 50
mesh 1M 4000 125
mesh 5M 20000 125

echo
echo "Scene size (1920 x 1080, 1 spp):"
echo
echo "| triangles | whole process [s] | reading [s] | building BVHs [s] | render [s] |"
echo "| ---: | ---: | ---: | ---: | ---: |"
for size in 1k 10k 100k 1M 5M; do
    row "$size" "$dir/$size"
done

echo
echo "Image size (1M triangles, 1 spp):"
echo
echo "| image | whole process [s] | reading [s] | building BVHs [s] | render [s] |"
echo "| ---: | ---: | ---: | ---: | ---: |"
for size in "480 270" "960 540" "1920 1080" "3840 2160"; do
    set -- $size
    row "$1 x $2" "$dir/1M" --width "$1" --height "$2"
done

echo
echo "Samples per pixel (1M triangles, 1920 x 1080):"
echo
echo "| spp | whole process [s] | reading [s] | building BVHs [s] | render [s] |"
echo "| ---: | ---: | ---: | ---: | ---: |"
for spp in 1 4 16 64; do
    row "$spp" "$dir/1M" --spp "$spp"
done
echo
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
