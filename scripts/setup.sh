#!/usr/bin/env bash
# Installs what vkphoton needs on Debian 12 (only the packages that are missing), then configures
# and builds it in build/. Safe to run again: a second run only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config python3
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-tools glslang-dev spirv-tools libspirv-cross-c-shared-dev
  libglm-dev libtinygltf-dev libopenexr-dev libstb-dev libcli11-dev libfmt-dev nlohmann-json3-dev
  libgtest-dev
  libdraco-dev libmeshoptimizer-dev  # compressed glTF geometry (KHR_draco_mesh_compression, EXT_meshopt_compression)
  libwebp-dev  # WebP textures (EXT_texture_webp)
  libembree-dev  # bench/embree_bench: the CPU reference for ray rates (docs/benchmarks.md)
  clang-14 libclang-rt-14-dev  # the glTF loader fuzzer (fuzz/): libFuzzer, ASan, UBSan
  libglfw3-dev xvfb xauth  # `vkphoton view`'s window (GLFW), and the X server its tests run it under (xvfb-run)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

jobs="${VKPHOTON_JOBS:-2}"
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build build -j "$jobs"
# The fuzzer is a separate project (clang); the GltfLoaderFuzz test runs it.
cmake --build build -j "$jobs" --target gltf_fuzz
