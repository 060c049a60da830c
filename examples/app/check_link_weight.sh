#!/bin/sh
# Fails when an example app (an engine's build) needs a library its backend does not, or contains
# the scene reader or the JSON library: an app links only facet_runtime_core and one backend.
#   check_link_weight.sh <binary> [vulkan|gl]   (vulkan when omitted)
# vulkan: needs libvulkan; no GL, EGL or OSMesa library.
# gl: the app's own EGL only; no OSMesa, no libGL/libGLESv2 (the runtime resolves GL through the
#     app's eglGetProcAddress), no Vulkan.
set -eu
binary="$1"
backend="${2:-vulkan}"
needed=$(readelf -d "$binary" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
echo "NEEDED: $(echo $needed)"
case "$backend" in
  vulkan) required=libvulkan; forbidden="libOSMesa libGL libEGL libGLESv2 libgbm"; other=createGlBackend ;;
  gl) required=libEGL; forbidden="libOSMesa libGL libGLESv2 libgbm libvulkan"; other=createVulkanBackend ;;
  *) echo "error: backend '$backend' is neither vulkan nor gl"; exit 2 ;;
esac
echo "$needed" | grep -q "^$required" || { echo "error: $binary does not need $required (is this the right binary?)"; exit 1; }
for lib in $forbidden; do
  # libGL must not match libGLESv2's own line and the other way round: compare up to ".so".
  if echo "$needed" | grep -q "^$lib\.so"; then echo "error: $binary needs $lib"; exit 1; fi
done
symbols=$(nm -C "$binary")
for symbol in 'facet::runtime::parseScene' 'facet::runtime::loadScene' 'nlohmann::' 'facet::runtime::SceneFrame' "$other" 'OSMesa'; do
  if echo "$symbols" | grep -q "$symbol"; then echo "error: $binary contains $symbol"; exit 1; fi
done
echo "ok: only the core and the $backend backend"
