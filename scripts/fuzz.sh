#!/usr/bin/env bash
# Builds the libFuzzer targets (the `fuzz` preset: clang, ASan + UBSan) and runs each for the
# given number of seconds (default 60), one after the other, starting from the seed corpus in
# tests/fuzz/corpus. New inputs go to build/fuzz/corpus/TARGET (the seeds are left as they are);
# a crash, a leak, a timeout or an input needing more memory than allowed stops that target and
# leaves the input as build/fuzz/findings/TARGET-crash-... (an input taking over 10 s is kept as
# TARGET-slow-unit-... and the target goes on); any of them makes the script exit 1 once every
# target has run. Usage: scripts/fuzz.sh [seconds] [target...]; targets: scene obj gltf ply
# image radiosity resume models.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene obj gltf ply image radiosity resume models)

cmake --preset fuzz > /dev/null
cmake --build --preset fuzz --target "${targets[@]/#/fuzz_}"

mkdir -p build/fuzz/findings
failed=()
for target in "${targets[@]}"; do
    corpus="build/fuzz/corpus/$target"
    mkdir -p "$corpus"
    echo "fuzz: $target for $seconds s"
    # -rss_limit_mb: the largest accepted texture (2^28 pixels) takes 3 GiB as a float image,
    # so the image target gets more; a single input is a hang after 30 s.
    rss=2048
    [ "$target" = image ] && rss=6144
    if ! "build/fuzz/bin/fuzz_$target" "$corpus" "tests/fuzz/corpus/$target" \
        -max_total_time="$seconds" -timeout=30 -rss_limit_mb="$rss" -print_final_stats=1 \
        -report_slow_units=10 -artifact_prefix="build/fuzz/findings/$target-" \
        2> "build/fuzz/$target.log"; then
        failed+=("$target")
    elif compgen -G "build/fuzz/findings/$target-slow-unit-*" > /dev/null; then
        failed+=("$target")  # an input that took over 10 s: libFuzzer reports it, but goes on
    fi
    grep -E "^stat::|^#[0-9]+ +DONE|^Done" "build/fuzz/$target.log" || true
done
if [ ${#failed[@]} -gt 0 ]; then
    echo "fuzz: findings in ${failed[*]}: see build/fuzz/TARGET.log and build/fuzz/findings" >&2
    exit 1
fi
echo "fuzz: no findings"
