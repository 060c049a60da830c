// What a package means, checked after its bytes (package.h, semanticError): for packages an app
// did not build (docs/security.md). read() guarantees every offset and size; this guarantees that
// what they hold is a material the runtime can use, as the compiler would have written it.
#include "facet/package/package.h"
#include "facet/package/package_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "facet/permutations/variant_key.h"
#include "rows.h"

namespace facet::package {
namespace {

// Names in messages: short, and without bytes that would garble a terminal.
std::string shown(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size() && i < 48; ++i) out += std::isprint(static_cast<unsigned char>(s[i])) ? s[i] : '?';
  return s.size() > 48 ? out + "..." : out;
}

std::string paramError(const Param& p) {
  const std::string what = "parameter '" + shown(p.name) + "'";
  if (!isValidName(p.name)) return what + ": a parameter name is an identifier (letters, digits, _)";
  for (double v : p.defaultValue)
    if (!std::isfinite(v)) return what + ": its default is not a finite number";
  if (p.rangeMin.has_value() != p.rangeMax.has_value()) return what + ": a range has both ends or none";
  if (p.rangeMin) {
    if (!std::isfinite(*p.rangeMin) || !std::isfinite(*p.rangeMax) || *p.rangeMin > *p.rangeMax)
      return what + ": its range is not a finite interval [min, max] with min <= max";
    if (!isTexture(p.type))
      for (double v : p.defaultValue)
        if (v < *p.rangeMin || v > *p.rangeMax) return what + ": its default lies outside its range";
  }
  bool unit = p.type == ParamType::Color || isTexture(p.type);
  for (double v : p.defaultValue) {
    if (unit && (v < 0.0 || v > 1.0)) return what + ": a colour or texture default lies in [0, 1]";
    if (p.type == ParamType::Bool && v != 0.0 && v != 1.0) return what + ": a bool default is 0 or 1";
    if (p.type == ParamType::Int && v != std::floor(v)) return what + ": an int default is a whole number";
  }
  return "";
}

// The parameters' places in the block, as the compiler's std140 layout gives them: a scalar
// aligned to 4 bytes, a vec2 to 8, a vec3 or vec4 to 16, no two sharing a byte, the block their
// end rounded up to 16 (where the preshader's derived members begin), and no two textures
// sharing a sampler slot. Overlapping parameters would have paramBlock() write one over the
// other, and a block declared larger than its parameters would put the derived members where the
// shaders do not read them.
std::string layoutError(const MaterialInfo& m) {
  std::vector<const Param*> inBlock;
  std::set<uint32_t> samplerSlots;
  uint64_t end = 0;
  for (const Param& p : m.params) {
    const std::string what = "parameter '" + shown(p.name) + "'";
    if (isTexture(p.type)) {
      if (p.offset != kNoTextureSlot && !samplerSlots.insert(p.offset).second)
        return what + ": sampler slot " + std::to_string(p.offset) + " is another texture parameter's";
      continue;
    }
    if (p.size == 0) continue;  // never read: no bytes
    const uint64_t components = p.defaultValue.size(), slotEnd = uint64_t(p.offset) + p.size;
    const uint32_t align = components == 1 ? 4 : components == 2 ? 8 : 16;
    if (p.size != 4 * components || slotEnd > m.paramBlockSize)
      return what + ": bytes " + std::to_string(p.offset) + ".." + std::to_string(slotEnd) + " do not hold its " +
             std::to_string(components) + " components inside the " + std::to_string(m.paramBlockSize) + "-byte block";
    if (p.offset % align != 0)
      return what + ": byte offset " + std::to_string(p.offset) + " is not a multiple of its std140 alignment, " +
             std::to_string(align);
    inBlock.push_back(&p);
    end = std::max(end, slotEnd);
  }
  std::sort(inBlock.begin(), inBlock.end(), [](const Param* a, const Param* b) { return a->offset < b->offset; });
  for (size_t i = 1; i < inBlock.size(); ++i) {
    const Param& a = *inBlock[i - 1];
    const Param& b = *inBlock[i];
    if (b.offset < a.offset + a.size)
      return "parameters '" + shown(a.name) + "' (bytes " + std::to_string(a.offset) + ".." +
             std::to_string(a.offset + a.size) + ") and '" + shown(b.name) + "' (bytes " + std::to_string(b.offset) +
             ".." + std::to_string(b.offset + b.size) + ") overlap";
  }
  const uint64_t rounded = (end + 15) / 16 * 16;
  if (m.paramBlockSize != rounded)
    return "the parameter block is " + std::to_string(m.paramBlockSize) + " bytes, but its parameters end at byte " +
           std::to_string(end) + ", which std140 rounds to " + std::to_string(rounded);
  return "";
}

}  // namespace

