#include "facet/compiler/preshader.h"

#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include "facet/abi/shader_abi.h"
#include "facet/compiler/glsl_library.h"
#include "facet/ir/uniform_values.h"

namespace facet::compiler {
namespace {

using package::PreshaderOp;
using package::PreshaderOpcode;

// Builds ops on the preshader's registers, one register per IR value (values are interned, so a
// shared subexpression is computed once). Scalars are kept broadcast to all four lanes, which
// gives GLSL's scalar-vector arithmetic with per-component ops.
class ProgramBuilder {
 public:
  ProgramBuilder(const ir::Material& material, const ParamLayout& params) : material_(material), params_(params) {}

  // The register holding `id`, emitting what computes it; nullopt when an op has no program
  // form or the registers run out (the caller rolls back with mark/restore).
  std::optional<uint8_t> value(ir::ValueId id) {
    if (auto it = regs_.find(id); it != regs_.end()) return it->second;
    const ir::Value& v = material_.surface.value(id);
    if (!isFloat(v.type)) return std::nullopt;
    std::optional<uint8_t> out;
    switch (v.op) {
      case ir::Op::Constant: {
        const bool scalar = v.type == ir::Type::Float;
        std::array<float, 4> k{};
        for (int i = 0; i < 4; ++i) k[size_t(i)] = float(v.constant[scalar ? 0 : size_t(i)]);
        out = constant(k);
        break;
      }
      case ir::Op::Param: out = param(v); break;
      case ir::Op::Swizzle: out = swizzle(v); break;
      case ir::Op::Construct:  // vecN(x) of a broadcast scalar is that register
        if (v.args.size() == 1 && material_.surface.value(v.args[0]).type == ir::Type::Float) out = value(v.args[0]);
        break;
      case ir::Op::Neg: {
        auto a = value(v.args[0]);
        auto zero = constant({0, 0, 0, 0});
        if (a && zero) out = binary(PreshaderOpcode::Sub, *zero, *a);
        break;
      }
      case ir::Op::Add:
      case ir::Op::Sub:
      case ir::Op::Mul:
      case ir::Op::Div: {
        auto a = value(v.args[0]);
        auto b = a ? value(v.args[1]) : std::nullopt;
        PreshaderOpcode code = v.op == ir::Op::Add   ? PreshaderOpcode::Add
                               : v.op == ir::Op::Sub ? PreshaderOpcode::Sub
                               : v.op == ir::Op::Mul ? PreshaderOpcode::Mul
                                                     : PreshaderOpcode::Div;
        if (a && b) out = binary(code, *a, *b);
        break;
      }
      case ir::Op::Builtin: out = builtin(v); break;
      default: break;
    }
    if (out) regs_[id] = *out;
    return out;
  }

  std::optional<uint8_t> constant(std::array<float, 4> k) {
    auto r = fresh();
    if (r) push({PreshaderOpcode::Constant, *r, 0, 0, 0, 0, k});
    return r;
  }
  std::optional<uint8_t> binary(PreshaderOpcode code, uint8_t a, uint8_t b) {
    auto r = fresh();
    if (r) push({code, *r, a, b, 0, 0, {}});
    return r;
  }
  std::optional<uint8_t> clamp(uint8_t a, float lo, float hi) {
    auto r = fresh();
    if (r) push({PreshaderOpcode::Clamp, *r, a, 0, 0, 0, {lo, hi, 0, 0}});
    return r;
  }
  void store(uint8_t a, uint32_t offset, uint32_t components) {
    push({PreshaderOpcode::Store, 0, a, 0, offset, components, {}});
  }

  struct Mark {
    size_t ops;
    unsigned next;
    std::map<ir::ValueId, uint8_t> regs;
  };
  Mark mark() const { return {ops_.size(), next_, regs_}; }
  void restore(const Mark& m) {
    ops_.resize(m.ops);
    next_ = m.next;
    regs_ = m.regs;
  }
  std::vector<PreshaderOp> take() { return std::move(ops_); }
  // The surface expressions may use all registers but kDerivationRegisters, which the models'
  // derivations then take, one group at a time (at most 12 each): those never run out.
  static constexpr unsigned kDerivationRegisters = 16;
  void startDerivations() { limit_ = package::kPreshaderRegisters; }
  // A group's registers are free again once it has stored its members: no later group reads them.
  unsigned groupStart() const { return next_; }
  void endGroup(unsigned start) { next_ = start; }

