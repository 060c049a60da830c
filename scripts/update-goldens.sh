#!/usr/bin/env bash
# Regenerates every golden expectation from the current matc (docs/testing.md, "Goldens"):
#   scripts/update-goldens.sh [path/to/matc]
# Without an argument, builds matc in build/test (the configuration scripts/test.sh runs first).
# For each tests/golden/diagnostics/<name>.mat, runs `matc compile` on it from the source root
# (so file paths in the text are relative) and writes <name>.expected:
#   exit: <code>
#   <stderr, byte for byte>
# Expectations with no .mat are deleted. Review the result with `git diff tests/golden`.
set -euo pipefail
cd "$(dirname "$0")/.."

matc=${1:-}
if [ -z "$matc" ]; then
  cmake -S . -B build/test -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFACET_WERROR=ON >/dev/null
  cmake --build build/test --target matc
  matc=build/test/matc/matc
fi
matc=$(realpath "$matc")
[ -x "$matc" ] || { echo "update-goldens: '$matc' is not an executable" >&2; exit 2; }

folder=tests/golden/diagnostics
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

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
git status --short -- "$folder" 2>/dev/null || true
