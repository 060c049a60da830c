#!/usr/bin/env bash
# Installs every build and test dependency of Facet from Debian 12 packages.
# Idempotent; run as root (or with sudo). Nothing is downloaded from outside Debian.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build ccache pkg-config git
  # shader toolchain: GLSL -> SPIR-V -> validate/optimise -> MSL
  glslang-dev glslang-tools spirv-tools libspirv-cross-c-shared-dev spirv-headers
  # Vulkan on Mesa lavapipe, with validation layers for tests
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  # GL on OSMesa (and GLES 3 via EGL surfaceless)
  libosmesa6-dev libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  # maths and utility libraries
  libglm-dev libzstd-dev libxxhash-dev nlohmann-json3-dev libcli11-dev libstb-dev
  # glTF 2.0 meshes in scenes (runtime/src/gltf_mesh.cpp)
  libtinygltf-dev
  # mobile data formats: vertex-cache and overdraw optimisation of meshes (meshoptimizer) and
  # ASTC texture encoding and decoding (Arm's astcenc)
  libmeshoptimizer-dev libastcenc-dev
  # JPEG images (glTF content is mostly JPEG): libjpeg-turbo, runtime/src/jpeg.cpp
  libjpeg62-turbo-dev
  # tests (python3-jsonschema: the SARIF schema check of matc lint's report; libexpat1-dev: the
  # XML check of matc tune's plot)
  googletest libgtest-dev libgmock-dev python3-jsonschema libexpat1-dev
  # tests of tools/mesa_stats (Python, standard library only)
  python3
  # fuzzing (scripts/fuzz.sh): clang, its libFuzzer/ASan/UBSan runtimes (libclang_rt.fuzzer),
  # and llvm-symbolizer for readable sanitizer stack traces
  clang libclang-rt-14-dev llvm
  # the code's layout and naming (scripts/check-format.sh, scripts/check-tidy.sh)
  clang-format clang-tidy
  # compile-path benchmarks (tests/ target bench_compile, not run by ctest): Google Benchmark,
  # and Filament's matc as the peer it is measured against
  libbenchmark-dev libfilament-tools
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup-deps: all ${#packages[@]} packages already installed"
else
  echo "setup-deps: installing ${#missing[@]} packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The published SARIF 2.1.0 JSON schema, for the test of matc lint's SARIF report. No Debian
# package ships it; the npm package @microsoft/jest-sarif does (lib/schemas/sarif-2.1.0-rtm.5.json,
# the schema SchemaStore serves as sarif-2.1.0.json). Fetched once, pinned by version.
sarif_schema=/usr/local/share/facet/sarif-schema-2.1.0.json
if [ ! -s "$sarif_schema" ]; then
  if ! command -v npm >/dev/null; then
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends npm
  fi
  tmp=$(mktemp -d)
  (cd "$tmp" && npm pack --silent @microsoft/jest-sarif@1.0.0-beta.0 >/dev/null &&
    tar xzf microsoft-jest-sarif-1.0.0-beta.0.tgz package/lib/schemas/sarif-2.1.0-rtm.5.json)
  $SUDO install -D -m 644 "$tmp/package/lib/schemas/sarif-2.1.0-rtm.5.json" "$sarif_schema"
  rm -rf "$tmp"
  echo "setup-deps: SARIF 2.1.0 schema -> $sarif_schema"
fi
