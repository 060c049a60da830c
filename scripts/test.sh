#!/usr/bin/env bash
# Builds and runs the whole test suite, as CI does:
#   docs        scripts/check-docs.sh: no date, commit hash, tracker reference or path outside the
#               repository in docs/ or source comments (history files excepted)
#   format      scripts/check-format.sh: every C++ source as clang-format writes it
#   build/test  warnings as errors (-Werror), RelWithDebInfo; then scripts/check-tidy.sh over what it
#               compiled (.clang-tidy's naming and bug checks)
#   build/fuzz  materials, packages, scenes, images, .cube LUTs and glTF meshes fuzzed for FACET_FUZZ_SECONDS each (default 60): clang,
#               libFuzzer + ASan + UBSan (scripts/fuzz.sh); a crash, leak or hang fails the run
#   build/asan  AddressSanitizer + UndefinedBehaviorSanitizer, Debug (last, so the run closes
#               with ctest's summary line)
# Vulkan tests run with the Khronos validation layer on; a validation error fails the test.
# `scripts/test.sh --quick` runs only the first configuration (for iterating).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup-deps.sh
bash scripts/check-docs.sh
bash scripts/check-format.sh

# The configurations are CMakePresets.json's (build/<preset>): the same ones a developer uses.
jobs=$(nproc)
run_suite() {
  cmake --preset "$1"
  cmake --build --preset "$1" --parallel "$jobs"
  ctest --preset "$1" --parallel "$jobs"
}

run_suite test
[ "${1:-}" = "--quick" ] && exit 0
bash scripts/check-tidy.sh build/test

# The seed corpus and every past finding already ran in the suite above (test_fuzz_regressions);
# this explores new inputs for a bounded time, well inside CI's 90-minute limit.
bash scripts/fuzz.sh "${FACET_FUZZ_SECONDS:-60}"

# The asan test preset sets LSAN_OPTIONS to tests/lsan.supp: Mesa's OSMesa keeps a few hundred
# bytes per context for the process lifetime; those reports are Mesa's. Our code gets no suppression.
run_suite asan