 private:
  static bool isFloat(ir::Type t) {
    return t == ir::Type::Float || t == ir::Type::Vec2 || t == ir::Type::Vec3 || t == ir::Type::Vec4;
  }
  std::optional<uint8_t> fresh() {
    if (next_ >= limit_) return std::nullopt;
    return uint8_t(next_++);
  }
  void push(PreshaderOp op) { ops_.push_back(op); }

  std::optional<uint8_t> param(const ir::Value& v) {
    for (const ParamSlot& slot : params_.slots) {
      if (slot.name != v.name) continue;
      if (slot.size == 0) return std::nullopt;
      auto r = fresh();
      if (r) push({PreshaderOpcode::LoadParam, *r, 0, 0, slot.offset, slot.size / 4, {}});
      return r;
    }
    return std::nullopt;
  }

  std::optional<uint8_t> swizzle(const ir::Value& v) {
    auto a = value(v.args[0]);
    if (!a || v.name.empty() || v.name.size() > 4) return std::nullopt;
    uint32_t selector = 0;
    for (size_t lane = 0; lane < 4; ++lane) {
      // A scalar result is broadcast: every lane takes the one component.
      const char c = v.name[v.name.size() == 1 ? 0 : std::min(lane, v.name.size() - 1)];
      const std::string letters[] = {"xyzw", "rgba", "stpq"};
      std::optional<uint32_t> index;
      for (const std::string& set : letters)
        if (size_t at = set.find(c); at != std::string::npos) index = uint32_t(at);
      if (!index) return std::nullopt;
      selector |= *index << (2 * lane);
    }
    auto r = fresh();
    if (r) push({PreshaderOpcode::Swizzle, *r, *a, 0, selector, 0, {}});
    return r;
  }

  // The built-ins a parameter-only expression uses that the ops express: clamp, and max / min
  // against a constant scalar (one Clamp op, the other bound the largest finite float); mix as
  // a + (b − a) · t, the IR's own evaluation of it (ir/src/evaluate.cpp); sqrt.
  std::optional<uint8_t> builtin(const ir::Value& v) {
    const auto scalarConstant = [&](ir::ValueId id) -> std::optional<float> {
      const ir::Value& k = material_.surface.value(id);
      if (k.op != ir::Op::Constant || k.type != ir::Type::Float) return std::nullopt;
      return float(k.constant[0]);
    };
    constexpr float kLargest = std::numeric_limits<float>::max();
    if (v.name == "clamp" && v.args.size() == 3) {
      const auto lo = scalarConstant(v.args[1]), hi = scalarConstant(v.args[2]);
      auto a = lo && hi ? value(v.args[0]) : std::nullopt;
      return a ? clamp(*a, *lo, *hi) : std::nullopt;
    }
    if ((v.name == "max" || v.name == "min") && v.args.size() == 2) {
      const auto bound = scalarConstant(v.args[1]);
      auto a = bound ? value(v.args[0]) : std::nullopt;
      if (!a) return std::nullopt;
      return v.name == "max" ? clamp(*a, *bound, kLargest) : clamp(*a, -kLargest, *bound);
    }
    if (v.name == "mix" && v.args.size() == 3) {
      auto a = value(v.args[0]);
      auto b = a ? value(v.args[1]) : std::nullopt;
      auto t = b ? value(v.args[2]) : std::nullopt;
      auto span = t ? binary(PreshaderOpcode::Sub, *b, *a) : std::nullopt;
      auto scaled = span ? binary(PreshaderOpcode::Mul, *span, *t) : std::nullopt;
      return scaled ? binary(PreshaderOpcode::Add, *a, *scaled) : std::nullopt;
    }
    if (v.name == "sqrt" && v.args.size() == 1) {
      auto a = value(v.args[0]);
      if (!a) return std::nullopt;
      auto r = fresh();
      if (r) push({PreshaderOpcode::Sqrt, *r, *a, 0, 0, 0, {}});
      return r;
    }
    return std::nullopt;
  }

