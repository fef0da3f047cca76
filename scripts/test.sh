#!/usr/bin/env bash
# Builds lancer and runs every test. `scripts/test.sh` uses the release preset;
# `scripts/test.sh asan` builds and runs the same tests under AddressSanitizer + UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
cmake --preset "$preset" > /dev/null
cmake --build --preset "$preset"
ctest --preset "$preset" -j "$(nproc)"
