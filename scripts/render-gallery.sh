#!/usr/bin/env bash
# Renders every scene of scenes/ into docs/gallery/NAME.png with the release build (or with the
# lancer program named by $LANCER).
#
# A scene NAME.json with a NAME-whitted.json beside it (the Cornell boxes) is a global-illumination
# scene lit by its emissive surfaces, and NAME-whitted.json the same scene with lights standing in
# for them: the pair is rendered three ways, side by side, as NAME-whitted.png, NAME-path.png and
# NAME-radiosity.png.
set -euo pipefail
cd "$(dirname "$0")/.."
lancer=${LANCER:-bin/lancer}
[ -x "$lancer" ] || { cmake --preset release > /dev/null && cmake --build --preset release; }
mkdir -p docs/gallery
# Radiosity traces camera rays only for anti-aliasing and the specular parts: fewer than the
# path tracer's samples per pixel (the scene's) suffice.
radiosity_spp=16

render() { # scene output [options]
    echo "gallery: $2"
    "$lancer" "$1" -o "docs/gallery/$2.png" "${@:3}"
}

for scene in scenes/*.json; do
    name=$(basename "$scene" .json)
    if [ -e "scenes/$name-whitted.json" ]; then
        render "scenes/$name-whitted.json" "$name-whitted"
        render "$scene" "$name-path" --integrator path
        render "$scene" "$name-radiosity" --integrator radiosity --spp "$radiosity_spp"
    elif [[ $name != *-whitted || ! -e "scenes/${name%-whitted}.json" ]]; then
        render "$scene" "$name"
    fi
done
