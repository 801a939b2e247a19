#!/usr/bin/env bash
# vkphoton on a borrowed GPU machine: the test suite and the benchmarks from a build made here,
# carried with the runtime libraries `ldd` names and the Khronos validation layer, every figure
# written to one file. Two steps:
#
#   bash bench/gpu/run.sh pack          # here: build, then gather binaries, libraries, layer in .gpu/
#   bash bench/gpu/run.sh run [DIR]     # there (or here, on lavapipe): tests + benchmarks into
#                                       # DIR/gpu-results.md (default: $OUT, else out/gpu)
#
# .gpu/ is ignored by git (.gitignore); the device tool carries it (`carry: [".gpu"]`).
# The GPU machine has no Vulkan loader of its own and cannot reach the network, so the loader
# (libvulkan.so.1) travels with the other libraries; the driver's ICD file is found where the
# NVIDIA image keeps it. Set VKPHOTON_GPU_TESTS=0 to skip the tests (VKPHOTON_GPU_BENCHES=0 the
# benchmarks, =view only the viewer's), VKPHOTON_GPU_TEST_FILTER
# to run a gtest filter, VKPHOTON_GPU_SHARDS for parallel test processes (default 8).
set -uo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
pack=$root/.gpu

do_pack() {
  set -e
  bash scripts/setup.sh
  cmake --build build -j "${VKPHOTON_JOBS:-2}" --target vkphoton vkphoton_unit_tests vkphoton_render_tests \
    vkphoton_slow_tests path_tracer_bench photon_bench photon_map_bench guiding_bench display_bench
  rm -rf "$pack"
  mkdir -p "$pack/bin" "$pack/lib" "$pack/layers"
  local bins=(build/vkphoton build/tests/vkphoton_unit_tests build/tests/vkphoton_render_tests
              build/tests/vkphoton_slow_tests build/bench/path_tracer_bench build/bench/photon_bench
              build/bench/photon_map_bench build/bench/guiding_bench build/bench/display_bench)
  for b in "${bins[@]}"; do strip -o "$pack/bin/$(basename "$b")" "$b"; done
  # Every shared library the binaries and the validation layer need, but the C runtime's own
  # (the GPU machine's glibc is newer, and mixing two loaders breaks both).
  local layer=/usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so
  { for b in "$pack"/bin/* "$layer"; do ldd "$b"; done; } |
    awk '$3 ~ /^\// {print $3}' | sort -u |
    grep -vE '/(libc|libm|libpthread|libdl|librt|ld-linux-x86-64|libresolv)\.so' |
    while read -r lib; do cp -L "$lib" "$pack/lib/"; done
  cp -L /usr/lib/x86_64-linux-gnu/libvulkan.so.1 "$pack/lib/"
  # The NVIDIA ICD (libGLX_nvidia.so.0) answers no vkCreateInstance without libglvnd's dispatch
  # libraries, which the bare GPU machine lacks: their Debian packages travel too and are unpacked
  # into / there (as root) before the first Vulkan call.
  mkdir -p "$pack/debs"
  (cd "$pack/debs" && apt-get download libglvnd0 libegl1 libgl1 libglx0 libopengl0 libgles2 >/dev/null 2>&1) ||
    echo "run.sh pack: could not download the libglvnd packages; the NVIDIA ICD may find no instance" >&2
  strip "$layer" -o "$pack/layers/libVkLayer_khronos_validation.so"
  sed 's#"library_path": *"[^"]*"#"library_path": "./libVkLayer_khronos_validation.so"#' \
    /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json >"$pack/layers/VkLayer_khronos_validation.json"
  # The tests find their data, scenes and the vkphoton binary at the paths compiled in.
  echo "$root" >"$pack/source_dir"
  # The device tool carries 64 MiB with the working tree: the binaries, libraries and layer
  # travel as one xz archive (about a fifth of their size).
  tar -C "$pack" -cJf "$root/.gpu-pack.tar.xz" bin lib layers debs source_dir
  rm -rf "$pack" && mkdir -p "$pack" && mv "$root/.gpu-pack.tar.xz" "$pack/pack.tar.xz"
  du -sh "$pack"
}

do_run() {
  local out=${1:-${OUT:-$root/out/gpu}}
  mkdir -p "$out"
  local results=$out/gpu-results.md log=$out/gpu-log.txt
  if [ -f "$pack/pack.tar.xz" ]; then
    local unpacked=${TMPDIR:-/tmp}/vkphoton-gpu
    rm -rf "$unpacked" && mkdir -p "$unpacked" && tar -C "$unpacked" -xJf "$pack/pack.tar.xz"
    pack=$unpacked
  fi
  [ -x "$pack/bin/vkphoton" ] || { echo "run.sh: no $pack/bin/vkphoton: run 'bash bench/gpu/run.sh pack' first" >&2; exit 2; }
  if [ "$(id -u)" = 0 ] && ! ldconfig -p | grep -q libGLdispatch.so.0 && compgen -G "$pack/debs/*.deb" >/dev/null; then
    for f in "$pack"/debs/*.deb; do dpkg -x "$f" /; done
    ldconfig
  fi
  export LD_LIBRARY_PATH="$pack/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib; do [ -d "$d" ] && LD_LIBRARY_PATH+=":$d"; done
  export VK_LAYER_PATH="$pack/layers"
  for icd in /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json /usr/share/vulkan/icd.d/nvidia_icd.json \
             /etc/vulkan/icd.d/nvidia_icd.json; do
    if [ -f "$icd" ] && [ -z "${VK_ICD_FILENAMES:-}" ]; then export VK_DRIVER_FILES=$icd; break; fi
  done
  # The compiled-in paths (tests' data, scenes, build/vkphoton) point at the packing checkout.
  local src; src=$(cat "$pack/source_dir")
  if [ "$src" != "$root" ] && [ ! -e "$src" ]; then mkdir -p "$(dirname "$src")" && ln -s "$root" "$src"; fi
  mkdir -p "$src/build/tests"
  [ -e "$src/build/vkphoton" ] || ln -s "$pack/bin/vkphoton" "$src/build/vkphoton"
  local bin=$pack/bin
  {
    echo "# vkphoton on $(hostname) — $(date -u +%Y-%m-%dT%H:%MZ)"
    echo
    echo "commit $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown); VK_DRIVER_FILES=${VK_DRIVER_FILES:-} VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-}"
    nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader 2>/dev/null | sed 's/^/gpu: /'
    echo; echo '## devices'; echo '```'
    if ! "$bin/vkphoton" devices 2>&1; then
      # What the loader saw, and what the ICD library lacks.
      VK_LOADER_DEBUG=error,warn,driver "$bin/vkphoton" devices 2>&1 | head -40
      ldconfig -p | grep -E 'GLX_nvidia|GLdispatch|nvidia-glcore' | head
      ldd "$(ldconfig -p | awk '/libGLX_nvidia.so.0/ {print $NF; exit}')" 2>&1 | grep -i 'not found'
    fi
    ls /usr/local/nvidia/share/vulkan/icd.d /usr/share/vulkan/icd.d /etc/vulkan/icd.d 2>&1 | head -8; echo '```'
  } >"$results"
  run_tests "$out" >>"$results" 2>>"$log"
  run_benches >>"$results" 2>>"$log"
  echo "run.sh: figures in $results" >&2
}

# The tier binaries (unit, render, slow) in parallel shards (the GPU is shared by them; the CPU work
# spreads), validation on.
run_tests() {
  [ "${VKPHOTON_GPU_TESTS:-1}" = 1 ] || return 0
  local out=$1 shards=${VKPHOTON_GPU_SHARDS:-8} filter=${VKPHOTON_GPU_TEST_FILTER:-*}
  echo; echo "## tests ($shards shards per tier, filter '$filter', validation layer on)"
  local start=$SECONDS pids=()
  for tier in unit render slow; do
    for ((i = 0; i < shards; i++)); do
      VKPHOTON_VALIDATE=1 VK_LOADER_DEBUG=none GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i \
        timeout "${VKPHOTON_GPU_TEST_TIMEOUT:-300}" "$pack/bin/vkphoton_${tier}_tests" --gtest_filter="$filter" \
        --gtest_brief=1 >"$out/tests-$tier-$i.txt" 2>&1 &
      pids+=($!)
    done
  done
  for p in "${pids[@]}"; do wait "$p"; done
  cat "$out"/tests-*.txt >"$out/tests.txt"; rm -f "$out"/tests-*.txt
  echo "wall: $((SECONDS - start)) s"
  echo '```'
  grep -E '^\[  (PASSED|FAILED|SKIPPED) |^\[  FAILED  \]|tests? ran|Terminated' "$out/tests.txt" | sort | uniq -c | sort -rn | head -60
  echo '```'
}

bench() {  # bench TITLE CMD...: the command line and its output, timed
  echo; echo "## $1"; shift
  echo '```'; echo "\$ $*"
  local start=$SECONDS
  timeout "${VKPHOTON_GPU_BENCH_TIMEOUT:-120}" "$@" 2>&1 | tail -40
  echo "(exit ${PIPESTATUS[0]}, $((SECONDS - start)) s)"; echo '```'
}

# `vkphoton view --headless` at 1920x1080 for 5 s after the first image, per integrator: the
# images presented per second (each through the display pass and the copy a swapchain image
# gets; no display, so no window system's present).
view_fps() {
  local o; o=$(mktemp -d)
  printf 'samples 1\nseconds 5\nquit\n' >"$o/events.txt"
  for integ in path photon sppm; do
    "$pack/bin/vkphoton" render scenes/cornell-box.gltf --integrator "$integ" --width 1920 --height 1080 --spp 1 \
      --quiet -o "$o/warm-$integ.exr" >/dev/null 2>&1  # the driver's pipeline compilation (run_benches)
    bench "view --headless 1920x1080 $integ, 5 s" "$pack/bin/vkphoton" view scenes/cornell-box.gltf --headless \
      --integrator "$integ" --width 1920 --height 1080 --spp 100000 --events "$o/events.txt" --stats-json "$o/$integ.json"
    [ -f "$o/$integ.json" ] && grep -E '^  "(presentedPerSecond|framesPresented|firstImageSeconds|firstIntegratorImageSeconds|seconds|device)"' "$o/$integ.json"
  done
  rm -rf "$o"
}

run_benches() {
  [ "${VKPHOTON_GPU_BENCHES:-1}" = view ] && { view_fps; return 0; }
  [ "${VKPHOTON_GPU_BENCHES:-1}" = 1 ] || return 0
  local bin=$pack/bin s=scenes
  bench "path tracer throughput (cornell-box)" "$bin/path_tracer_bench" $s/cornell-box.gltf --width 256 --height 256 --spp 16 --repeat 3
  bench "path tracer throughput (cornell-glass)" "$bin/path_tracer_bench" $s/cornell-glass.gltf --width 256 --height 256 --spp 16 --repeat 3
  bench "photon tracing (cornell-glass)" "$bin/photon_bench" $s/cornell-glass.gltf --paths 1000000 --repeat 3
  bench "photon map: grid build and gathers" "$bin/photon_map_bench" $s/cornell-glass.gltf --skip-convergence --repeat 3
  bench "viewer display pass, 1920x1080" "$bin/display_bench" --repeat 5
  view_fps
  # Guided vs plain path tracing, error against the Cycles reference per sample count and second.
  bench "guided path tracing (cornell-ceiling-lambert, 128x128, Cycles reference)" "$bin/guiding_bench" \
    tests/data/cycles/cornell-ceiling-lambert.gltf --size 128 --reference tests/data/cycles/cornell-ceiling-lambert.exr \
    --max-spp 4096 --max-seconds 8
  local o; o=$(mktemp -d)
  for integ in path photon sppm guided; do
    local extra=(--integrator "$integ")
    # A warm-up run first: the NVIDIA driver compiles each pipeline on its first use (seconds for
    # the large kernels: 6 s before the path tracer's first sample at 1080p, 14 s for the guided
    # one, 2026-11-28) and keeps it in its own disk cache; the timed run measures rendering.
    "$bin/vkphoton" render $s/cornell-box.gltf "${extra[@]}" --width 1920 --height 1080 --spp 1 --quiet \
      -o "$o/warm-$integ.exr" >/dev/null 2>&1
    bench "render 1920x1080 $integ, 10 s (cornell-box)" "$bin/vkphoton" render $s/cornell-box.gltf "${extra[@]}" \
      --width 1920 --height 1080 --spp 100000 --time-limit 10 --quiet -o "$o/$integ.exr" --stats-json "$o/$integ.json"
    [ -f "$o/$integ.json" ] && { echo '```json'; head -c 1500 "$o/$integ.json"; echo; echo '```'; }
  done
  rm -rf "$o"
}

case "${1:-}" in
  pack) do_pack ;;
  run) shift; do_run "$@" ;;
  *) echo "usage: bash bench/gpu/run.sh pack | run [DIR]" >&2; exit 2 ;;
esac
