#!/usr/bin/env python3
"""Writes a synthetic sun-and-sky equirectangular map as a Radiance .hdr (flat RGBE scanlines).

Deterministic: the same bytes every run. The mapping is vkphoton's (docs/environment.md): the centre
column faces +X, u = 0.75 faces +Z, the top row is the zenith. The sky brightens towards the zenith
and the horizon, the ground below the horizon is dim, and the sun is a small disk of high radiance.
Run: python3 scripts/make_sun_sky.py OUT.hdr [--width 512] [--sun-azimuth DEG] [--sun-elevation DEG]
"""
import argparse
import math


def rgbe(r, g, b):
    v = max(r, g, b)
    if v < 1e-32:
        return bytes((0, 0, 0, 0))
    m, e = math.frexp(v)
    scale = m * 256.0 / v
    return bytes((int(r * scale), int(g * scale), int(b * scale), e + 128))


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("out")
    parser.add_argument("--width", type=int, default=512)
    parser.add_argument("--sun-azimuth", type=float, default=230.0, help="degrees from +X towards +Z")
    parser.add_argument("--sun-elevation", type=float, default=40.0, help="degrees above the horizon")
    parser.add_argument("--sun-radiance", type=float, default=5000.0)
    parser.add_argument("--sun-radius", type=float, default=1.5, help="degrees")
    args = parser.parse_args()
    width, height = args.width, args.width // 2
    az, el = math.radians(args.sun_azimuth), math.radians(args.sun_elevation)
    sun = (math.cos(el) * math.cos(az), math.sin(el), math.cos(el) * math.sin(az))
    cos_sun = math.cos(math.radians(args.sun_radius))
    rows = []
    for j in range(height):
        theta = math.pi * (j + 0.5) / height
        row = bytearray()
        for i in range(width):
            phi = 2 * math.pi * ((i + 0.5) / width - 0.5)
            d = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            if d[1] > 0:
                horizon = 1.0 - d[1]
                c = (0.35 + 0.5 * horizon, 0.55 + 0.35 * horizon, 1.0)
                c = tuple(0.8 * x for x in c)
            else:
                c = (0.12, 0.1, 0.08)
            if sum(a * b for a, b in zip(d, sun)) > cos_sun:
                c = (args.sun_radiance, args.sun_radiance * 0.95, args.sun_radiance * 0.85)
            row += rgbe(*c)
        rows.append(bytes(row))
    with open(args.out, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(f"-Y {height} +X {width}\n".encode())
        for row in rows:
            f.write(row)


if __name__ == "__main__":
    main()
