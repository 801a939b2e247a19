#!/usr/bin/env bash
# A lower-noise Cycles reference (shared/peers/README.md, step 1: "the mean of a few long renders;
# its own relMSE must be well below the figures you compare"): renders each scene of REFS_DIR with
# Cycles at SPP samples once per seed, at the reference's size, and writes into OUT_DIR the mean
# of those renders and REFS_DIR's own reference, weighted by samples, with the scene file and a
# JSON saying what it is made of. OUT_DIR can then stand for REFS_DIR in cycles_equal_time.sh.
#   bench/cycles_reference.sh PEERS_DIR REFS_DIR OUT_DIR SPP SCENE...   (SEEDS="11 12 13" by default)
# A render already in OUT_DIR (OUT_DIR/renders/SCENE-SEED.exr) is kept, so an interrupted run goes on.
set -euo pipefail
peers=$1 refs=$2 out=$3 spp=$4
shift 4
seeds=${SEEDS:-"11 12 13"}
mkdir -p "$out/renders"
for scene in "$@"; do
    gltf="$refs/$scene.gltf"
    for f in "$gltf" "$refs/$scene.exr" "$refs/$scene.exr.json"; do
        [ -f "$f" ] || { echo "cycles_reference: no $f (REFS_DIR holds SCENE.gltf, SCENE.exr and SCENE.exr.json)" >&2; exit 2; }
    done
    read -r width height refSpp < <(python3 -c "
import json; d = json.load(open('$refs/$scene.exr.json')); print(d['width'], d['height'], d['spp'])")
    parts=("$refs/$scene.exr") weights=("$refSpp")
    total=$refSpp
    for seed in $seeds; do
        render="$out/renders/$scene-$seed.exr"
        if [ ! -f "$render" ]; then
            echo "$scene: Cycles, $spp spp, seed $seed ($width x $height)" >&2
            blender -b --factory-startup -P "$peers/cycles_render.py" -- "$gltf" "$render.part.exr" \
                "$width" "$height" "$spp" seed="$seed" >"$out/renders/$scene-$seed.log" 2>&1 ||
                { echo "cycles_reference: Cycles failed, see $out/renders/$scene-$seed.log" >&2; exit 1; }
            mv "$render.part.exr" "$render"
        fi
        parts+=("$render") weights+=("$spp")
        total=$((total + spp))
    done
    args=()
    for i in "${!parts[@]}"; do
        args+=("${parts[$i]}" --ch R,G,B --mulc "$(python3 -c "print(${weights[$i]} / $total)")")
        ((i == 0)) || args+=(--add)
    done
    oiiotool "${args[@]}" -d float -o "$out/$scene.exr"
    cp "$gltf" "$out/$scene.gltf"
    python3 - "$out/$scene.exr.json" "$width" "$height" "$total" "${parts[@]}" <<'EOF'
import json, sys
path, width, height, total, parts = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5:]
json.dump({"width": width, "height": height, "spp": total,
           "what": "mean of Cycles renders weighted by samples", "made_of": parts},
          open(path, "w"), indent=1)
EOF
    echo "$scene: $out/$scene.exr, $total spp in all" >&2
done
