#!/usr/bin/env bash
# Regenerates every golden expectation from the current matc (docs/testing.md, "Goldens"):
#   scripts/update-goldens.sh [path/to/matc]
#   scripts/update-goldens.sh --shaders-into DIR [path/to/matc]   (the shader goldens only, into
#                                    the empty or new folder DIR: what test_golden_shaders checks)
# Without a matc, builds matc in build/test (the configuration scripts/test.sh runs first).
#
# tests/golden/diagnostics: for each <name>.mat, runs `matc compile` on it from the source root
# (so file paths in the text are relative) and writes <name>.expected:
#   exit: <code>
#   <stderr, byte for byte>
# Expectations with no .mat are deleted.
#
# tests/golden/shaders: the shipped text of every shader the examples build, rewritten whole (a
# shader no longer built leaves with the folder):
#   materials/<material>/<variant>.<vert|frag>.es300.glsl and .metal: every variant that
#       scripts/run-examples.sh compiles (the materials and options of scripts/example-packages.sh),
#       GLSL ES 3.00 and MSL, the bytes the package holds (`matc info PKG --variant K --stage S
#       --target T` prints them)
#   post/<effects>.<vert|frag|fetch.frag|upscaled.frag>.es300.glsl: every post-pass variant the runtime embeds
#       (`matc post --every-variant`; its Vulkan stages ship as SPIR-V only, so it has no MSL)
#
# Review the result with `git diff tests/golden`.
set -euo pipefail

# Paths given on the command line are relative to where it runs.
shaders_into=
if [ "${1:-}" = --shaders-into ]; then
  [ $# -ge 2 ] || { echo "update-goldens: --shaders-into needs a folder" >&2; exit 2; }
  shaders_into=$(realpath -m "$2")
  shift 2
fi
matc=${1:-}
[ -z "$matc" ] || matc=$(realpath -m "$matc")
cd "$(dirname "$0")/.."
source scripts/example-packages.sh
if [ -z "$matc" ]; then
  cmake --preset test >/dev/null
  cmake --build --preset test --target matc
  matc=build/test/matc/matc
fi
matc=$(realpath "$matc")
[ -x "$matc" ] || { echo "update-goldens: '$matc' is not an executable" >&2; exit 2; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# write_shader_goldens DIR: the layout above, into the empty folder DIR. No variant cache: its
# entries are the same bytes, but a test must not depend on (or fill) the user's cache.
write_shader_goldens() {
  local out=$1 material name file base
  for material in "${example_materials[@]}"; do
    name=$(basename "$material" .mat)
    "$matc" compile "$material" -o "$tmp/$name.matpkg" --no-cache "${example_compile_options[@]}" \
      --emit-source "$tmp/materials/$name" >/dev/null
    mkdir -p "$out/materials/$name"
    # --emit-source names a file <material name>.<variant>.<stage>.<flavour>; *.es300.glsl and
    # *.metal are the shipped text (the readable, Vulkan-flavour and SPIR-V files are not).
    for file in "$tmp/materials/$name"/*.es300.glsl "$tmp/materials/$name"/*.metal; do
      base=${file##*/}
      cp "$file" "$out/materials/$name/${base#*.}"
    done
  done
  "$matc" post --every-variant --cpp "$tmp/post.cpp" --emit-source "$tmp/post" >/dev/null
  mkdir -p "$out/post"
  for file in "$tmp/post"/*.es300.glsl; do
    base=${file##*/}
    cp "$file" "$out/post/${base#post.}"
  done
}

if [ -n "$shaders_into" ]; then
  mkdir -p "$shaders_into"
  [ -z "$(ls -A "$shaders_into")" ] || { echo "update-goldens: '$shaders_into' is not empty" >&2; exit 2; }
  write_shader_goldens "$shaders_into"
  exit 0
fi

folder=tests/golden/diagnostics
count=0
for mat in "$folder"/*.mat; do
  status=0
  "$matc" compile "$mat" -o "$tmp/out.matpkg" >/dev/null 2>"$tmp/stderr" || status=$?
  { echo "exit: $status"; cat "$tmp/stderr"; } >"${mat%.mat}.expected"
  count=$((count + 1))
done
for expected in "$folder"/*.expected; do
  [ -e "${expected%.expected}.mat" ] || { rm -f "$expected"; echo "update-goldens: removed stale $expected"; }
done
echo "update-goldens: wrote $count expectations with $matc"

shaders=tests/golden/shaders
mkdir -p "$tmp/shaders"
write_shader_goldens "$tmp/shaders"
listing() { (cd "$1" && find . -type f | sort); }
if [ -d "$shaders" ]; then
  listing "$shaders" >"$tmp/before"
  rm -rf "$shaders"
else
  : >"$tmp/before"
fi
mv "$tmp/shaders" "$shaders"
listing "$shaders" >"$tmp/after"
comm -23 "$tmp/before" "$tmp/after" | sed "s|^\./|update-goldens: removed stale $shaders/|"
echo "update-goldens: wrote $(wc -l <"$tmp/after") shader goldens with $matc"
git status --short -- tests/golden 2>/dev/null || true
