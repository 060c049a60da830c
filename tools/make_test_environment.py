#!/usr/bin/env python3
"""Writes tests/data/scenes/environments/softboxes.hdr: a 128 × 64 equirect Radiance file (flat RGBE,
row 0 the zenith, +y up, docs/ibl.md "Conventions") of high dynamic range, for measuring image-based
lighting against its ground truth (docs/eval.md, "The ground truth"): a dim sky over a dark
ground, a round softbox of radiance 10 (a small bright source, where prefiltering and the split sum
err most) and a warm panel of radiance 6 low on the other side. Deterministic: no randomness."""
import math
import struct
import sys

W, H = 128, 64


def radiance(x, y, z):
    if y < 0:
        return (0.05, 0.045, 0.04)
    t = math.sqrt(y)
    sky = (0.9 * (1 - t) + 0.25 * t, 0.9 * (1 - t) + 0.45 * t, 0.9 * (1 - t) + 1.0 * t)
    sky = tuple(0.4 * c for c in sky)
    # Round softbox: 20 degrees across, centred at 40 degrees elevation, towards -z +x.
    cx, cy, cz = math.cos(math.radians(40)) * math.sin(math.radians(30)), math.sin(math.radians(40)), \
        -math.cos(math.radians(40)) * math.cos(math.radians(30))
    if x * cx + y * cy + z * cz > math.cos(math.radians(10)):
        return (10.0, 10.0, 10.0)
    # Warm panel: azimuth 100..140 degrees, elevation 5..20 degrees.
    azimuth = math.degrees(math.atan2(x, z)) % 360
    elevation = math.degrees(math.asin(max(-1.0, min(1.0, y))))
    if 100 <= azimuth <= 140 and 5 <= elevation <= 20:
        return (6.0, 4.2, 2.4)
    return sky


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return bytes((int(r * scale), int(g * scale), int(b * scale), exponent + 128))


def main(path):
    rows = []
    for j in range(H):
        theta = (j + 0.5) / H * math.pi  # from the zenith
        row = b""
        for i in range(W):
            phi = (i + 0.5) / W * 2 * math.pi
            x, y, z = math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi)
            row += rgbe(*radiance(x, y, z))
        rows.append(row)
    with open(path, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (H, W))
        for row in rows:
            f.write(row)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/scenes/environments/softboxes.hdr")
