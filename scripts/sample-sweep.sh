#!/usr/bin/env bash
# Renders every model of a glTF-Sample-Assets checkout (its Models/NAME/glTF/NAME.gltf) the way a new
# user would: `vkphoton render FILE` with no option but a small size (and the stats file this
# script reads), then prints a Markdown table of what went wrong, if anything:
#   refused  the file was not rendered (exit status, the error's last line)
#   dark     the PNG's mean 8-bit value is below 0.05 of white
#   blown    more than half of the PNG's pixels have a channel at 255
#   warned   a "not rendered" warning (a material extension or feature left out)
# Usage: scripts/sample-sweep.sh MODELS_DIR OUT_DIR [SIZE=64] [MODEL...]
# Runs one model at a time (each render uses every core); a model has 600 s at most. VKPHOTON names
# another binary than build/vkphoton.
set -uo pipefail
models=${1:?MODELS_DIR (the Models folder of a glTF-Sample-Assets checkout)}
out=${2:?OUT_DIR}
size=${3:-64}
shift $(($# < 3 ? $# : 3))
binary=${VKPHOTON:-"$(cd "$(dirname "$0")/.." && pwd)/build/vkphoton"}
mkdir -p "$out"
names=("$@")
if ((${#names[@]} == 0)); then
  for dir in "$models"/*/glTF; do names+=("$(basename "$(dirname "$dir")")"); done
fi
for name in "${names[@]}"; do
  file="$models/$name/glTF/$name.gltf"
  [ -f "$file" ] || file=$(ls "$models/$name"/glTF/*.gltf 2>/dev/null | head -1)
  [ -n "$file" ] && [ -f "$file" ] || continue
  start=$(date +%s.%N)
  timeout 600 "$binary" render "$file" -o "$out/$name.exr" --width "$size" --height "$size" \
    --stats-json "$out/$name.json" >"$out/$name.log" 2>&1
  echo "$? $(echo "$(date +%s.%N) - $start" | bc)" >"$out/$name.status"
done
python3 - "$out" "${names[@]}" <<'EOF'
import json, os, sys
out, names = sys.argv[1], sys.argv[2:]
print("| model | exit | seconds | PNG mean | blown | result |")
print("|---|---|---|---|---|---|")
failures = 0
for name in names:
    status = os.path.join(out, name + ".status")
    if not os.path.exists(status):
        continue
    code, seconds = open(status).read().split()
    log = open(os.path.join(out, name + ".log"), errors="replace").read().splitlines()
    problems, mean, blown = [], "", ""
    stats = os.path.join(out, name + ".json")
    if code == "0" and os.path.exists(stats):
        shown = json.load(open(stats)).get("display", {})
        mean, blown = shown.get("meanValue", 0.0), shown.get("saturatedPixels", 0.0)
        if mean < 0.05: problems.append("dark")
        if blown > 0.5: problems.append("blown")
        mean, blown = f"{mean:.3f}", f"{blown:.3f}"
    else:
        last = [l for l in log if l.strip()]
        problems.append("refused" if code != "124" else "timed out")
        if last: problems[-1] += ": " + last[-1].replace("|", "/")[:160]
    warned = [l for l in log if "not rendered" in l]
    if warned: problems.append("warned: " + warned[0].replace("|", "/")[:160])
    failures += bool(problems)
    print(f"| {name} | {code} | {float(seconds):.0f} | {mean} | {blown} | {'; '.join(problems) or 'ok'} |")
print(f"\n{failures} of {len(names)} with a problem")
EOF
