// ASTC LDR blocks through Arm's astcenc (Debian libastcenc): encoding RGBA8 levels at build time
// (facet-texture, `matc texture`) and decoding them back to RGBA8 where a GPU cannot sample ASTC
// (the runtime's fallback, runtime/src/compressed_texture.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace facet::texture {

// What a texture holds, which decides how astcenc weighs its error.
enum class TextureUsage {
  Color,   // sRGB-encoded colour: astcenc's LDR_SRGB profile, errors weighed on the encoded values
  Normal,  // a tangent-space normal map in RGB (x, y, z mapped to [0, 1]): linear, alpha ignored
  Data,    // linear values (masks, roughness): LDR profile, every channel weighed alike
};

struct AstcSettings {
  uint32_t blockWidth = 4;
  uint32_t blockHeight = 4;
  float quality = 60.0f;  // astcenc's effort 0..100 (ASTCENC_PRE_MEDIUM is 60)
  TextureUsage usage = TextureUsage::Color;
  unsigned threads = 1;  // 1 keeps the output independent of scheduling
};

// Encodes one RGBA8 level (width x height, rows tightly packed) into ASTC blocks: ceil(w/bw) x
// ceil(h/bh) blocks of 16 bytes. nullopt with *error (astcenc's reason) when astcenc refuses.
std::optional<std::vector<uint8_t>> encodeAstc(std::span<const uint8_t> rgba, uint32_t width, uint32_t height,
                                               const AstcSettings& settings, std::string* error);

// Decodes one level of ASTC blocks to RGBA8; `srgb` selects the sRGB profile (the values stay
// sRGB-encoded: the sampler of an RGBA8 sRGB texture decodes them, as it would the ASTC ones).
// Blocks outside the LDR profile decode to astcenc's error colour (magenta), as on a GPU.
std::optional<std::vector<uint8_t>> decodeAstc(std::span<const uint8_t> blocks, uint32_t width, uint32_t height,
                                               uint32_t blockWidth, uint32_t blockHeight, bool srgb,
                                               std::string* error);

}  // namespace facet::texture
