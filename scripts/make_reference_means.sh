#!/usr/bin/env bash
# Renders each shipped scene at 64x64 with many samples and writes the mean radiance per channel
# to tests/data/reference_means.json: the reference values of tests/render/shipped_scenes_render_test.cpp.
# Usage: bash scripts/make_reference_means.sh [SPP]   (after a build)
set -euo pipefail
cd "$(dirname "$0")/.."
spp="${1:-8192}"
mkdir -p out/reference
for scene in cornell-box cornell-ceiling cornell-glass; do
  build/vkphoton render "scenes/$scene.gltf" --quiet --width 64 --height 64 --spp "$spp" --seed 1000 \
    -o "out/reference/$scene.exr" --stats-json "out/reference/$scene.json"
done
python3 - "$spp" <<'PY'
import json, sys
spp = int(sys.argv[1])
out = {"_comment": f"mean radiance of 64x64 renders at {spp} spp, seed 1000, max depth 16: bash scripts/make_reference_means.sh {spp}"}
for scene in ["cornell-box", "cornell-ceiling", "cornell-glass"]:
    with open(f"out/reference/{scene}.json") as f:
        out[scene] = json.load(f)["meanRadiance"]
with open("tests/data/reference_means.json", "w") as f:
    json.dump(out, f, indent=2)
    f.write("\n")
PY
cat tests/data/reference_means.json
