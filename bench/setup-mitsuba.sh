#!/usr/bin/env bash
# Installs what bench/cornell_time_to_error.py needs, outside the build: Mitsuba 3 (pinned to the
# version that rendered ../shared/references/cornell), NumPy and Matplotlib in a virtual
# environment, and Debian's LLVM 19 for Mitsuba's llvm_ad_rgb variant (Dr.Jit loads libLLVM at
# run time; older LLVMs crash it). Idempotent: it does nothing that is already done.
#
#   bench/setup-mitsuba.sh [VENV]      (default VENV: build/mitsuba-venv)
#
# Afterwards it prints the two variables the benchmark script needs (it also finds them itself).
set -euo pipefail
cd "$(dirname "$0")/.."
venv=${1:-build/mitsuba-venv}
mitsuba_version=3.9.1

llvm_lib() { dpkg -L libllvm19 2> /dev/null | grep -m1 '/libLLVM-19\.so$' || true; }
if [ -z "$(llvm_lib)" ]; then
    sudo_cmd=""
    [ "$(id -u)" -eq 0 ] || sudo_cmd=sudo
    $sudo_cmd apt-get update -qq
    $sudo_cmd apt-get install -y -qq libllvm19 > /dev/null
fi
llvm_lib=$(llvm_lib)

if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
if ! "$venv/bin/python" -c "import mitsuba, numpy, matplotlib" 2> /dev/null; then
    "$venv/bin/pip" install --quiet --upgrade pip
    "$venv/bin/pip" install --quiet "mitsuba==$mitsuba_version" numpy matplotlib
fi

# Both variants must render the Cornell box: a 16x16, 4 spp check.
DRJIT_LIBLLVM_PATH=$llvm_lib "$venv/bin/python" - << 'EOF'
import mitsuba as mi
for variant in ("scalar_rgb", "llvm_ad_rgb"):
    mi.set_variant(variant)
    scene = mi.cornell_box()
    scene["sensor"]["film"]["width"] = scene["sensor"]["film"]["height"] = 16
    image = mi.render(mi.load_dict(scene), spp=4)
    print(f"setup-mitsuba: {variant} renders (mean {float(mi.TensorXf(image).numpy().mean()):.3f})")
EOF

echo "setup-mitsuba: ready: PYTHON=$venv/bin/python DRJIT_LIBLLVM_PATH=$llvm_lib"
