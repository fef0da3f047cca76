#!/usr/bin/env bash
# Renders every scene of scenes/ into docs/gallery/NAME.png with the release build.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x bin/lancer ] || { cmake --preset release > /dev/null && cmake --build --preset release; }
mkdir -p docs/gallery
for scene in scenes/*.json; do
    name=$(basename "$scene" .json)
    echo "gallery: $name"
    bin/lancer "$scene" -o "docs/gallery/$name.png"
done
