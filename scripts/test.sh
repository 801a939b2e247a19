#!/usr/bin/env bash
# Sets up and builds vkphoton if needed, then runs the whole test suite on lavapipe with the
# Khronos validation layer on for every test. Extra arguments go to ctest: -L unit runs the fast
# tier (docs/testing.md), -L render and -L slow the others.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# Tests always run on the software rasteriser so results are the same on every machine.
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
exec ctest --test-dir build --output-on-failure -j 2 "$@"
