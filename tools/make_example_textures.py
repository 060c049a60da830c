#!/usr/bin/env python3
"""Writes the images the painted_tiles example samples, 64x64 each:
  examples/scenes/textures/tiles.png         sRGB tiles (two glazes, light grout);
  examples/scenes/textures/tiles_normal.png  its tangent-space normal map: each tile is raised above the
                                      grout with a 2-texel bevel;
  examples/scenes/textures/floor_normal.png  the hammered floor's normal map (examples/materials/hammered_floor.mat):
                                      a 4 x 4 egg-crate relief, slopes up to 0.5.
Standard library only, so the images are reproducible anywhere:
    python3 tools/make_example_textures.py
"""
import math
import pathlib
import struct
import zlib

SIZE, TILE = 64, 16
GLAZE_A, GLAZE_B, GROUT = (176, 58, 46), (230, 196, 120), (235, 232, 224)
BEVEL, SLOPE = 2, 0.6


def pixel(x, y):
    if x % TILE in (0, TILE - 1) or y % TILE in (0, TILE - 1):
        return GROUT
    return GLAZE_A if (x // TILE + y // TILE) % 2 == 0 else GLAZE_B


def normal(x, y):
    """Facet's normal maps: red = +u, green = +v (down the image: its top row is v = 0), decoded
    as rgb * 255/127 - 128/127, so 128 is exactly 0."""
    lx, ly = x % TILE, y % TILE
    nx = -SLOPE if lx < BEVEL else SLOPE if lx >= TILE - BEVEL else 0.0
    ny = -SLOPE if ly < BEVEL else SLOPE if ly >= TILE - BEVEL else 0.0
    length = (nx * nx + ny * ny + 1.0) ** 0.5
    return tuple(min(255, round(128 + 127 * c / length)) for c in (nx, ny, 1.0))


RIPPLE_PERIOD, RIPPLE_SLOPE = 16, 0.5


def ripple(x, y):
    """An egg-crate relief, height sin(2 pi x / P) sin(2 pi y / P): its gradient at the texel's
    centre, scaled so that the steepest slope along an axis is RIPPLE_SLOPE. Smooth everywhere (no
    flat floor between bumps, no crease), so the normal varies nearly linearly across a pixel where
    a period spans a few of them. Encoded as normal()."""
    u = 2 * math.pi * (x + 0.5) / RIPPLE_PERIOD
    v = 2 * math.pi * (y + 0.5) / RIPPLE_PERIOD
    nx = -RIPPLE_SLOPE * math.cos(u) * math.sin(v)
    ny = -RIPPLE_SLOPE * math.sin(u) * math.cos(v)
    length = (nx * nx + ny * ny + 1.0) ** 0.5
    return tuple(min(255, round(128 + 127 * c / length)) for c in (nx, ny, 1.0))


def png(width, height, rows):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    raw = b"".join(b"\x00" + bytes(c for p in row for c in p) for row in rows)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


folder = pathlib.Path(__file__).resolve().parent.parent / "examples" / "scenes" / "textures"
for name, texel in (("tiles.png", pixel), ("tiles_normal.png", normal), ("floor_normal.png", ripple)):
    out = folder / name
    out.write_bytes(png(SIZE, SIZE, [[texel(x, y) for x in range(SIZE)] for y in range(SIZE)]))
    print(out)
