#!/usr/bin/env bash
# The naming and bug checks of .clang-tidy over every C++ file the test configuration compiles
# (build/test's compile_commands.json; scripts/test.sh runs this after building it):
#   scripts/check-tidy.sh [build-dir]    lists each finding as file:line:col and exits 1 on any
set -euo pipefail
cd "$(dirname "$0")/.."

dir=${1:-build/test}
[ -f "$dir/compile_commands.json" ] || { echo "check-tidy: no $dir/compile_commands.json (configure it first: cmake --preset test)" >&2; exit 2; }

# Facet's own sources only: generated files (the post shaders) and third-party code are not ours.
root=$(pwd)
log=$(mktemp)
trap 'rm -f "$log"' EXIT
run-clang-tidy -p "$dir" -j "$(nproc)" -quiet \
  "^$root/(abi|cli|compiler|eval|gpu_stats|ibl|ir|lint|matc|package|permutations|runtime|scene|tests|texture|tools|examples)/" >"$log" 2>&1 || true
runs=$(grep -c '^clang-tidy' "$log" || true)
if [ "$runs" -eq 0 ]; then
  cat "$log" >&2
  echo "check-tidy: clang-tidy ran on no file" >&2
  exit 2
fi
# run-clang-tidy colours its output (--use-color) even into a file: strip the escapes before
# matching, or no finding would ever match.
findings=$(sed 's/\x1b\[[0-9;]*m//g' "$log" | grep -E ': (warning|error): ' | sort -u || true)
if [ -n "$findings" ]; then
  echo "$findings"
  echo "check-tidy: $(echo "$findings" | wc -l) finding(s) (.clang-tidy says which names are whose)" >&2
  exit 1
fi
echo "check-tidy: $runs files, no finding"
