#!/usr/bin/env python3
"""Top views (x right, z down) of photon maps written by `vkphoton photons`, side by side: the
log of the photon count per pixel, each map scaled to its own largest count, like Keller &
Wald's figure 1. Pure Python (no numpy), PNG out.

    python3 scripts/plot_photons_top.py A.ply [B.ply ...] out.png [--size 400]
"""
import math
import struct
import sys

from plot_convergence import write_png


def read_ply_positions(path):
    with open(path, "rb") as f:
        count = 0
        while True:
            line = f.readline().decode("ascii").strip()
            if line.startswith("element vertex"):
                count = int(line.split()[-1])
            if line == "end_header":
                break
        record = struct.Struct("<9fB")
        data = f.read(count * record.size)
    return [record.unpack_from(data, i * record.size)[0:3] for i in range(count)]


def top_view(points, size):
    xs = [p[0] for p in points]
    zs = [p[2] for p in points]
    lo, hi = min(min(xs), min(zs)), max(max(xs), max(zs))
    scale = (size - 1) / max(hi - lo, 1e-9)
    counts = [0] * (size * size)
    for x, z in zip(xs, zs):
        counts[int((z - lo) * scale) * size + int((x - lo) * scale)] += 1
    top = math.log1p(max(counts) or 1)
    return [int(255 * math.log1p(c) / top) for c in counts]


def main():
    args = [a for i, a in enumerate(sys.argv[1:]) if not a.startswith("--") and sys.argv[i] != "--size"]
    size = int(sys.argv[sys.argv.index("--size") + 1]) if "--size" in sys.argv else 400
    if len(args) < 2:
        sys.exit(__doc__)
    gap = 6
    views = []
    for path in args[:-1]:
        points = read_ply_positions(path)
        views.append(top_view(points, size))
        print(f"{path}: {len(points)} photons")
    width = len(views) * size + (len(views) - 1) * gap
    pixels = bytearray()
    for y in range(size):
        for i, view in enumerate(views):
            if i:
                pixels += bytes((255, 255, 255)) * gap
            for v in view[y * size:(y + 1) * size]:
                pixels += bytes((v, v, v))
    write_png(args[-1], width, size, bytes(pixels))
    print(f"wrote {args[-1]}")


if __name__ == "__main__":
    main()
