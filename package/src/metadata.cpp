// META section: compiler version and material description.
#include "sections.h"

namespace facet::package::detail {

namespace {

constexpr uint8_t kHasRangeMin = 1;
constexpr uint8_t kHasRangeMax = 2;

}  // namespace

void encodeMetadata(ByteWriter& out, const std::string& compilerVersion, const MaterialInfo& material) {
  out.string(compilerVersion);
  out.string(material.name);
  out.string(material.shading);
  out.string(material.blending);
  out.u32(material.paramBlockSize);
  out.u8(material.doubleSided ? 1 : 0);
  out.u32(uint32_t(material.params.size()));
  for (const Param& p : material.params) {
    out.string(p.name);
    out.u8(uint8_t(p.type));
    out.u8(uint8_t((p.rangeMin ? kHasRangeMin : 0) | (p.rangeMax ? kHasRangeMax : 0)));
    out.u8(uint8_t(p.defaultValue.size()));
    out.u8(0);
    out.u32(p.offset);
    out.u32(p.size);
    for (double v : p.defaultValue) out.f64(v);
    if (p.rangeMin) out.f64(*p.rangeMin);
    if (p.rangeMax) out.f64(*p.rangeMax);
  }
}

void decodeMetadata(ByteReader& in, std::string& compilerVersion, MaterialInfo& material) {
  compilerVersion = in.string("compiler version");
  material.name = in.string("material name");
  material.shading = in.string("shading model");
  material.blending = in.string("blending mode");
  material.paramBlockSize = in.u32();
  const uint8_t doubleSided = in.u8();
  if (doubleSided > 1) {
    in.fail("material flag 'double sided' is " + std::to_string(doubleSided) + " (0 or 1)");
    return;
  }
  material.doubleSided = doubleSided == 1;
  uint32_t count = in.count(kMinParamSize, "parameter count");
  material.params.reserve(count);
  for (uint32_t i = 0; i < count && in.ok(); ++i) {
    Param p;
    uint64_t at = in.position();
    p.name = in.string("parameter name");
    uint8_t type = in.u8();
    uint8_t flags = in.u8();
    uint8_t components = in.u8();
    uint8_t reserved = in.u8();
    p.offset = in.u32();
    p.size = in.u32();
    if (!in.ok()) return;
    const std::string what = "parameter '" + p.name + "' at byte " + std::to_string(at);
    if (type > kLastParamType) {
      in.fail(what + " has unknown type " + std::to_string(type));
      return;
    }
    p.type = ParamType(type);
    if ((flags & ~(kHasRangeMin | kHasRangeMax)) != 0 || reserved != 0) {
      in.fail(what + " has reserved bits set");
      return;
    }
    if (!defaultCountMatches(p.type, components)) {
      in.fail(what + " of type " + toString(p.type) + " has " + std::to_string(components) + " default components");
      return;
    }
    // A parameter either has a slot inside the block (size = 4 bytes per component) or none
    // (size 0: the material never reads it, so the compiler gave it no uniform).
    const uint64_t slotEnd = uint64_t(p.offset) + p.size;
    if (isTexture(p.type) && (p.size != 0 || (p.offset >= 8 && p.offset != kNoTextureSlot))) {
      in.fail(what + " is a texture with sampler slot " + std::to_string(p.offset) + " (0..7, or none)");
      return;
    }
    if (!isTexture(p.type) && p.size != 0 && (p.size != 4u * components || slotEnd > material.paramBlockSize)) {
      in.fail(what + " occupies bytes " + std::to_string(p.offset) + ".." + std::to_string(slotEnd) +
              ", which do not fit its type inside the " + std::to_string(material.paramBlockSize) +
              "-byte parameter block");
      return;
    }
    p.defaultValue.resize(components);
    for (double& v : p.defaultValue) v = in.f64();
    if (flags & kHasRangeMin) p.rangeMin = in.f64();
    if (flags & kHasRangeMax) p.rangeMax = in.f64();
    material.params.push_back(std::move(p));
  }
  in.expectEnd();
}

}  // namespace facet::package::detail
