#!/usr/bin/env bash
# Builds Mesa's open mobile-GPU shader compilers (panfrost for Mali Bifrost/Valhall, freedreno ir3
# for Adreno) with their drm-shim fake devices, from Debian 12's own Mesa source package (22.3.6),
# into a cache folder outside the source tree. tools/mesa_stats.py uses the result to collect
# shader-db statistics (docs/mesa-statistics.md).
#
# Optional: not part of the README's build, and CI does not depend on it. Idempotent: a stamp file
# makes a second run do nothing. Needs root (or sudo) once, for the deb-src entry and build deps.
#
#   scripts/build-mesa-shader-compilers.sh [--prefix-only]
#     MESA_CACHE_DIR   where to put source, build and install (default below)
#     MESA_JOBS        ninja -j (default 2; the build runs under nice -n 19)
#   --prefix-only      print the install prefix (for tools) and exit, building nothing
set -euo pipefail

cache_dir="${MESA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/facet/mesa}"
prefix="$cache_dir/install"
stamp="$cache_dir/.built-22.3"
jobs="${MESA_JOBS:-2}"

if [ "${1:-}" = "--prefix-only" ]; then echo "$prefix"; exit 0; fi

if [ -f "$stamp" ]; then
  echo "build-mesa-shader-compilers: already built in $prefix (remove $stamp to rebuild)"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

# 1. A deb-src entry, so `apt-get source mesa` can fetch Debian's source package.
if ! grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  echo "build-mesa-shader-compilers: adding a deb-src entry for bookworm"
  $SUDO tee /etc/apt/sources.list.d/facet-deb-src.sources >/dev/null <<'EOF'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
  $SUDO apt-get update -qq
fi

# 2. Only what the meson configuration below needs (a subset of `apt-get build-dep mesa`, which
#    would pull LLVM, X11, Wayland and Vulkan headers).
deps=(
  dpkg-dev            # apt-get source (dpkg-source unpacks and applies Debian's patches)
  meson ninja-build pkg-config bison flex
  python3-mako        # Mesa's code generators
  libdrm-dev          # panfrost and freedreno winsys
  zlib1g-dev libzstd-dev libexpat1-dev
  build-essential
)
missing=()
for p in "${deps[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "build-mesa-shader-compilers: installing ${missing[*]}"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Debian's meson and mako live in the system Python; a pyenv/venv python3 first on PATH lacks mako.
export PATH="/usr/bin:$PATH"

# 3. The source package.
mkdir -p "$cache_dir"
src_dir=$(find "$cache_dir" -maxdepth 1 -type d -name 'mesa-22.3*' | sort | tail -n1)
if [ -z "$src_dir" ]; then
  (cd "$cache_dir" && apt-get source -qq mesa)
  src_dir=$(find "$cache_dir" -maxdepth 1 -type d -name 'mesa-22.3*' | sort | tail -n1)
fi
if [ -z "$src_dir" ]; then
  echo "build-mesa-shader-compilers: error: apt-get source mesa gave no mesa-22.3* folder in $cache_dir" >&2
  exit 1
fi
echo "build-mesa-shader-compilers: source $src_dir"

# 4. Configure: gallium panfrost + freedreno, surfaceless EGL + GLES only, drm-shim, no LLVM,
#    no Vulkan, no X11/Wayland/GBM.
build_dir="$cache_dir/build"
if [ ! -f "$build_dir/build.ninja" ]; then
  meson setup "$build_dir" "$src_dir" \
    --prefix="$prefix" --libdir=lib --buildtype=release -Db_ndebug=true \
    -Dgallium-drivers=panfrost,freedreno -Dvulkan-drivers= \
    -Dplatforms= -Degl=enabled -Dgbm=disabled -Dglx=disabled \
    -Dopengl=true -Dgles1=disabled -Dgles2=enabled -Dshared-glapi=enabled \
    -Dllvm=disabled -Dshared-llvm=disabled -Dvalgrind=disabled -Dlibunwind=disabled \
    -Dgallium-vdpau=disabled -Dgallium-va=disabled -Dgallium-xa=disabled \
    -Dgallium-nine=false -Dgallium-opencl=disabled -Dgallium-omx=disabled \
    -Dlmsensors=disabled -Dbuild-tests=false \
    -Dtools=drm-shim
fi

# 5. Build only what compiling shaders needs (not Mesa's standalone tools such as computerator or
#    glsl_compiler, which `ninja` alone would also build), gently: two cores are shared.
targets=(
  src/egl/libEGL.so.1.0.0 src/mapi/es2api/libGLESv2.so.2.0.0 src/mapi/shared-glapi/libglapi.so.0.0.0
  src/gallium/targets/dri/libgallium_dri.so
  src/panfrost/drm-shim/libpanfrost_noop_drm_shim.so src/freedreno/drm-shim/libfreedreno_noop_drm_shim.so
)
nice -n 19 ninja -C "$build_dir" -j "$jobs" "${targets[@]}"

# 6. Install those by hand into the prefix (`meson install` would build everything first). The
#    loader finds a driver by the kernel driver's name: panfrost_dri.so, msm_dri.so (freedreno).
mkdir -p "$prefix/lib/dri"
cp -f "$build_dir/src/egl/libEGL.so.1.0.0" "$prefix/lib/libEGL.so.1"
cp -f "$build_dir/src/mapi/es2api/libGLESv2.so.2.0.0" "$prefix/lib/libGLESv2.so.2"
cp -f "$build_dir/src/mapi/shared-glapi/libglapi.so.0.0.0" "$prefix/lib/libglapi.so.0"
cp -f "$build_dir/src/gallium/targets/dri/libgallium_dri.so" "$prefix/lib/dri/libgallium_dri.so"
ln -sf libgallium_dri.so "$prefix/lib/dri/panfrost_dri.so"
ln -sf libgallium_dri.so "$prefix/lib/dri/msm_dri.so"
cp -f "$build_dir/src/panfrost/drm-shim/libpanfrost_noop_drm_shim.so" "$prefix/lib/"
cp -f "$build_dir/src/freedreno/drm-shim/libfreedreno_noop_drm_shim.so" "$prefix/lib/"
date -u +%FT%TZ >"$stamp"
echo "build-mesa-shader-compilers: done; prefix $prefix"