std::string shaderCodeError(Target target, std::span<const uint8_t> code) {
  // The shader's kind matches its slot: SPIR-V words in a SPIR-V slot (a driver handed text as
  // SPIR-V fails with VK_ERROR_UNKNOWN at best), text where text is expected.
  if (target == Target::Spirv) {
    if (code.size() < 20 || code.size() % 4 != 0 ||
        !(code[0] == 0x03 && code[1] == 0x02 && code[2] == 0x23 && code[3] == 0x07))
      return "is not SPIR-V (a whole number of little-endian words after the 5-word header, magic 0x07230203)";
    return "";
  }
  for (uint8_t c : code)
    if (c == 0) return "is text with a NUL byte in it";
  if (target == Target::GlslEs300) {
    static const std::string version = "#version 300 es";
    if (code.size() < version.size() || !std::equal(version.begin(), version.end(), code.begin()))
      return "is not GLSL ES 3.00 (it does not start with '#version 300 es')";
  }
  return "";
}

bool isDepthProgramKey(std::string_view key) {
  const std::optional<permutations::VariantKey> parsed = permutations::VariantKey::parse(key);
  return parsed && parsed->depthOnly;
}

std::string semanticError(const MaterialInfo& m, const std::vector<VariantInfo>& variants, const Preshader& preshader,
                          const std::vector<MslBinding>& mslBindings) {
  if (!isValidName(m.name))
    return "the material name '" + shown(m.name) + "' is not an identifier (letters, digits, _)";
  if (m.shading != "lit" && m.shading != "unlit")
    return "unknown shading model '" + shown(m.shading) + "' (lit, unlit)";
  static const std::set<std::string> blendings = {"opaque", "masked", "transparent", "additive"};
  if (!blendings.count(m.blending))
    return "unknown blending mode '" + shown(m.blending) + "' (opaque, masked, transparent, additive)";
  if (m.paramBlockSize > kMaxParamBlockBytes)
    return "the parameter block is " + std::to_string(m.paramBlockSize) + " bytes; the limit is " +
           std::to_string(kMaxParamBlockBytes);
  if (m.params.size() > kMaxParams)
    return std::to_string(m.params.size()) + " parameters; the limit is " + std::to_string(kMaxParams);
  std::set<std::string> names;
  for (const Param& p : m.params) {
    if (std::string e = paramError(p); !e.empty()) return e;
    if (!names.insert(p.name).second) return "parameter '" + shown(p.name) + "' is declared twice";
  }
  if (std::string e = layoutError(m); !e.empty()) return e;
  std::set<std::string> keys;
  bool shadowReceivers = false;
  for (const VariantInfo& v : variants) {
    auto key = permutations::VariantKey::parse(v.key);
    if (!key || key->toString() != v.key)
      return "variant key '" + shown(v.key) + "' is not a valid key (e.g. high.dir1)";
    shadowReceivers = shadowReceivers || key->receivesShadow();
    // The shadow pass draws only what casts: a transparent or additive material never does.
    if (key->depthOnly && !permutations::blendingCastsShadows(m.blending))
      return "variant '" + v.key + "' is a depth-only program, but a " + m.blending +
             " material casts no shadow (only opaque and masked ones do)";
    if (!keys.insert(v.key).second) return "variant '" + v.key + "' is stored twice";
    std::set<std::pair<Stage, Target>> slots;
    for (const ShaderInfo& s : v.shaders)
      if (!slots.insert({s.stage, s.target}).second)
        return "variant '" + v.key + "' has two " + toString(s.stage) + " " + toString(s.target) + " shaders";
  }
  if (std::string e = mslBindingsError(m, mslBindings, shadowReceivers); !e.empty()) return e;
  return preshaderSemanticError(m, preshader);
}

std::string semanticError(const Package& pkg) {
  // The rows' blob indices play no part in the checks.
  std::vector<VariantInfo> variants;
  for (const Variant& v : pkg.variants) variants.push_back(detail::variantRow(v, [](const Shader&) { return 0u; }));
  if (std::string e = semanticError(pkg.material, variants, pkg.preshader, pkg.mslBindings); !e.empty()) return e;
  for (const Variant& v : pkg.variants)
    for (const Shader& s : v.shaders)
      if (std::string e = shaderCodeError(s.target, s.code); !e.empty())
        return "the " + std::string(toString(s.stage)) + " " + toString(s.target) + " shader of variant '" + v.key +
               "' " + e;
  return "";
}

}  // namespace facet::package