  const ir::Material& material_;
  const ParamLayout& params_;
  std::vector<PreshaderOp> ops_;
  std::map<ir::ValueId, uint8_t> regs_;
  unsigned next_ = 0;
  unsigned limit_ = package::kPreshaderRegisters - kDerivationRegisters;
};

// A surface output's register: what the program writes, or its default (ir::outputs()).
std::optional<uint8_t> output(ProgramBuilder& b, const ir::Material& material, const char* name) {
  if (auto id = ir::outputValue(material, name)) {
    if (!ir::isUniformOnly(material, *id)) return std::nullopt;
    return b.value(*id);
  }
  const ir::OutputInfo* info = ir::findOutput(name);
  if (!info) return std::nullopt;
  const bool scalar = info->type == ir::Type::Float;
  std::array<float, 4> k{};
  for (int i = 0; i < 4; ++i) k[size_t(i)] = float(info->defaultValue[scalar ? 0 : size_t(i)]);
  return b.constant(k);
}

// The registers of the models' inputs, clamped as their chunks clamp them
// (chunks/shading_standard.glsl, clear_coat_ambient.glsl, anisotropy_frame.glsl, sheen_layer.glsl);
// unset where an input cannot be preshaded or its model is not the material's.
struct Inputs {
  std::optional<uint8_t> baseColor, metallic, reflectance, roughness;
  std::optional<uint8_t> clearCoat, clearCoatRoughness, anisotropy, sheenColor, sheenRoughness;
};

// Whether the output reads a parameter (a default or a constant expression does not).
bool readsParameter(const ir::Material& material, const char* name) {
  auto id = ir::outputValue(material, name);
  return id && ir::readsParameter(material, *id);
}

bool writes(const ir::Material& material, const char* name) { return ir::outputValue(material, name).has_value(); }

Inputs clampedInputs(ProgramBuilder& b, const ir::Material& material) {
  Inputs in;
  auto clamped = [&](const char* name, float lo) -> std::optional<uint8_t> {
    ProgramBuilder::Mark m = b.mark();
    auto r = output(b, material, name);
    if (r) r = b.clamp(*r, lo, 1.0f);
    if (!r) b.restore(m);
    return r;
  };
  in.baseColor = clamped("baseColor", 0.0f);
  in.metallic = clamped("metallic", 0.0f);
  in.reflectance = clamped("reflectance", 0.0f);
  in.roughness = clamped("roughness", minPerceptualRoughness());
  // The other models' inputs exist in the shaders only where the material writes the output that
  // brings the model (compiler/src/assemble.cpp: writesClearCoat, writesAnisotropy, writesSheenLayer),
  // and the cloth model reads none of the standard model's layers.
  if (!material.cloth && writes(material, "clearCoat")) {
    in.clearCoat = clamped("clearCoat", 0.0f);
    in.clearCoatRoughness = clamped("clearCoatRoughness", minPerceptualRoughness());
  }
  if (!material.cloth && writes(material, "anisotropy")) in.anisotropy = clamped("anisotropy", -1.0f);
  if (writes(material, "sheenColor")) {
    in.sheenColor = clamped("sheenColor", 0.0f);
    if (!material.cloth) in.sheenRoughness = clamped("sheenRoughness", minPerceptualRoughness());
  }
  return in;
}

// std140: a vec3 aligns to 16, a vec2 to 8, a float to 4 and packs into a vec3's fourth slot.
void addMember(PreshadeLayout& layout, uint32_t* offset, const char* type, const char* name, uint32_t components) {
  const uint32_t align = components == 1 ? 4 : components == 2 ? 8 : 16;
  *offset = (*offset + align - 1) / align * align;
  layout.members.push_back({type, name, *offset, components});
  *offset += 4 * components;
}

const PreshadedMember* member(const PreshadeLayout& layout, std::string_view name) {
  for (const PreshadedMember& m : layout.members)
    if (name == m.name) return &m;
  return nullptr;
}

// A chunk's `const float NAME = value;` or `#define NAME value`: the preshader's bounds and
// coefficients are the chunks' own.
float chunkConstant(const char* chunk, const char* name) {
  const std::string& text = glslLibrary().at(chunk);
  for (const std::string& decl : {std::string("const float ") + name + " = ", std::string("#define ") + name + " "}) {
    const size_t at = text.find(decl);
    if (at != std::string::npos) return std::strtof(text.c_str() + at + decl.size(), nullptr);
  }
  throw std::logic_error(std::string("chunks/") + chunk + " defines no " + name);
}

// lod = r · ((levels − 1) · (2 − r)): chunks/ibl_prefiltered.glsl's prefiltered_radiance, in its
// order of operations.
std::optional<uint8_t> environmentLod(ProgramBuilder& b, uint8_t r) {
  const float maxLod = float(abi::kEnvironmentLevels - 1);
  auto two = b.constant({2, 2, 2, 2});
  auto twoMinusR = b.binary(PreshaderOpcode::Sub, *two, r);
  auto levels = b.constant({maxLod, maxLod, maxLod, maxLod});
  auto scaled = b.binary(PreshaderOpcode::Mul, *levels, *twoMinusR);
  return b.binary(PreshaderOpcode::Mul, r, *scaled);
}

}  // namespace

float minPerceptualRoughness() {
  static const float value = chunkConstant("precision.glsl", "MIN_PERCEPTUAL_ROUGHNESS");
  return value;
}

float anisotropyBendMax() {
  static const float value = chunkConstant("anisotropy_frame.glsl", "ANISOTROPY_BEND_MAX");
  return value;
}

float anisotropyAlphaMin() {
  static const float value = chunkConstant("anisotropy_frame.glsl", "ANISOTROPY_ALPHA_MIN");
  return value;
}

PreshadeLayout planPreshade(const ir::Material& material, const ParamLayout& params) {
  PreshadeLayout layout;
  if (material.shading != "lit") return layout;
  ProgramBuilder b(material, params);
  const Inputs in = clampedInputs(b, material);
  // Inputs made of constants alone stay in the shader, where the compiler folds them.
  auto reads = [&](std::initializer_list<const char*> names) {
    for (const char* n : names)
      if (readsParameter(material, n)) return true;
    return false;
  };
  // A constant metallic of 1 makes the diffuse colour 0, and the shader compiler then drops every
  // diffuse term (brushed_gold: 0.59 cycles of reference.dir0's 1.64, measured): a preshaded
  // diffuse colour, unknown to it, would keep them.
  const std::optional<ir::ValueId> metallic = ir::outputValue(material, "metallic");
  const bool pureMetal = metallic && material.surface.value(*metallic).op == ir::Op::Constant &&
                         material.surface.value(*metallic).constant[0] >= 1.0;
  layout.diffuseColor = in.baseColor && in.metallic && !pureMetal && reads({"baseColor", "metallic"});
  // The cloth model reads no f0 (chunks/shading_cloth.glsl).
  layout.f0 = !material.cloth && in.baseColor && in.metallic && in.reflectance &&
              reads({"baseColor", "metallic", "reflectance"});
  layout.roughness = in.roughness && reads({"roughness"});
  layout.clearCoat = in.clearCoat && reads({"clearCoat"});
  layout.clearCoatRoughness = in.clearCoatRoughness && reads({"clearCoatRoughness"});
  layout.anisotropy = in.anisotropy && in.roughness && reads({"anisotropy", "roughness"});
  layout.sheenColor = in.sheenColor && reads({"sheenColor"});
  // The cloth's r_s is its roughness (chunks/sheen_layer.glsl): the lod of the preshaded one.
  layout.sheenRoughness = material.cloth ? layout.roughness : in.sheenRoughness && reads({"sheenRoughness"});
  if (!layout.diffuseColor && !layout.f0 && !layout.roughness && !layout.clearCoat && !layout.clearCoatRoughness &&
      !layout.anisotropy && !layout.sheenColor && !layout.sheenRoughness)
    return layout;
  uint32_t offset = params.blockSize;
  if (layout.diffuseColor) addMember(layout, &offset, "vec3", "facet_diffuseColor", 3);
  if (layout.roughness) addMember(layout, &offset, "float", "facet_perceptualRoughness", 1);
  if (layout.f0) addMember(layout, &offset, "vec3", "facet_f0", 3);
  if (layout.roughness) {
    addMember(layout, &offset, "float", "facet_alpha", 1);
    addMember(layout, &offset, "float", "facet_environmentLod", 1);
    addMember(layout, &offset, "float", "facet_ggxAlphaScaled", 1);
    addMember(layout, &offset, "float", "facet_ziomaRoughnessFactor", 1);
  }
  if (layout.sheenColor) addMember(layout, &offset, "vec3", "facet_sheenColor", 3);
  if (layout.sheenRoughness) addMember(layout, &offset, "float", "facet_sheenLod", 1);
  if (layout.sheenRoughness && !material.cloth) {
    addMember(layout, &offset, "float", "facet_sheenRoughness", 1);
    addMember(layout, &offset, "float", "facet_sheenAlpha", 1);
  }
  if (layout.clearCoat) addMember(layout, &offset, "float", "facet_clearCoat", 1);
  if (layout.clearCoatRoughness) {
    addMember(layout, &offset, "float", "facet_clearCoatAlpha", 1);
    addMember(layout, &offset, "float", "facet_clearCoatLod", 1);
  }
  if (layout.anisotropy) {
    addMember(layout, &offset, "float", "facet_anisotropy", 1);
    addMember(layout, &offset, "float", "facet_anisotropicBend", 1);
    addMember(layout, &offset, "vec2", "facet_anisotropicAlpha", 2);
  }
  layout.blockSize = (offset + 15) / 16 * 16;
  return layout;
}

std::vector<PreshaderOp> preshaderProgram(const ir::Material& material, const ParamLayout& params,
                                          const PreshadeLayout& layout, const permutations::TierConfig& tier) {
  if (!layout.any()) return {};
  ProgramBuilder b(material, params);
  const Inputs in = clampedInputs(b, material);
  b.startDerivations();
  // The formulas of chunks/shading_standard.glsl (material_diffuse_color, material_f0,
  // material_perceptual_roughness), which keeps them as the per-pixel form.
  const unsigned standardGroup = b.groupStart();
  std::optional<uint8_t> oneMinusMetallic;
  if (layout.diffuseColor || layout.f0) {
    auto one = b.constant({1, 1, 1, 1});
    oneMinusMetallic = b.binary(PreshaderOpcode::Sub, *one, *in.metallic);
  }
  if (layout.diffuseColor) {
    auto diffuse = b.binary(PreshaderOpcode::Mul, *oneMinusMetallic, *in.baseColor);
    b.store(*diffuse, member(layout, "facet_diffuseColor")->offset, 3);
  }
  if (layout.f0) {
    auto metalPart = b.binary(PreshaderOpcode::Mul, *in.metallic, *in.baseColor);
    std::optional<uint8_t> f0;
    if (tier.colorSpace == permutations::ColorSpace::GammaHack) {
      // f0_γ = 0.4 · reflectance · (1 − metallic) + metallic · baseColor_γ, squared to linear.
      auto scaled = b.binary(PreshaderOpcode::Mul, *in.reflectance, *b.constant({0.4f, 0.4f, 0.4f, 0.4f}));
      auto dielectric = b.binary(PreshaderOpcode::Mul, *scaled, *oneMinusMetallic);
      auto f0Gamma = b.binary(PreshaderOpcode::Add, *dielectric, *metalPart);
      f0 = b.binary(PreshaderOpcode::Mul, *f0Gamma, *f0Gamma);
    } else {
      // f0 = 0.16 · reflectance² · (1 − metallic) + metallic · baseColor.
      auto squared = b.binary(PreshaderOpcode::Mul, *in.reflectance, *in.reflectance);
      auto scaled = b.binary(PreshaderOpcode::Mul, *squared, *b.constant({0.16f, 0.16f, 0.16f, 0.16f}));
      auto dielectric = b.binary(PreshaderOpcode::Mul, *scaled, *oneMinusMetallic);
      f0 = b.binary(PreshaderOpcode::Add, *dielectric, *metalPart);
    }
    b.store(*f0, member(layout, "facet_f0")->offset, 3);
  }
  b.endGroup(standardGroup);
  if (layout.roughness) {
    const unsigned group = b.groupStart();
    auto alpha = b.binary(PreshaderOpcode::Mul, *in.roughness, *in.roughness);
    b.store(*in.roughness, member(layout, "facet_perceptualRoughness")->offset, 1);
    b.store(*alpha, member(layout, "facet_alpha")->offset, 1);
    // The environment's lod (material_prefiltered_radiance, shading_ambient.glsl).
    b.store(*environmentLod(b, *in.roughness), member(layout, "facet_environmentLod")->offset, 1);
    b.endGroup(group);
  }
  // 2^12 α (GGX_D_SCALE2 · α, ggx_denominator.glsl) and Zioma's 4π (p α + q) (specular_zioma.glsl),
  // which specular_zioma_lobe.glsl reads (a cloth variant compiles the tier's lobe too, unread).
  if (layout.roughness) {
    const unsigned group = b.groupStart();
    auto broadcast = [&](float k) { return *b.constant({k, k, k, k}); };
    auto alpha = b.binary(PreshaderOpcode::Mul, *in.roughness, *in.roughness);
    b.store(*b.binary(PreshaderOpcode::Mul, broadcast(chunkConstant("ggx_denominator.glsl", "GGX_D_SCALE2")), *alpha),
            member(layout, "facet_ggxAlphaScaled")->offset, 1);
    auto pAlpha =
        b.binary(PreshaderOpcode::Mul, broadcast(chunkConstant("specular_zioma.glsl", "ZIOMA_ROUGH_SCALE")), *alpha);
    auto sum =
        b.binary(PreshaderOpcode::Add, *pAlpha, broadcast(chunkConstant("specular_zioma.glsl", "ZIOMA_ROUGH_BIAS")));
    auto factor = b.binary(PreshaderOpcode::Mul, broadcast(4.0f * chunkConstant("math.glsl", "PI")), *sum);
    b.store(*factor, member(layout, "facet_ziomaRoughnessFactor")->offset, 1);
    b.endGroup(group);
  }
  auto store = [&](std::optional<uint8_t> r, const char* name) {
    const PreshadedMember* m = member(layout, name);
    b.store(*r, m->offset, m->components);
  };
  // chunks/sheen_layer.glsl (sheen_color, sheen_perceptual_roughness, sheen_alpha) and the
  // environment's lod at r_s that sheen_layer reads.
  if (layout.sheenColor) {
    const bool gamma = tier.colorSpace == permutations::ColorSpace::GammaHack;  // encoded with γ = 2
    const unsigned group = b.groupStart();
    store(gamma ? b.binary(PreshaderOpcode::Mul, *in.sheenColor, *in.sheenColor) : in.sheenColor, "facet_sheenColor");
    b.endGroup(group);
  }
  if (layout.sheenRoughness) {
    const unsigned group = b.groupStart();
    const uint8_t r = material.cloth ? *in.roughness : *in.sheenRoughness;
    store(environmentLod(b, r), "facet_sheenLod");
    if (!material.cloth) {
      store(r, "facet_sheenRoughness");
      store(b.binary(PreshaderOpcode::Mul, r, r), "facet_sheenAlpha");
    }
    b.endGroup(group);
  }
  // chunks/clear_coat_ambient.glsl (clear_coat_strength, the environment's lod at r_c in
  // clear_coat_layer) and clear_coat_ggx_kelemen.glsl (α_c = r_c²).
  if (layout.clearCoat) store(in.clearCoat, "facet_clearCoat");
  if (layout.clearCoatRoughness) {
    const unsigned group = b.groupStart();
    const uint8_t r = *in.clearCoatRoughness;
    store(b.binary(PreshaderOpcode::Mul, r, r), "facet_clearCoatAlpha");
    store(environmentLod(b, r), "facet_clearCoatLod");
    b.endGroup(group);
  }
  // chunks/anisotropy_frame.glsl: k = clamp(anisotropy, −1, 1),
  // (α_t, α_b) = clamp(α · (1 + k, 1 − k), ANISOTROPY_ALPHA_MIN, 1) with α = r² (material_alpha) and
  // the reflection's bend min(|k| · clamp(5 r, 0, 1), ANISOTROPY_BEND_MAX), where
  // |k| = clamp(k, 0, 1) − clamp(k, −1, 0) (one side is 0: exact) and the min is a clamp from 0
  // (the product is ≥ 0).
  if (layout.anisotropy) {
    const unsigned group = b.groupStart();
    const uint8_t k = *in.anisotropy;
    store(k, "facet_anisotropy");
    // (One op per statement: the order of the ops is the package's bytes, not left to the order in
    // which a compiler evaluates arguments.)
    auto positive = b.clamp(k, 0.0f, 1.0f);
    auto negative = b.clamp(k, -1.0f, 0.0f);
    auto absK = b.binary(PreshaderOpcode::Sub, *positive, *negative);
    auto five = b.constant({5, 5, 5, 5});
    auto fiveR = b.binary(PreshaderOpcode::Mul, *five, *in.roughness);
    auto fade = b.clamp(*fiveR, 0.0f, 1.0f);
    auto bend = b.binary(PreshaderOpcode::Mul, *absK, *fade);
    store(b.clamp(*bend, 0.0f, anisotropyBendMax()), "facet_anisotropicBend");
    b.endGroup(group);
    auto alpha = b.binary(PreshaderOpcode::Mul, *in.roughness, *in.roughness);
    auto signs = b.constant({1, -1, 0, 0});
    auto plusMinusK = b.binary(PreshaderOpcode::Mul, k, *signs);
    auto one = b.constant({1, 1, 1, 1});
    auto factors = b.binary(PreshaderOpcode::Add, *one, *plusMinusK);  // (1 + k, 1 − k)
    auto scaled = b.binary(PreshaderOpcode::Mul, *alpha, *factors);
    store(b.clamp(*scaled, anisotropyAlphaMin(), 1.0f), "facet_anisotropicAlpha");
    b.endGroup(group);
  }
  return b.take();
}

}  // namespace facet::compiler
