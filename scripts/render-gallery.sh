#!/usr/bin/env bash
# Renders every scene of scenes/ into docs/gallery/NAME.png with the release build (or with the
# lancer program named by $LANCER).
#
# A scene NAME.json with a NAME-whitted.json beside it (the Cornell boxes) is a global-illumination
# scene lit by its emissive surfaces, and NAME-whitted.json the same scene with lights standing in
# for them: the pair is rendered three ways, side by side, as NAME-whitted.png, NAME-path.png and
# NAME-radiosity.png.
#
# An animated scene (one with an "animation" block) is rendered frame by frame into a temporary
# folder and its frames assembled as docs/gallery/NAME.gif by ImageMagick's convert (Debian's
# imagemagick package: the gallery needs it, the build and the tests do not).
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

animate() { # scene output: the frames, played at the scene's "fps"
    command -v convert > /dev/null || {
        echo "gallery: $2.gif needs ImageMagick: apt-get install imagemagick" >&2
        exit 1
    }
    echo "gallery: $2.gif"
    local frames fps
    frames=$(mktemp -d)
    "$lancer" "$1" -o "$frames/frame.png" --quiet
    fps=$(sed -n 's/.*"fps": *\([0-9.]*\).*/\1/p' "$1" | head -1)
    convert -delay "$(awk "BEGIN { print int(100 / ${fps:-24} + 0.5) }")" -loop 0 \
        "$frames"/frame-*.png -layers Optimize "docs/gallery/$2.gif"
    rm -r "$frames"
}

for scene in scenes/*.json; do
    name=$(basename "$scene" .json)
    if grep -q '"animation"' "$scene"; then
        animate "$scene" "$name"
    elif [ -e "scenes/$name-whitted.json" ]; then
        render "scenes/$name-whitted.json" "$name-whitted"
        render "$scene" "$name-path" --integrator path
        render "$scene" "$name-radiosity" --integrator radiosity --spp "$radiosity_spp"
    elif [[ $name != *-whitted || ! -e "scenes/${name%-whitted}.json" ]]; then
        render "$scene" "$name"
    fi
done
