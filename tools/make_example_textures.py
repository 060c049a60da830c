#!/usr/bin/env python3
"""Writes examples/textures/tiles.png: 64x64 sRGB tiles (two glazes, light grout), the image the
painted_tiles example samples. Standard library only, so the image is reproducible anywhere:
    python3 tools/make_example_textures.py
"""
import pathlib
import struct
import zlib

SIZE, TILE = 64, 16
GLAZE_A, GLAZE_B, GROUT = (176, 58, 46), (230, 196, 120), (235, 232, 224)


def pixel(x, y):
    if x % TILE in (0, TILE - 1) or y % TILE in (0, TILE - 1):
        return GROUT
    return GLAZE_A if (x // TILE + y // TILE) % 2 == 0 else GLAZE_B


def png(width, height, rows):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    raw = b"".join(b"\x00" + bytes(c for p in row for c in p) for row in rows)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


out = pathlib.Path(__file__).resolve().parent.parent / "examples" / "textures" / "tiles.png"
out.write_bytes(png(SIZE, SIZE, [[pixel(x, y) for x in range(SIZE)] for y in range(SIZE)]))
print(out)
