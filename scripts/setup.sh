#!/usr/bin/env bash
# Installs the Debian packages watergraph builds and tests with (the list in
# ../shared/TOOLCHAIN.md), skipping what is already installed. Idempotent and quiet
# when nothing is missing, so `make demo` and `make test` can call it every time.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang libclang-rt-14-dev
  libegl-dev libgl-dev libgles-dev libglvnd-dev libegl1-mesa-dev libegl-mesa0 libgl1-mesa-dri
  libepoxy-dev glslang-dev glslang-tools spirv-tools spirv-cross libspirv-cross-c-shared-dev
  libglfw3-dev libimgui-dev libstb-dev libcli11-dev libglm-dev nlohmann-json3-dev
  libgtest-dev libbenchmark-dev xvfb xauth
  libfftw3-dev  # the spectral ocean's double-precision reference transform (core/ocean_fft_reference.cpp)
  python3-jsonschema  # tests/ecosystem: a real JSON Schema validator for docs/watergraph.schema.json
  chromium  # tests/ecosystem: renders clients/three/ (three.js, WebGL 2) headless for the comparison
  gnuplot-nox  # watergraph bench --plot: the cost-against-error plot
  # The Vulkan runtime (render --target vk450): the loader and headers, lavapipe
  # (Vulkan 1.3 on llvmpipe, headless), and the Khronos validation layer its tests run under
  # (a missing layer fails those tests; they never skip).
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: not root and no sudo; install: ${missing[*]}" >&2; exit 2; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
