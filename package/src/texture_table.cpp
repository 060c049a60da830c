// TEXS section: textures the compiler generated for the shaders (e.g. the `lut` tier's specular
// table), which variants sample them, and the blob that holds their texels.
#include <algorithm>

#include "sections.h"

namespace facet::package::detail {

bool isGlslIdentifier(const std::string& s, size_t maxLength) {
  if (s.empty() || s.size() > maxLength) return false;
  auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!letter(s[0])) return false;
  return std::all_of(s.begin(), s.end(), [&](char c) { return letter(c) || (c >= '0' && c <= '9'); });
}

void encodeTextureTable(ByteWriter& out, const std::vector<TextureInfo>& textures) {
  out.u32(uint32_t(textures.size()));
  for (const TextureInfo& t : textures) {
    out.string(t.name);
    out.u32(t.width);
    out.u32(t.height);
    out.u8(uint8_t(t.format));
    out.u8(0);
    out.u16(0);
    out.u32(t.blob);
    out.u32(uint32_t(t.variants.size()));
    for (uint32_t v : t.variants) out.u32(v);
  }
}

void decodeTextureTable(ByteReader& in, uint64_t variantCount, const std::vector<BlobEntry>& blobs,
                        std::vector<TextureInfo>& textures) {
  uint32_t count = in.count(kMinTextureSize, "texture count");
  textures.reserve(count);
  for (uint32_t i = 0; i < count && in.ok(); ++i) {
    const uint64_t at = in.position();
    TextureInfo t;
    t.name = in.string("texture name");
    t.width = in.u32();
    t.height = in.u32();
    uint8_t format = in.u8();
    uint8_t reserved8 = in.u8();
    uint16_t reserved16 = in.u16();
    t.blob = in.u32();
    if (!in.ok()) return;
    const std::string what = "texture " + std::to_string(i) + " (entry at byte " + std::to_string(at) + ")";
    if (!isGlslIdentifier(t.name, kMaxTextureNameLength))
      return in.fail(what + " has name '" + t.name + "', not an identifier of 1.." +
                     std::to_string(kMaxTextureNameLength) + " letters, digits and '_'");
    for (const TextureInfo& earlier : textures)
      if (earlier.name == t.name) return in.fail(what + " repeats the name '" + t.name + "'");
    if (t.width == 0 || t.height == 0 || t.width > kMaxTextureSide || t.height > kMaxTextureSide)
      return in.fail(what + " '" + t.name + "' is " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                     "; each side must be 1.." + std::to_string(kMaxTextureSide));
    if (format > kLastTexelFormat)
      return in.fail(what + " '" + t.name + "' has unknown texel format " + std::to_string(format));
    t.format = TexelFormat(format);
    if (reserved8 != 0 || reserved16 != 0) return in.fail(what + " '" + t.name + "' has reserved bits set");
    if (t.blob >= blobs.size())
      return in.fail(what + " '" + t.name + "' refers to blob " + std::to_string(t.blob) + " but the package has " +
                     std::to_string(blobs.size()) + " blobs");
    // Both factors are ≤ 2^14 and the texel size is small: no overflow in 64 bits.
    const uint64_t bytes = uint64_t(t.width) * t.height * bytesPerTexel(t.format);
    if (blobs[t.blob].rawSize != bytes)
      return in.fail(what + " '" + t.name + "' needs " + std::to_string(bytes) + " bytes of texels but blob " +
                     std::to_string(t.blob) + " holds " + std::to_string(blobs[t.blob].rawSize));
    uint32_t users = in.count(kVariantIndexSize, "variant index count");
    t.variants.reserve(users);
    for (uint32_t j = 0; j < users && in.ok(); ++j) {
      uint32_t v = in.u32();
      if (!in.ok()) return;
      if (v >= variantCount)
        return in.fail(what + " '" + t.name + "' lists variant " + std::to_string(v) + " but the package has " +
                       std::to_string(variantCount) + " variants");
      // Strictly increasing: one way to write each list, so output stays canonical.
      if (!t.variants.empty() && v <= t.variants.back())
        return in.fail(what + " '" + t.name + "' lists variant " + std::to_string(v) + " after " +
                       std::to_string(t.variants.back()) + " (indices must increase)");
      t.variants.push_back(v);
    }
    textures.push_back(std::move(t));
  }
  in.expectEnd();
}

}  // namespace facet::package::detail
