#!/usr/bin/env bash
# Joins the frames of `vkphoton render --frames` into a video with ffmpeg (docs/animation.md).
#   scripts/frames-to-video.sh 'out/moving/frame-####.png' out/moving.mp4 [FPS=24] [FIRST=auto]
# The pattern is the -o of the render with .png: its run of '#' becomes ffmpeg's %0Nd.
set -euo pipefail
if [[ $# -lt 2 || $# -gt 4 ]]; then
    echo "usage: $0 'FRAMES-####.png' OUTPUT.mp4 [FPS=24] [FIRST-FRAME]" >&2
    exit 2
fi
pattern=$1 output=$2 fps=${3:-24}
if ! command -v ffmpeg >/dev/null 2>&1; then
    echo "error: ffmpeg is not installed (Debian: sudo apt-get install ffmpeg); the frames are in $(dirname "$pattern")" >&2
    exit 1
fi
name=$(basename "$pattern")
hashes=$(grep -o '#\+' <<<"$name" | head -n1 || true)
if [[ -z $hashes ]]; then
    echo "error: $pattern: the file name needs a run of '#' where the frame number is" >&2
    exit 2
fi
printf_pattern="$(dirname "$pattern")/${name/$hashes/%0${#hashes}d}"
first=${4:-}
if [[ -z $first ]]; then  # the lowest frame number present
    glob="$(dirname "$pattern")/${name/$hashes/*}"
    first_file=$(ls $glob 2>/dev/null | sort | head -n1 || true)
    if [[ -z $first_file ]]; then
        echo "error: no frames match $pattern" >&2
        exit 2
    fi
    prefix=${name%%#*}
    digits=$(basename "$first_file")
    digits=${digits#"$prefix"}
    first=$((10#${digits:0:${#hashes}}))
fi
ffmpeg -hide_banner -loglevel error -y -framerate "$fps" -start_number "$first" -i "$printf_pattern" \
    -c:v libx264 -pix_fmt yuv420p -vf "pad=ceil(iw/2)*2:ceil(ih/2)*2" "$output"
echo "wrote $output"
