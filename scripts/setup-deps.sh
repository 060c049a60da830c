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
  # tests
  googletest libgtest-dev libgmock-dev
  # tests of tools/mesa_stats (Python, standard library only)
  python3
  # fuzzing (scripts/fuzz.sh): clang, its libFuzzer/ASan/UBSan runtimes (libclang_rt.fuzzer),
  # and llvm-symbolizer for readable sanitizer stack traces
  clang libclang-rt-14-dev llvm
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "setup-deps: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
