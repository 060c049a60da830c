#!/bin/sh
# Fails when the example app (an engine's build) needs a GL/OSMesa/EGL library or contains the
# scene reader or the JSON library: an app links only facet_runtime_core and one backend.
set -eu
binary="$1"
needed=$(readelf -d "$binary" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
echo "NEEDED: $(echo $needed)"
echo "$needed" | grep -q '^libvulkan' || { echo "error: $binary does not need libvulkan (is this the right binary?)"; exit 1; }
for lib in libOSMesa libGL libEGL libGLESv2 libgbm; do
  if echo "$needed" | grep -q "^$lib"; then echo "error: $binary needs $lib"; exit 1; fi
done
symbols=$(nm -C "$binary")
for symbol in 'facet::runtime::parseScene' 'facet::runtime::loadScene' 'nlohmann::' 'facet::runtime::SceneFrame' 'createGlBackend'; do
  if echo "$symbols" | grep -q "$symbol"; then echo "error: $binary contains $symbol"; exit 1; fi
done
echo "ok: only the core and the Vulkan backend"
