#!/usr/bin/env bash
# Equal-time comparison with Cycles (shared/peers/README.md): for each scene, Cycles at 64 and
# 256 spp (its time/error line: E(T) = E_256 x t_256 / T) and vkphoton's photon integrators
# with --time-limit T, all against the same reference, in one run on one machine.
#   bench/cycles_equal_time.sh PEERS_DIR REFS_DIR T SIZE SCENE... (scene: e.g. cornell-ceiling-lambert)
# Prints one line per render: scene, renderer, seconds, relmse, mean luminance ratio; then, per
# vkphoton render, its relMSE over Cycles' at the same time.
set -euo pipefail
peers=$1 refs=$2 T=$3 size=$4
shift 4
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
metric() { "$peers/compare.sh" "$1" "$2" | awk -v k="$3" '$1 == k { print $2 }'; }
for scene in "$@"; do
    ref="$refs/$scene.exr"
    gltf="$refs/$scene.gltf"
    declare -A err=() secs=()
    for spp in 64 256; do
        log=$(blender -b --factory-startup -P "$peers/cycles_render.py" -- "$gltf" "$out/cycles-$spp.exr" "$size" "$size" "$spp" seed=1 2>&1)
        secs[cycles$spp]=$(echo "$log" | sed -n 's/.*cycles_ref: render time \([0-9.]*\) s.*/\1/p' | tail -1)
        err[cycles$spp]=$(metric "$out/cycles-$spp.exr" "$ref" relmse)
        echo "$scene cycles-${spp}spp ${secs[cycles$spp]} s relmse ${err[cycles$spp]} lum $(metric "$out/cycles-$spp.exr" "$ref" mean_lum_ratio)"
    done
    cyclesAtT=$(python3 -c "print(${err[cycles256]} * ${secs[cycles256]} / $T)")
    echo "$scene cycles relMSE at $T s (E_256 t_256 / T): $cyclesAtT"
    for variant in "photon" "photon --gather-reuse 0 --gather-rays 4 --radiance-photons 4" "sppm" "path"; do
        name=$(echo "$variant" | tr ' ' '_')
        start=$(date +%s.%N)
        "$root/build/vkphoton" render "$gltf" --integrator $variant --time-limit "$T" --spp 1000000 \
            --width "$size" --height "$size" --seed 1 --quiet -o "$out/$name.exr" --stats-json "$out/$name.json"
        wall=$(python3 -c "import time; print(round(time.time() - $start, 1))")
        e=$(metric "$out/$name.exr" "$ref" relmse)
        echo "$scene vkphoton-$name ${wall} s relmse $e lum $(metric "$out/$name.exr" "$ref" mean_lum_ratio)" \
             "ratio-to-cycles $(python3 -c "print(round($e / $cyclesAtT, 3))")"
    done
    unset err secs
done
