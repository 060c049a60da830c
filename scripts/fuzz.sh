#!/usr/bin/env bash
# Fuzzes the material front end (lexer, parser, checker, GLSL emission), the package reader, the
# scene loader, the image decoders, the colour-grading .cube reader, the glTF loader and matc tune's
# budgets and tuning files, each for a bounded time:
#   scripts/fuzz.sh [seconds] [target...]   default 60 s per target; all targets, or those named
# Builds the clang configuration build/fuzz (-DFACET_FUZZ=ON: libFuzzer + ASan + UBSan) and runs
# tests/fuzz/fuzz_material from the seed corpus tests/fuzz/corpus/ and every past finding in
# tests/fuzz/regressions/, with the dictionary tests/fuzz/material.dict; then
# tests/fuzz/fuzz_package from real packages (tests/fuzz/package_corpus/) and its past findings
# (tests/fuzz/package_regressions/), most mutants resealed with a recomputed checksum; then
# tests/fuzz/fuzz_scene from examples/scenes/ (and tests/data/scenes/shadows/) and tests/fuzz/fuzz_image from examples/scenes/textures/ and
# tests/fuzz/image_corpus/ (Radiance files), tests/fuzz/fuzz_ktx2 (KTX2 reader, ASTC decoding) from
# tests/fuzz/ktx2_corpus/ and its past findings (tests/fuzz/ktx2_regressions/), tests/fuzz/fuzz_cube from examples/scenes/looks/ and
# tests/fuzz/cube_corpus/, then tests/fuzz/fuzz_gltf from tests/fuzz/gltf_corpus/ and its
# past findings (tests/fuzz/gltf_regressions/), with tests/fuzz/gltf.dict, then
# tests/fuzz/fuzz_tune_files from examples/lint/ and examples/materials/ (the budgets file and
# the committed tuning files) and its past findings (tests/fuzz/tune_regressions/). New inputs
# go to a temporary working corpus, so the committed corpus never churns.
#
# Fails (non-zero) on any crash, sanitizer report, leak, hang (> 5 s per input) or out-of-memory
# (> 2 GiB); the input that did it is left in build/fuzz/crashes/. To turn it into a regression:
#   build/fuzz/tests/fuzz/fuzz_material -minimize_crash=1 -runs=100000 \
#     -exact_artifact_path=tests/fuzz/regressions/<name>.mat build/fuzz/crashes/<file>
# (fuzz_package: tests/fuzz/package_regressions/<name>.matpkg; fuzz_gltf: tests/fuzz/gltf_regressions/;
# fuzz_ktx2: tests/fuzz/ktx2_regressions/; fuzz_tune_files: tests/fuzz/tune_regressions/) then fix the bug;
# tests/ir/test_fuzz_regressions.cpp, tests/package/test_package.cpp, tests/runtime/test_gltf_hostile.cpp,
# tests/texture/test_ktx2.cpp and tests/tune/test_tune.cpp replay those folders in every test run.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "usage: scripts/fuzz.sh [seconds] [target...]" >&2
  exit 2
fi
targets=(fuzz_material fuzz_package fuzz_scene fuzz_image fuzz_ktx2 fuzz_cube fuzz_gltf fuzz_tune_files)
if [ $# -gt 1 ]; then
  shift
  for t in "$@"; do
    [[ " ${targets[*]} " == *" $t "* ]] || { echo "scripts/fuzz.sh: unknown target '$t' (targets: ${targets[*]})" >&2; exit 2; }
  done
  targets=("$@")
fi

bash scripts/setup-deps.sh

dir=build/fuzz
cmake --preset fuzz >/dev/null  # build/fuzz, CMakePresets.json
cmake --build --preset fuzz --target "${targets[@]}" --parallel "$(nproc)"
mkdir -p "$dir/crashes"

# fuzz <target> <dict or ""> <committed corpus folders...>
fuzz() {
  local target=$1 dict=$2
  shift 2
  [[ " ${targets[*]} " == *" $target "* ]] || return 0
  local fuzzer=$(pwd)/$dir/tests/fuzz/$target
  local work
  work=$(mktemp -d "$(pwd)/$dir/work.XXXXXX")
  local log=$dir/$target.log
  echo "fuzz: running $target for ${seconds}s (log: $log)"
  local status=0
  # The first corpus folder is the writable working corpus; the committed ones are read only.
  "$fuzzer" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 -print_final_stats=1 \
    ${dict:+-dict=$dict} -artifact_prefix="$(pwd)/$dir/crashes/" \
    "$work" "$@" >"$log" 2>&1 || status=$?
  rm -rf "$work"

  local runs cov features
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  [ -n "$runs" ] || runs=$(sed -n 's/^#\([0-9]*\).*/\1/p' "$log" | tail -n 1)  # no stats after a crash
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1 | tr -dc '0-9' || true)
  features=$(grep -o 'ft: [0-9]*' "$log" | tail -n 1 | tr -dc '0-9' || true)
  if [ "$status" -ne 0 ]; then
    tail -n 60 "$log"
    echo "fuzz: $target FAILED (exit $status) after ${runs:-?} runs; the input is in $dir/crashes/:"
    ls -t "$dir/crashes" | head -n 5 | sed "s|^|  $dir/crashes/|"
    echo "fuzz: reproduce with  $dir/tests/fuzz/$target <input>  (minimise into the regressions folder, see the top of this script)"
    exit 1
  fi
  echo "fuzz: $target OK, ${runs:-?} runs in ${seconds}s, coverage ${cov:-?} edges, ${features:-?} features, no crashes"
}

fuzz fuzz_material tests/fuzz/material.dict tests/fuzz/corpus tests/fuzz/regressions
fuzz fuzz_package "" tests/fuzz/package_corpus tests/fuzz/package_regressions
fuzz fuzz_scene "" examples/scenes tests/data/scenes/shadows
fuzz fuzz_image "" examples/scenes/textures tests/fuzz/image_corpus tests/fuzz/image_regressions
fuzz fuzz_ktx2 "" tests/fuzz/ktx2_corpus tests/fuzz/ktx2_regressions
fuzz fuzz_cube "" examples/scenes/looks tests/fuzz/cube_corpus
fuzz fuzz_gltf tests/fuzz/gltf.dict tests/fuzz/gltf_corpus tests/fuzz/gltf_regressions
fuzz fuzz_tune_files "" examples/lint examples/materials tests/fuzz/tune_regressions
