#include "facet/ir/module.h"

#include <cstring>
#include <functional>

namespace facet::ir {

const std::vector<AttributeInfo>& attributes() {
  static const std::vector<AttributeInfo> list = {
      {"worldPosition", Type::Vec3, "v_worldPosition", true},
      {"normal", Type::Vec3, "shading_normal", false},
      {"viewDirection", Type::Vec3, "shading_view", false},
      {"uv0", Type::Vec2, "v_uv0", true},
      {"uv1", Type::Vec2, "v_uv1", true},
      {"color", Type::Vec4, "v_color", false},
  };
  return list;
}

const AttributeInfo* findAttribute(std::string_view name) {
  for (const AttributeInfo& a : attributes())
    if (name == a.name) return &a;
  return nullptr;
}

const std::vector<OutputInfo>& outputs() {
  // Defaults follow Filament's material model: white, dielectric, fully rough, 4 % reflectance.
  static const std::vector<OutputInfo> list = {
      {"baseColor", Type::Vec3, {1, 1, 1, 0}, false, nullptr, OutputModel::Any},
      {"alpha", Type::Float, {1, 0, 0, 0}, false, nullptr, OutputModel::Any},
      {"metallic", Type::Float, {0, 0, 0, 0}, true, nullptr, OutputModel::Standard},
      {"roughness", Type::Float, {1, 0, 0, 0}, true, nullptr, OutputModel::Any},
      {"reflectance", Type::Float, {0.5, 0, 0, 0}, true, nullptr, OutputModel::Standard},
      {"normal", Type::Vec3, {0, 0, 1, 0}, true, nullptr, OutputModel::Any},  // tangent space: (0, 0, 1) is the
                                                                              // interpolated normal
      {"emissive", Type::Vec3, {0, 0, 0, 0}, false, nullptr, OutputModel::Any},
      {"ambientOcclusion", Type::Float, {1, 0, 0, 0}, true, nullptr, OutputModel::Any},
      // The clear coat (Filament's): strength 0..1, its perceptual roughness (Filament's default,
      // a smooth coat) and its tangent-space normal ((0, 0, 1): the interpolated normal, not the
      // base's mapped one).
      {"clearCoat", Type::Float, {0, 0, 0, 0}, true, "clearCoat", OutputModel::Standard},
      {"clearCoatRoughness", Type::Float, {0, 0, 0, 0}, true, "clearCoat", OutputModel::Standard},
      {"clearCoatNormal", Type::Vec3, {0, 0, 1, 0}, true, "clearCoat", OutputModel::Standard},
      // Anisotropy (Filament's): −1..1 (positive stretches the highlight along the direction,
      // negative across it) and its direction in tangent space ((1, 0, 0): the mesh's tangent).
      {"anisotropy", Type::Float, {0, 0, 0, 0}, true, "anisotropy", OutputModel::Standard},
      {"anisotropyDirection", Type::Vec3, {1, 0, 0, 0}, true, "anisotropy", OutputModel::Standard},
      // The cloth model (`shading cloth`, Filament's): the sheen's colour (without it, √baseColor,
      // Filament's default: chunks/shading_cloth.glsl) and the colour light takes through the
      // fabric (wrap diffuse; without it, Lambert's diffuse). On a lit material sheenColor is a
      // sheen layer over the base (KHR_materials_sheen's, chunks/sheen_layer.glsl) and
      // sheenRoughness its perceptual roughness (the glTF extension's default 0: the floor); the
      // cloth model's sheen takes `roughness`.
      {"sheenColor", Type::Vec3, {0, 0, 0, 0}, true, nullptr, OutputModel::Sheen},
      {"sheenRoughness", Type::Float, {0, 0, 0, 0}, true, "sheenColor", OutputModel::Standard},
      {"subsurfaceColor", Type::Vec3, {0, 0, 0, 0}, true, nullptr, OutputModel::Cloth},
  };
  return list;
}

const OutputInfo* findOutput(std::string_view name) {
  for (const OutputInfo& o : outputs())
    if (name == o.name) return &o;
  return nullptr;
}

const TierChoices& tierChoices() {
  static const TierChoices choices = {
      {"reference", "high", "mid", "low"},
      {{"specular", {"ggx_smith", "ggx_fastv", "fused_hammon", "zioma", "lut"}},
       {"diffuse", {"pixel", "vertex", "cube"}},
       {"clear_coat", {"ggx_kelemen", "ambient", "none"}},
       {"anisotropy", {"ggx_smith", "bent_ibl", "none"}},
       {"ao", {"single", "multi_bounce"}},
       {"specular_occlusion", {"ao", "lagarde"}},
       {"sheen", {"charlie_neubelt", "ambient", "none"}},
       {"specular_aa", {"projected", "none"}}},
  };
  return choices;
}

size_t Module::Hash::operator()(const Value& v) const {
  size_t h = std::hash<int>()(int(v.op)) * 31 + std::hash<int>()(int(v.type));
  for (ValueId a : v.args) h = h * 131 + a;
  for (double c : v.constant) {
    uint64_t bits;
    std::memcpy(&bits, &c, sizeof bits);
    h = h * 131 + std::hash<uint64_t>()(bits);
  }
  return h * 31 + std::hash<std::string>()(v.name);
}

ValueId Module::add(Value v) {
  if (v.op == Op::Constant) {
    for (double& c : v.constant)
      if (c == 0.0) c = 0.0;  // -0.0 and 0.0 are one constant
  }
  auto it = interned_.find(v);
  if (it != interned_.end()) return it->second;
  ValueId id = ValueId(values_.size());
  values_.push_back(v);
  interned_.emplace(std::move(v), id);
  return id;
}

ValueId Module::constant(Type t, std::array<double, 4> c) {
  Value v;
  v.op = Op::Constant;
  v.type = t;
  for (int i = componentCount(t); i < 4; ++i) c[size_t(i)] = 0.0;
  v.constant = c;
  return add(std::move(v));
}

}  // namespace facet::ir
