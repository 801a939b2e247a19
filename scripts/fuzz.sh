#!/usr/bin/env bash
# Runs the glTF loader fuzzer (fuzz/, built by `cmake --build build --target gltf_fuzz`) for
# SECONDS seconds on a copy of the corpus in tests/data (good and bad files), with the glTF
# dictionary. Exits non-zero, leaving the failing input under FUZZ_DIR/artifacts, when the
# fuzzer finds a crash, a sanitizer report, a leak, a hang over 10 s or memory over 2 GB.
#   bash scripts/fuzz.sh [SECONDS] [FUZZ_DIR]      (defaults: 120, build/fuzz)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-120}"
dir="${2:-build/fuzz}"
fuzzer="$dir/gltf_loader_fuzz"
if [ ! -x "$fuzzer" ]; then
  echo "fuzz: $fuzzer is missing: build it with cmake --build build --target gltf_fuzz" >&2
  exit 1
fi
corpus="$dir/corpus"
mkdir -p "$corpus" "$dir/artifacts"
cp -n tests/data/good/*.gltf tests/data/good/*.glb tests/data/bad/*.gltf tests/data/bad/*.glb "$corpus"/ 2>/dev/null || true
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# -fork would use more cores than CI has; one process, bounded per input and in all.
VKPHOTON_FUZZ_FOLDER="$work" "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len=65536 -dict=fuzz/gltf.dict -artifact_prefix="$dir/artifacts/" -print_final_stats=1 "$corpus" 2>&1 |
  grep -vE '^#[0-9]+.*(NEW|REDUCE|pulse)|^warning: ' || true
status=${PIPESTATUS[0]}
exit "$status"
