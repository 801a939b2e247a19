#!/usr/bin/env bash
# Equal-time comparison with Cycles (shared/peers/README.md): for each scene, Cycles at 64 and
# 256 spp (its time/error line: E(T) = E_256 x t_256 / T) and vkphoton's photon integrators
# with --time-limit T, all against the same reference, in one run on one machine.
#   bench/cycles_equal_time.sh PEERS_DIR REFS_DIR T SIZE SCENE... (scene: e.g. cornell-ceiling-lambert)
# Prints one line per render: scene, renderer, seconds, relmse, mean luminance ratio; then, per
# vkphoton render, its relMSE over Cycles' at the same time, as measured and with the reference's
# own noise taken out of both. A reference of N Cycles samples is itself off by E_N = V / N (V: one
# Cycles sample's relMSE), and every render's measured relMSE is its own error plus E_N; Cycles'
# 256-spp error gives V = E_256 / (1/256 + 1/N), N read from the reference's JSON ("spp"). With
# shared/refs's 8192-spp cornell-glass, E_N is half the photon integrator's error at 30 s: average
# more renders into the reference (bench/cycles_reference.sh) to make it small.
set -euo pipefail
peers=$1 refs=$2 T=$3 size=$4
shift 4
root=$(cd "$(dirname "$0")/.." && pwd)
binary=${VKPHOTON:-"$root/build/vkphoton"}  # VKPHOTON names another binary
out=$(mktemp -d)
# The integrators compared (each a --integrator value and its options); VARIANTS="a;b" replaces them.
IFS=';' read -r -a variants <<<"${VARIANTS:-photon;photon --gather-reuse 0 --gather-rays 4 --radiance-photons 4;sppm;path}"
metric() { "$peers/compare.sh" "$1" "$2" | awk -v k="$3" '$1 == k { print $2 }'; }
for scene in "$@"; do
    ref="$refs/$scene.exr"
    gltf="$refs/$scene.gltf"
    for f in "$gltf" "$ref" "$ref.json"; do
        [ -f "$f" ] || { echo "cycles_equal_time: no $f (REFS_DIR holds SCENE.gltf, SCENE.exr and SCENE.exr.json)" >&2; exit 2; }
    done
    declare -A err=() secs=()
    for spp in 64 256; do
        log=$(blender -b --factory-startup -P "$peers/cycles_render.py" -- "$gltf" "$out/cycles-$spp.exr" "$size" "$size" "$spp" seed=1 2>&1)
        secs[cycles$spp]=$(echo "$log" | sed -n 's/.*cycles_ref: render time \([0-9.]*\) s.*/\1/p' | tail -1)
        err[cycles$spp]=$(metric "$out/cycles-$spp.exr" "$ref" relmse)
        echo "$scene cycles-${spp}spp ${secs[cycles$spp]} s relmse ${err[cycles$spp]} lum $(metric "$out/cycles-$spp.exr" "$ref" mean_lum_ratio)"
    done
    cyclesAtT=$(python3 -c "print(${err[cycles256]} * ${secs[cycles256]} / $T)")
    refSpp=$(python3 -c "import json; print(json.load(open('$ref.json'))['spp'])")
    floor=$(python3 -c "print(${err[cycles256]} / (1 + $refSpp / 256))")
    cyclesOwnAtT=$(python3 -c "print((${err[cycles256]} - $floor) * ${secs[cycles256]} / $T)")
    echo "$scene cycles relMSE at $T s (E_256 t_256 / T): $cyclesAtT"
    echo "$scene reference's own relMSE ($refSpp spp, E_256 / (1 + N/256)): $floor;" \
         "Cycles' own at $T s: $cyclesOwnAtT"
    for variant in "${variants[@]}"; do
        name=$(echo "$variant" | tr ' ' '_')
        start=$(date +%s.%N)
        "$binary" render "$gltf" --integrator $variant --time-limit "$T" --spp 1000000 \
            --width "$size" --height "$size" --seed 1 --quiet -o "$out/$name.exr" --stats-json "$out/$name.json"
        wall=$(python3 -c "import time; print(round(time.time() - $start, 1))")
        e=$(metric "$out/$name.exr" "$ref" relmse)
        echo "$scene vkphoton-$name ${wall} s relmse $e lum $(metric "$out/$name.exr" "$ref" mean_lum_ratio)" \
             "ratio-to-cycles $(python3 -c "print(round($e / $cyclesAtT, 3))")" \
             "without-reference-noise $(python3 -c "print(round(($e - $floor) / $cyclesOwnAtT, 3))")"
    done
    unset err secs
done
