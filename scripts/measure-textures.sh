#!/usr/bin/env bash
# The figures of docs/runtime.md, "Compressed textures (ASTC)": for each ASTC block size, on the
# example textures and on a 1024x1024 picture made here (smooth gradients, tiles and fine
# noise: the example textures are 64x64 and flat), level 0's PSNR against the source PNG, the
# bytes of every level against RGBA8 with the same mip chain, and the encoding time
# (facet-texture's own clock, one thread, astcenc's medium effort). Then the GL upload: facet-view
# rendering a 64x64 frame of that picture's ASTC 6x6 texture, the blocks uploaded
# (glCompressedTexImage2D) against astcenc's CPU decoding plus an RGBA8 upload
# (--decode-textures), timed whole with farm-bench, paired.
#   scripts/measure-textures.sh     (after: cmake --preset test; cmake --build build/test --target matc facet-texture facet-view)
set -euo pipefail
cd "$(dirname "$0")/.."

build=build/test
work=build/measure-textures
rm -rf "$work"
mkdir -p "$work/textures" "$work/packages" "$work/out"

# The 1024x1024 picture, written as an uncompressed-deflate PNG by Python's zlib (deterministic).
python3 - "$work/textures/picture.png" <<'PY'
import math, struct, sys, zlib
w = h = 1024
seed = 12345
rows = []
for y in range(h):
    row = bytearray([0])
    for x in range(w):
        seed = (seed * 1103515245 + 12345) & 0x7fffffff
        noise = (seed >> 16) % 17 - 8
        tile = 40 if (x // 128 + y // 128) % 2 else 0
        grout = -60 if x % 128 < 4 or y % 128 < 4 else 0
        r = 120 + 80 * math.sin(x / 97.0) + tile + grout + noise
        g = 110 + 70 * math.sin(y / 61.0 + x / 150.0) + grout + noise
        b = 90 + 60 * math.cos((x + y) / 83.0) - tile + grout + noise
        row += bytes(max(0, min(255, int(v))) for v in (r, g, b))
    rows.append(bytes(row))
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
png += chunk(b"IDAT", zlib.compress(b"".join(rows), 9)) + chunk(b"IEND", b"")
open(sys.argv[1], "wb").write(png)
PY

echo "| image | usage | block | bits/texel | level 0 PSNR (dB) | bytes with mips (RGBA8) | encode (s) |"
echo "|---|---|---|---|---|---|---|"
encode() {  # image usage block
  local line
  line=$("$build/matc/matc" texture "$1" -o "$work/textures/$(basename "$1" .png)_$2_$3.ktx2" --usage "$2" --block "$3")
  # "<out>: WxH, N levels, FORMAT, B bytes of levels (RGBA8: R, P%), level 0 PSNR X dB, encoded in T s"
  local bytes rgba psnr seconds
  bytes=$(sed -n 's/.*, \([0-9]*\) bytes of levels.*/\1/p' <<<"$line")
  rgba=$(sed -n 's/.*(RGBA8: \([0-9]*\),.*/\1/p' <<<"$line")
  psnr=$(sed -n 's/.*PSNR \([0-9.inf]*\) dB.*/\1/p' <<<"$line")
  seconds=$(sed -n 's/.*encoded in \([0-9.]*\) s.*/\1/p' <<<"$line")
  local bits
  bits=$(python3 -c "b='$3'.split('x'); print(f'{128 / (int(b[0]) * int(b[1])):.2f}')")
  echo "| $(basename "$1") | $2 | $3 | $bits | $psnr | $bytes ($rgba) | $seconds |"
}
for block in 4x4 5x5 6x6 8x8; do encode examples/scenes/textures/tiles.png color "$block"; done
for block in 4x4 5x5 6x6 8x8; do encode examples/scenes/textures/tiles_normal.png normal "$block"; done
for block in 4x4 5x5 6x6 8x8; do encode "$work/textures/picture.png" color "$block"; done
for block in 6x6 8x8; do encode "$work/textures/picture.png" data "$block"; done

# GL upload: one 64x64 frame of the picture's ASTC 6x6 texture (level 0 fills the frame's sphere).
"$build/matc/matc" compile examples/materials/painted_tiles.mat -o "$work/packages/painted_tiles.matpkg" >/dev/null
cat >"$work/picture.json" <<'JSON'
{ "width": 64, "height": 64, "sun": {}, "objects": [
  { "material": "painted_tiles", "params": { "albedo": "textures/picture_color_6x6.ktx2", "tiling": 0.25 } } ] }
JSON
view=("$build/runtime/viewer/facet-view" "$work/picture.json" --packages "$work/packages" --out "$work/out" --backend gl)
echo
echo "GL upload, ASTC blocks (A) against CPU decoding + RGBA8 (B), whole facet-view processes:"
farm-bench -n 15 --warmup 2 --vs "${view[*]} --decode-textures" -- "${view[@]}"
