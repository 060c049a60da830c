#include "facet/runtime/material_instance.h"

#include <algorithm>
#include <cstring>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "facet/permutations/tiers.h"
#include "facet/permutations/variant_key.h"
#include "facet/runtime/image_texture.h"

namespace facet::runtime {

std::shared_ptr<Material> Material::create(LoadedMaterial loaded, const VariantRequest& request, std::string* error) {
  auto tier = permutations::tierFromString(request.tier);
  if (!tier) {
    *error = "unknown tier '" + request.tier + "' (reference, high, mid, low)";
    return nullptr;
  }
  if (request.pointLights < 0 || request.pointLights > int(abi::kMaxPunctualLights)) {
    *error = "point lights " + std::to_string(request.pointLights) + " outside 0.." +
             std::to_string(abi::kMaxPunctualLights);
    return nullptr;
  }
  std::shared_ptr<Material> m(new Material(std::move(loaded)));
  const package::MaterialInfo& info = m->loaded_.info();
  // Axes the material ignores (lights, for unlit) are normalised as the compiler normalised them.
  permutations::MaterialNeeds needs{info.shading == "lit"};
  m->variantKey_ = permutations::requestKey(needs, *tier, request.sun, request.pointLights, request.shadowCascades,
                                            request.spotShadow)
                       .toString();
  auto program = m->loaded_.program(m->variantKey_, error);
  if (!program) return nullptr;
  m->program_ = std::move(*program);
  // Tiers with the gamma hack light sRGB-encoded colours (chunks/shading_standard.glsl).
  m->colors_ = permutations::preset(*tier).colorSpace == permutations::ColorSpace::GammaHack ? ColorEncoding::Srgb
                                                                                             : ColorEncoding::Linear;
  m->blending_ = info.blending == "transparent" ? Blending::Transparent
                 : info.blending == "additive"  ? Blending::Additive
                                                : Blending::Opaque;
  m->masked_ = info.blending == "masked";
  m->doubleSided_ = info.doubleSided;
  auto defaults = m->loaded_.paramBlock({}, error, m->colors_);
  if (!defaults || !m->loaded_.preshade(m->variantKey_, &*defaults, error)) return nullptr;
  m->defaults_ = std::move(*defaults);
  auto generated = m->loaded_.generatedTextures(m->variantKey_, error);
  if (!generated) return nullptr;
  m->generated_ = std::move(*generated);
  m->defaultTextures_ = m->generated_;
  auto sampled = m->loaded_.sampledTextures({}, error);
  if (!sampled) return nullptr;
  m->textureOfParam_.assign(info.params.size(), -1);
  for (const LoadedMaterial::SampledTexture& t : *sampled) {
    Texture solid = solidTexture(t.defaultValue, t.srgb);
    // The gamma hack samples sRGB undecoded (as SceneFrame does for scenes).
    if (t.srgb && m->colors_ == ColorEncoding::Srgb) solid.format = TextureFormat::Rgba8Unorm;
    m->solidTextures_.push_back(std::make_unique<Texture>(std::move(solid)));
    for (size_t p = 0; p < info.params.size(); ++p)
      if (info.params[p].name == t.param) m->textureOfParam_[p] = int(m->defaultTextures_.size());
    m->defaultTextures_.push_back({abi::kMaterialTextureBase + t.slot, t.glslName, m->solidTextures_.back().get()});
  }
  return m;
}

std::optional<ParameterHandle> Material::parameter(std::string_view name) const {
  const auto& params = loaded_.info().params;
  for (size_t i = 0; i < params.size(); ++i)
    if (params[i].name == name) return ParameterHandle{uint32_t(i)};
  return std::nullopt;
}

std::unique_ptr<MaterialInstance> Material::createInstance() const {
  return std::unique_ptr<MaterialInstance>(new MaterialInstance(shared_from_this()));
}

MaterialInstance::MaterialInstance(std::shared_ptr<const Material> material) : material_(std::move(material)) {
  block_.bytes = material_->defaults_;
  block_.generation = nextUniformGeneration();
  textures_ = material_->defaultTextures_;
}

std::optional<ParameterHandle> MaterialInstance::resolve(std::string_view name, std::string* error) const {
  auto handle = material_->parameter(name);
  if (!handle) {
    *error = "material '" + material_->loaded_.info().name + "' has no parameter '" + std::string(name) + "'";
  }
  return handle;
}

bool MaterialInstance::set(ParameterHandle handle, std::vector<double> values, bool typeMatches, bool isBool,
                           std::string* error) {
  const package::MaterialInfo& info = material_->loaded_.info();
  if (handle.index >= info.params.size()) {
    *error = "parameter handle " + std::to_string(handle.index) + " is not one of material '" + info.name + "'";
    return false;
  }
  const package::Param& p = info.params[handle.index];
  if (!typeMatches) {
    *error = "parameter '" + p.name + "' of material '" + info.name + "' is " + package::toString(p.type) +
             ": the value given has another type";
    return false;
  }
  // One parameter through the scene path's packing: the same range checks and colour conversion.
  std::set<std::string> asBool;
  if (isBool) asBool.insert(p.name);
  auto packed = material_->loaded_.paramBlock({{p.name, std::move(values)}}, error, material_->colors_, asBool);
  if (!packed) return false;
  if (p.size == 0) return true;  // never read by the shaders
  const uint8_t* dst = block_.bytes.data() + p.offset;
  const uint8_t* src = packed->data() + p.offset;
  if (std::memcmp(dst, src, p.size) == 0) return true;
  // The preshader's derived members follow from the parameters: recomputed on a copy, so a
  // refused program leaves the instance as it was.
  std::vector<uint8_t> bytes = block_.bytes;
  std::memcpy(bytes.data() + p.offset, src, p.size);
  if (!material_->loaded_.preshade(material_->variantKey_, &bytes, error)) return false;
  block_.bytes = std::move(bytes);
  block_.generation = nextUniformGeneration();
  return true;
}

namespace {
// Whether the handle names a parameter of one of these types (an invalid handle: no; set()
// reports it).
bool hasType(const Material& material, ParameterHandle handle, std::initializer_list<package::ParamType> types) {
  const auto& params = material.loaded().info().params;
  return handle.index < params.size() &&
         std::find(types.begin(), types.end(), params[handle.index].type) != types.end();
}
using package::ParamType;
}  // namespace

bool MaterialInstance::setParameter(ParameterHandle handle, float value, std::string* error) {
  return set(handle, {value}, hasType(*material_, handle, {ParamType::Float}), false, error);
}
bool MaterialInstance::setParameter(ParameterHandle handle, int32_t value, std::string* error) {
  return set(handle, {double(value)}, hasType(*material_, handle, {ParamType::Int}), false, error);
}
bool MaterialInstance::setParameter(ParameterHandle handle, bool value, std::string* error) {
  return set(handle, {value ? 1.0 : 0.0}, hasType(*material_, handle, {ParamType::Bool}), true, error);
}
bool MaterialInstance::setParameter(ParameterHandle handle, const std::array<float, 2>& value, std::string* error) {
  return set(handle, {value[0], value[1]}, hasType(*material_, handle, {ParamType::Vec2}), false, error);
}
bool MaterialInstance::setParameter(ParameterHandle handle, const std::array<float, 3>& value, std::string* error) {
  return set(handle, {value[0], value[1], value[2]}, hasType(*material_, handle, {ParamType::Vec3, ParamType::Color}),
             false, error);
}
bool MaterialInstance::setParameter(ParameterHandle handle, const std::array<float, 4>& value, std::string* error) {
  return set(handle, {value[0], value[1], value[2], value[3]}, hasType(*material_, handle, {ParamType::Vec4}), false,
             error);
}

bool MaterialInstance::setTexture(ParameterHandle handle, const Texture* texture, std::string* error) {
  const package::MaterialInfo& info = material_->loaded_.info();
  if (handle.index >= info.params.size() || !package::isTexture(info.params[handle.index].type)) {
    *error = "material '" + info.name + "': parameter " +
             (handle.index < info.params.size() ? "'" + info.params[handle.index].name + "'"
                                                : std::to_string(handle.index)) +
             " is not a texture";
    return false;
  }
  if (!texture) {
    *error = "texture for parameter '" + info.params[handle.index].name + "' is null";
    return false;
  }
  const int slot = material_->textureOfParam_[handle.index];
  // A texture parameter the shaders never sample has no slot: nothing to bind.
  if (slot >= 0) textures_[size_t(slot)].texture = texture;
  return true;
}

bool MaterialInstance::setTexture(std::string_view name, const Texture* texture, std::string* error) {
  auto handle = resolve(name, error);
  return handle && setTexture(*handle, texture, error);
}

DrawItem MaterialInstance::draw(const Mesh& mesh, const std::array<float, 16>& model) const {
  return draw(mesh, std::span(&model, 1));
}

DrawItem MaterialInstance::draw(const Mesh& mesh, std::span<const std::array<float, 16>> models) const {
  DrawItem item;
  item.mesh = &mesh;
  item.program = &material_->program_;
  item.instances.reserve(models.size());
  for (const std::array<float, 16>& model : models) item.instances.push_back(instanceTransform(model.data()));
  item.materialBlock = &block_;
  item.textures = textures_;
  item.blending = material_->blending_;
  item.masked = material_->masked_;
  item.cullBackFaces = !material_->doubleSided_;
  return item;
}

}  // namespace facet::runtime
