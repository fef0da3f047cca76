#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages lancer needs to build, test and benchmark. Idempotent:
# packages already present are not fetched again.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config clang-format
    libfreeimage-dev libopenexr-dev libsdl2-dev libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev
    libcli11-dev libtbb-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    xvfb xauth libx11-dev libxtst-dev
    libopenmpi-dev openmpi-bin  # mpirun: optional for the build, its tests run when found
    povray libembree-dev hyperfine
    imagemagick  # scripts/render-gallery.sh: the animation's GIF
    clang libclang-rt-14-dev  # libFuzzer (scripts/fuzz.sh); the runtime is packaged apart on Debian 12
)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all packages are installed"
    exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
