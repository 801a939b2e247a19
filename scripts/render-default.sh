#!/usr/bin/env bash
# Sets up and builds vkphoton if needed, then renders the default scene to out/cornell-box.exr/.png.
# Extra arguments are passed to `vkphoton render` (e.g. --spp 256).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec build/vkphoton render scenes/cornell-box.gltf -o out/cornell-box.exr "$@"
