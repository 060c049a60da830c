// VARS section: variant keys and the blob each shader's code lives in.
#include "sections.h"

namespace facet::package::detail {

void encodeVariantTable(ByteWriter& out, const std::vector<VariantInfo>& variants) {
  out.u32(uint32_t(variants.size()));
  for (const VariantInfo& v : variants) {
    out.string(v.key);
    out.u32(uint32_t(v.shaders.size()));
    for (const ShaderInfo& s : v.shaders) {
      out.u8(uint8_t(s.stage));
      out.u8(uint8_t(s.target));
      out.u16(0);
      out.u32(s.blob);
    }
  }
}

void decodeVariantTable(ByteReader& in, std::vector<VariantInfo>& variants) {
  uint32_t count = in.count(kMinVariantSize, "variant count");
  variants.reserve(count);
  for (uint32_t i = 0; i < count && in.ok(); ++i) {
    VariantInfo v;
    v.key = in.string("variant key");
    uint32_t shaders = in.count(kShaderInfoSize, "shader count");
    v.shaders.reserve(shaders);
    for (uint32_t j = 0; j < shaders && in.ok(); ++j) {
      uint64_t at = in.position();
      uint8_t stage = in.u8();
      uint8_t target = in.u8();
      uint16_t reserved = in.u16();
      uint32_t blob = in.u32();
      if (!in.ok()) return;
      const std::string what =
          "shader " + std::to_string(j) + " of variant '" + v.key + "' at byte " + std::to_string(at);
      if (stage > kLastStage) return in.fail(what + " has unknown stage " + std::to_string(stage));
      if (target > kLastTarget) return in.fail(what + " has unknown target " + std::to_string(target));
      if (reserved != 0) return in.fail(what + " has reserved bits set");
      v.shaders.push_back({Stage(stage), Target(target), blob});
    }
    variants.push_back(std::move(v));
  }
  in.expectEnd();
}

}  // namespace facet::package::detail
