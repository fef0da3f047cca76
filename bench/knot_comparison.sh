#!/usr/bin/env bash
# The 1M-triangle knot (../shared/bench/mesh-knot: one OBJ, one directional light, 1920 x 1080 at
# 1 spp with a shadow ray per visible point), whole process as a user waits for it (load the OBJ,
# build, render, write), lancer against Mitsuba 3 llvm_ad_rgb (issue 14's aim: lancer at most 0.5x
# Mitsuba's time), measured by hyperfine in one run, the two renderers alternating; then lancer's
# own split of its time (--stats: the scene's load and build, the render), with its model cache
# and without it.
#
#   bench/knot_comparison.sh [--runs N] [--threads T] [--lancer PATH] [--venv DIR] [--dir DIR]
#
# --venv: bench/setup-mitsuba.sh's virtual environment (default build/mitsuba-venv); --dir: where
# knot.obj is made (by the shared gen_mesh.py, with the venv's NumPy) if it is not there yet
# (default /tmp/lancer-knot). Needs hyperfine (Debian).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=3
threads=2
lancer="$PWD/bin/lancer"
venv="$PWD/build/mitsuba-venv"
dir=/tmp/lancer-knot
while [ $# -gt 0 ]; do
    case "$1" in
        --runs) runs="$2"; shift 2 ;;
        --threads) threads="$2"; shift 2 ;;
        --lancer) lancer="$(realpath "$2")"; shift 2 ;;
        --venv) venv="$(realpath "$2")"; shift 2 ;;
        --dir) dir="$2"; shift 2 ;;
        *) echo "knot_comparison.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
shared="$(realpath ../shared/bench/mesh-knot)"
llvm="$(dpkg -L libllvm19 2> /dev/null | grep -m1 '/libLLVM-19\.so$' || true)"
[ -x "$venv/bin/python" ] && [ -n "$llvm" ] || { echo "run bench/setup-mitsuba.sh first" >&2; exit 1; }
mkdir -p "$dir"
cp "$shared/knot.json" "$shared/knot-mitsuba.xml" "$dir/"
[ -f "$dir/knot.obj" ] || "$venv/bin/python" "$shared/gen_mesh.py" --outdir "$dir" > /dev/null
cd "$dir"
cat > render_mitsuba.py << EOF
import drjit as dr, mitsuba as mi
mi.set_variant("llvm_ad_rgb")
dr.set_thread_count($threads)
mi.util.write_bitmap("knot-mitsuba.exr", mi.render(mi.load_file("knot-mitsuba.xml")))
EOF
export DRJIT_LIBLLVM_PATH="$llvm"

lscpu | grep -E "Model name" | sed 's/^/# /'
echo "# SIMD: $(grep -o -E 'avx512[a-z]*|avx2|fma' /proc/cpuinfo | sort -u | tr '\n' ' ')"
echo "# load before: $(cut -d' ' -f1-3 /proc/loadavg)"
# The warm-up also fills Dr.Jit's kernel cache and lancer's model cache (in this folder), as a
# user's second render finds them; lancer without its model cache reads and builds the model
# every time, as a first render does.
hyperfine --runs "$runs" --warmup 1 --export-markdown knot.md \
    -n "lancer, $threads threads" \
    "$lancer knot.json -o knot-lancer.png --threads $threads --quiet --model-cache model-cache" \
    -n "lancer --no-model-cache, $threads threads" \
    "$lancer knot.json -o knot-lancer.png --threads $threads --quiet --no-model-cache" \
    -n "Mitsuba 3 llvm_ad_rgb, $threads threads" "$venv/bin/python render_mitsuba.py"
cat knot.md
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# lancer's split (one run):"
for cache in "--model-cache model-cache" --no-model-cache; do
    echo "#  $cache:"
    "$lancer" knot.json -o knot-lancer.png --threads "$threads" --stats $cache 2>&1 |
        grep -E "loaded in|Mrays/s" | sed 's/^/#   /'
done
