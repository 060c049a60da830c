#!/bin/sh
# Fails when a binary needs a library its role does not, or contains code it must not link.
#   check_link_weight.sh <binary> [vulkan|gl|compiler]   (vulkan when omitted)
# vulkan: an example app (an engine's build) on the Vulkan backend: needs libvulkan; no GL, EGL or
#     OSMesa library; no scene reader and no JSON library (an app links only facet_runtime_core and
#     one backend).
# gl: the same on the GL backend: the app's own EGL only; no OSMesa, no libGL/libGLESv2 (the
#     runtime resolves GL through the app's eglGetProcAddress), no Vulkan.
# compiler: matc, a build-time compiler: no Vulkan (neither the library nor a vk* symbol), no GL,
#     EGL or OSMesa, no tinygltf, no astcenc, none of the runtime (matc eval's renderer is
#     facet-eval's, matc texture's encoder facet-texture's).
set -eu
binary="$1"
role="${2:-vulkan}"
needed=$(readelf -d "$binary" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
echo "NEEDED: $(echo $needed)"
app_symbols="facet::runtime::parseScene facet::runtime::loadScene nlohmann:: facet::runtime::SceneFrame OSMesa"
case "$role" in
  vulkan) required=libvulkan; forbidden="libOSMesa libGL libEGL libGLESv2 libgbm"
          symbols_forbidden="$app_symbols createGlBackend"; vk_symbols=allowed ;;
  gl) required=libEGL; forbidden="libOSMesa libGL libGLESv2 libgbm libvulkan"
      symbols_forbidden="$app_symbols createVulkanBackend"; vk_symbols=forbidden ;;
  compiler) required=libspirv-cross-c; forbidden="libvulkan libOSMesa libGL libEGL libGLESv2 libgbm libtinygltf libastcenc"
            symbols_forbidden="facet::runtime::LoadedMaterial facet::runtime::SceneFrame createVulkanBackend createGlBackend tinygltf:: OSMesa"
            vk_symbols=forbidden ;;
  *) echo "error: role '$role' is neither vulkan, gl nor compiler"; exit 2 ;;
esac
echo "$needed" | grep -q "^$required" || { echo "error: $binary does not need $required (is this the right binary?)"; exit 1; }
for lib in $forbidden; do
  # libGL must not match libGLESv2's own line and the other way round: compare up to ".so".
  if echo "$needed" | grep -q "^$lib\.so"; then echo "error: $binary needs $lib"; exit 1; fi
done
symbols=$(nm -C "$binary")
for symbol in $symbols_forbidden; do
  if echo "$symbols" | grep -q "$symbol"; then echo "error: $binary contains $symbol"; exit 1; fi
done
# Vulkan's entry points (vkCreateInstance, ...), defined or called: a call through a table the
# binary loads itself would not show in NEEDED.
if [ "$vk_symbols" = forbidden ] && nm "$binary" | grep -Eq ' vk[A-Z][A-Za-z0-9]*$'; then
  echo "error: $binary contains Vulkan symbols: $(nm "$binary" | grep -E ' vk[A-Z][A-Za-z0-9]*$' | head -3 | tr '\n' ' ')"
  exit 1
fi
echo "ok: $binary links what a $role build needs"
