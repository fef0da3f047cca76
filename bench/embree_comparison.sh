#!/usr/bin/env bash
# lancer's BVH vs Intel Embree 3 on the same meshes and rays: builds bench/embree_comparison.cpp
# with the bench preset (into bin/) and runs it. Prints a Markdown report on stdout: the machine,
# the command, then build times, bytes per triangle and single-ray Mrays/s (primary, diffuse
# bounce, shadow; 1 and 2 threads) of lancer, Embree high-quality and Embree medium-quality
# builds, with the ratios lancer / Embree. Progress goes to stderr.
#
# Usage: bench/embree_comparison.sh [--max-wait S] [embree_comparison options]
#   --max-wait S         wait up to S seconds (default 120) for an idle CPU before starting
#   --only NAME          only the meshes whose name contains NAME (e.g. sphere_1M)
#   --min-time SECONDS   tracing time per tracer, ray kind and thread count (default 1)
#   --assets DIR         the shared models (default: ../shared/assets beside the repository)
#
# Needs Embree 3 (Debian: apt-get install libembree-dev) and Google Benchmark (libbenchmark-dev),
# which the bench preset builds against. Exit status: 0 on success, 1 on failure.
set -euo pipefail

max_wait=120
args=()
while (($#)); do
    case $1 in
        --max-wait) max_wait=${2:?--max-wait needs a number of seconds}; shift 2 ;;
        -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) args+=("$1"); shift ;;
    esac
done

fail() { echo "embree_comparison.sh: error: $*" >&2; exit 1; }

[[ $max_wait =~ ^[0-9]+$ ]] || fail "--max-wait must be a number of seconds"

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

echo "building the bench preset" >&2
{ cmake --preset bench && cmake --build --preset bench --target embree_comparison; } >&2 ||
    fail "the bench build failed"
[[ -x bin/embree_comparison ]] || fail "the bench build did not produce bin/embree_comparison"

# Builds are timed on the wall clock (traversal on the tracing threads' CPU time): start when the
# CPUs have been idle for half a second, or after --max-wait seconds.
cpu_busy_percent() {
    local _ u n s idle iow irq sirq steal t1 i1 t2 i2
    read -r _ u n s idle iow irq sirq steal _ </proc/stat
    t1=$((u + n + s + idle + iow + irq + sirq + steal)) i1=$((idle + iow))
    sleep 0.5
    read -r _ u n s idle iow irq sirq steal _ </proc/stat
    t2=$((u + n + s + idle + iow + irq + sirq + steal)) i2=$((idle + iow))
    echo $((100 * ((t2 - t1) - (i2 - i1)) / (t2 - t1 > 0 ? t2 - t1 : 1)))
}
deadline=$((SECONDS + max_wait))
while (($(cpu_busy_percent) > 10)) && ((SECONDS < deadline)); do sleep 2; done

memory_gib=$(awk '/MemTotal/ { printf "%.1f", $2 / 1024 / 1024 }' /proc/meminfo)
echo "## lancer vs Embree 3"
echo
echo "- Machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores," \
    "${memory_gib} GiB of memory"
echo "- Embree: $(dpkg-query -W -f '${Version}' libembree-dev 2>/dev/null || echo unknown)," \
    "lancer: $(git describe --always --dirty 2>/dev/null || echo "not a git checkout")"
echo "- Date: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "- Command: bench/embree_comparison.sh ${args[*]}"
bin/embree_comparison "${args[@]}"
