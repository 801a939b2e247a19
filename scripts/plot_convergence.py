#!/usr/bin/env python3
"""Plots benchmark convergence tables as a PNG (no plotting library needed).

Reads the Markdown rows `| method | spp | seconds | relMSE | ...` that bench/guiding_bench and
bench/photon_map_bench print, and draws two log-log panels side by side: relMSE against samples
per pixel (left) and against seconds (right), one colour per method, with grid lines at every
decade. Usage: python3 scripts/plot_convergence.py TABLE.txt OUT.png
"""
import math
import struct
import sys
import zlib

COLOURS = [(120, 120, 120), (31, 119, 180), (255, 127, 14), (44, 160, 44), (214, 39, 40), (148, 103, 189)]
PANEL_W, PANEL_H, MARGIN = 420, 320, 30


def read_rows(path):
    curves = {}
    for line in open(path):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 4:  # later columns (e.g. segments per path) are ignored
            continue
        try:
            spp, seconds, err = int(cells[1]), float(cells[2]), float(cells[3])
        except ValueError:
            continue
        curves.setdefault(cells[0], []).append((spp, seconds, err))
    return curves


def write_png(path, width, height, pixels):
    raw = b"".join(b"\x00" + bytes(pixels[y * width * 3:(y + 1) * width * 3]) for y in range(height))
    chunk = lambda tag, data: struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)


def main():
    curves = read_rows(sys.argv[1])
    width, height = 2 * (PANEL_W + 2 * MARGIN), PANEL_H + 2 * MARGIN
    pixels = bytearray([255] * (width * height * 3))

    def plot(x, y, colour):
        if 0 <= x < width and 0 <= y < height:
            pixels[3 * (y * width + x):3 * (y * width + x) + 3] = bytes(colour)

    def line(x0, y0, x1, y1, colour, thick=1):
        steps = max(abs(x1 - x0), abs(y1 - y0), 1)
        for i in range(steps + 1):
            x, y = round(x0 + (x1 - x0) * i / steps), round(y0 + (y1 - y0) * i / steps)
            for dx in range(-thick // 2, thick // 2 + 1):
                for dy in range(-thick // 2, thick // 2 + 1):
                    plot(x + dx, y + dy, colour)

    errors = [r[2] for rows in curves.values() for r in rows if r[2] > 0]
    e_lo, e_hi = math.floor(math.log10(min(errors))), math.ceil(math.log10(max(errors)))
    for panel, column in ((0, 0), (1, 1)):
        xs = [max(r[column], 1e-3) for rows in curves.values() for r in rows]
        x_lo, x_hi = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
        left = panel * (PANEL_W + 2 * MARGIN) + MARGIN
        to_px = lambda v, lo, hi, size: (math.log10(v) - lo) / (hi - lo) * size
        for d in range(x_lo, x_hi + 1):
            x = left + round(to_px(10 ** d, x_lo, x_hi, PANEL_W))
            line(x, MARGIN, x, MARGIN + PANEL_H, (220, 220, 220))
        for d in range(e_lo, e_hi + 1):
            y = MARGIN + PANEL_H - round(to_px(10 ** d, e_lo, e_hi, PANEL_H))
            line(left, y, left + PANEL_W, y, (220, 220, 220))
        line(left, MARGIN + PANEL_H, left + PANEL_W, MARGIN + PANEL_H, (0, 0, 0))
        line(left, MARGIN, left, MARGIN + PANEL_H, (0, 0, 0))
        for i, (name, rows) in enumerate(curves.items()):
            points = [(left + round(to_px(max(r[column], 1e-3), x_lo, x_hi, PANEL_W)),
                       MARGIN + PANEL_H - round(to_px(r[2], e_lo, e_hi, PANEL_H))) for r in rows if r[2] > 0]
            for (x0, y0), (x1, y1) in zip(points, points[1:]):
                line(x0, y0, x1, y1, COLOURS[i % len(COLOURS)], 3)
        print(f"panel {panel}: x 1e{x_lo}..1e{x_hi}, relMSE 1e{e_lo}..1e{e_hi}")
    for i, name in enumerate(curves):
        print(f"colour {COLOURS[i % len(COLOURS)]}: {name}")
    write_png(sys.argv[2], width, height, pixels)


if __name__ == "__main__":
    main()
