#!/usr/bin/env bash
# The C++ sources as clang-format (.clang-format; Debian 12's clang-format 14, which
# scripts/setup-deps.sh installs) writes them:
#   scripts/check-format.sh          lists every file that differs and exits 1 (CI)
#   scripts/check-format.sh --fix    rewrites them in place
# GLSL chunks and templates are not C++ and keep their hand layout.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=check
case "${1:-}" in
  "") ;;
  --fix) mode=fix ;;
  *) echo "usage: scripts/check-format.sh [--fix]" >&2; exit 2 ;;
esac

mapfile -t files < <(git ls-files -- '*.cpp' '*.h' ':!:tests/fuzz/*corpus*/**' ':!:tests/fuzz/*regressions/**')
if [ "$mode" = fix ]; then
  clang-format -i --style=file "${files[@]}"
  exit 0
fi

differ=()
for f in "${files[@]}"; do
  clang-format --style=file "$f" | cmp -s - "$f" || differ+=("$f")
done
if [ ${#differ[@]} -ne 0 ]; then
  printf '%s\n' "${differ[@]}" | sed 's/$/: not as clang-format writes it/'
  echo "check-format: ${#differ[@]} file(s) differ; run scripts/check-format.sh --fix and review the diff" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files as clang-format writes them"
