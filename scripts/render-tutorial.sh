#!/usr/bin/env bash
# Renders every scene of scenes/tutorial into docs/tutorial/NAME.png (the pictures of
# docs/TUTORIAL.md) with the release build, or with the lancer program named by $LANCER.
set -euo pipefail
cd "$(dirname "$0")/.."
lancer=${LANCER:-bin/lancer}
[ -x "$lancer" ] || { cmake --preset release > /dev/null && cmake --build --preset release; }
mkdir -p docs/tutorial
for scene in scenes/tutorial/*.json; do
    name=$(basename "$scene" .json)
    echo "tutorial: $name"
    "$lancer" "$scene" -o "docs/tutorial/$name.png"
done
