// How a material texture is sampled: a scene object's `samplers` (docs/scene-format.md), which
// `matc import` writes from glTF 2.0's samplers (§3.8.4: wrapS, wrapT, magFilter, minFilter).
// Carried by a draw's TextureBinding (render_backend.h); each backend makes one sampler per
// distinct value and reuses it.
#pragma once

#include <cstdint>

namespace facet::runtime {

enum class TextureWrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };

struct TextureSampler {
  TextureWrap wrapS = TextureWrap::Repeat;
  TextureWrap wrapT = TextureWrap::Repeat;
  bool magLinear = true;  // magnification: LINEAR (true) or NEAREST
  bool minLinear = true;  // minification within a level
  bool mipmaps = true;    // false: level 0 only (glTF's minFilter NEAREST and LINEAR)
  bool mipLinear = true;  // between levels, when mipmaps: LINEAR (true) or NEAREST

  bool operator==(const TextureSampler&) const = default;
  // The fields packed into one number: a cache key.
  uint32_t key() const {
    return uint32_t(wrapS) | uint32_t(wrapT) << 2 | uint32_t(magLinear) << 4 | uint32_t(minLinear) << 5 |
           uint32_t(mipmaps) << 6 | uint32_t(mipLinear) << 7;
  }
};

}  // namespace facet::runtime
