#include "facet/runtime/material.h"
#include "facet/runtime/preshader.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "facet/package/checks.h"

namespace facet::runtime {
namespace {

int componentCount(package::ParamType t) {
  switch (t) {
    case package::ParamType::Vec2: return 2;
    case package::ParamType::Vec3:
    case package::ParamType::Color: return 3;
    case package::ParamType::Vec4: return 4;
    default: return 1;
  }
}

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double linearToSrgb(double c) { return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

// A lookup table, not an image: bilinear within its one level, clamped so that the table's
// ends (R·L = 1, roughness 1) are not blended with the opposite edge.
Texture runtimeTexture(const package::TextureInfo& t, std::span<const uint8_t> texels) {
  Texture out;
  out.width = t.width;
  out.height = t.height;
  out.format = TextureFormat::R8Unorm;  // the package's only texel format
  out.levels = {std::vector<uint8_t>(texels.begin(), texels.end())};
  out.linearFilter = true;
  out.repeat = false;
  return out;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

LoadedMaterial::LoadedMaterial(package::PackageReader reader) : reader_(std::move(reader)) {
  textures_.resize(reader_.textures().size());
}

std::optional<LoadedMaterial> LoadedMaterial::checked(std::optional<package::PackageReader> reader,
                                                      const std::string& name, std::string* error) {
  if (!reader) {
    *error = name + ": " + *error;
    return std::nullopt;
  }
  // The tables' meaning, the environment's form, generated textures' shapes; each shader's code
  // when program() first decodes it.
  if (std::string why = package::loadError(*reader); !why.empty()) {
    *error = name + ": " + why;
    return std::nullopt;
  }
  return LoadedMaterial(std::move(*reader));
}

std::optional<LoadedMaterial> LoadedMaterial::load(const std::string& path, std::string* error) {
  return checked(package::PackageReader::openFile(path, error), path, error);
}

std::optional<LoadedMaterial> LoadedMaterial::loadFromMemory(std::span<const uint8_t> bytes, const std::string& name,
                                                             std::string* error) {
  return checked(package::PackageReader::open(bytes, error), name, error);
}

std::optional<ShaderProgram> LoadedMaterial::program(const std::string& key, std::string* error) const {
  const std::vector<package::VariantInfo>& variants = reader_.variants();
  size_t index = 0;
  while (index < variants.size() && variants[index].key != key) ++index;
  if (index == variants.size()) {
    std::string keys;
    for (const package::VariantInfo& v : variants) keys += (keys.empty() ? "" : ", ") + v.key;
    *error = "material '" + info().name + "' was not built with variant '" + key + "' (built: " + keys +
             "); recompile it for this scene";
    return std::nullopt;
  }
  std::optional<package::CheckedVariant> checked = package::checkVariant(reader_, index, error);
  if (!checked) return std::nullopt;
  ShaderProgram p;
  p.vertexSpirv = std::move(checked->vertexSpirv);
  p.fragmentSpirv = std::move(checked->fragmentSpirv);
  p.vertexGlslEs = std::move(checked->vertexGlslEs);
  p.fragmentGlslEs = std::move(checked->fragmentGlslEs);
  p.interface = std::move(checked->interface);
  return p;
}

bool LoadedMaterial::checkEveryVariant(std::string* error) const { return package::checkEveryVariant(reader_, error); }

bool LoadedMaterial::preshade(const std::string& variantKey, std::vector<uint8_t>* block, std::string* error) const {
  const package::PreshaderProgram* program = reader_.preshaderProgram(variantKey);
  if (!program) return true;
  const uint32_t params = reader_.material().paramBlockSize;
  if (block->size() < params) {
    *error = "a parameter block of " + std::to_string(block->size()) + " bytes for material '" + info().name +
             "', whose parameters take " + std::to_string(params);
    return false;
  }
  block->resize(reader_.preshader().blockSize, 0);
  if (runPreshader(program->ops, params, *block, error)) return true;
  *error = "material '" + info().name + "', variant '" + variantKey + "': " + *error;
  return false;
}

std::optional<std::vector<TextureBinding>> LoadedMaterial::generatedTextures(const std::string& variantKey,
                                                                             std::string* error) const {
  std::vector<TextureBinding> out;
  const std::vector<package::VariantInfo>& variants = reader_.variants();
  uint32_t index = 0;
  while (index < variants.size() && variants[index].key != variantKey) ++index;
  for (size_t i = 0; i < reader_.textures().size(); ++i) {
    const package::TextureInfo& t = reader_.textures()[i];
    if (std::find(t.variants.begin(), t.variants.end(), index) == t.variants.end()) continue;
    const package::GeneratedTextureSlot* slot = package::generatedTextureSlot(t.name);
    if (!slot) {
      *error = package::unknownTextureError(info().name, variantKey, t.name);
      return std::nullopt;
    }
    if (!textures_[i]) {
      std::optional<std::span<const uint8_t>> texels = reader_.texels(i, error);
      if (!texels) {
        *error = "material '" + info().name + "' texture '" + t.name + "': " + *error;
        return std::nullopt;
      }
      textures_[i] = std::make_unique<Texture>(runtimeTexture(t, *texels));
    }
    out.push_back({slot->binding, t.name, textures_[i].get()});
  }
  return out;
}

std::optional<std::vector<uint8_t>> LoadedMaterial::paramBlock(const std::map<std::string, std::vector<double>>& values,
                                                               std::string* error, ColorEncoding colors,
                                                               const std::set<std::string>& givenAsBool) const {
  const package::MaterialInfo& info = reader_.material();
  for (const auto& [name, value] : values) {
    bool known = false;
    for (const package::Param& p : info.params) known = known || p.name == name;
    if (!known) {
      std::string names;
      for (const package::Param& p : info.params) names += (names.empty() ? "" : ", ") + p.name;
      *error = "material '" + info.name + "' has no parameter '" + name + "' (it has: " + names + ")";
      return std::nullopt;
    }
  }
  std::vector<uint8_t> block(info.paramBlockSize, 0);
  for (const package::Param& p : info.params) {
    if (package::isTexture(p.type)) {
      if (values.count(p.name)) {
        *error = "parameter '" + p.name + "' of material '" + info.name + "' is a texture: give an image path";
        return std::nullopt;
      }
      continue;
    }
    if (p.size == 0) continue;  // never read by the shaders: no bytes to fill
    std::vector<double> v = p.defaultValue;
    // Defaults are stored linear; the gamma hack wants them as authored (sRGB-encoded).
    if (p.type == package::ParamType::Color && colors == ColorEncoding::Srgb)
      for (double& c : v) c = linearToSrgb(c);
    if (auto it = values.find(p.name); it != values.end()) {
      if (int(it->second.size()) != componentCount(p.type)) {
        *error = "parameter '" + p.name + "' of material '" + info.name + "' is " + package::toString(p.type) + " (" +
                 std::to_string(componentCount(p.type)) + " values), but " + std::to_string(it->second.size()) +
                 " were given";
        return std::nullopt;
      }
      v = it->second;
      bool isBool = p.type == package::ParamType::Bool;
      if (isBool != (givenAsBool.count(p.name) > 0)) {
        *error = "parameter '" + p.name + "' of material '" + info.name + "' is " + package::toString(p.type) +
                 (isBool ? ": give true or false" : ", not a bool");
        return std::nullopt;
      }
      for (double c : v) {
        if (p.type == package::ParamType::Int && c != std::floor(c)) {
          *error = "parameter '" + p.name + "' of material '" + info.name + "' is int, not " + number(c);
          return std::nullopt;
        }
        bool outside = (p.rangeMin && c < *p.rangeMin) || (p.rangeMax && c > *p.rangeMax) || !std::isfinite(c);
        if (p.type == package::ParamType::Color) outside = outside || c < 0.0 || c > 1.0;
        if (outside) {
          *error = "parameter '" + p.name + "' of material '" + info.name + "' = " + number(c) +
                   " is outside its range" +
                   (p.rangeMin ? " [" + number(*p.rangeMin) + ", " + number(*p.rangeMax) + "]" : std::string());
          return std::nullopt;
        }
      }
      if (p.type == package::ParamType::Color && colors == ColorEncoding::Linear)
        for (double& c : v) c = srgbToLinear(c);
    }
    if (p.offset + p.size > block.size() || v.size() * 4 != p.size) {
      *error = "parameter '" + p.name + "' lies outside the parameter block";  // the reader validates this; defensive
      return std::nullopt;
    }
    for (size_t i = 0; i < v.size(); ++i) {
      uint8_t* dst = block.data() + p.offset + 4 * i;
      if (p.type == package::ParamType::Int || p.type == package::ParamType::Bool) {
        int32_t x = int32_t(std::lround(v[i]));
        std::memcpy(dst, &x, 4);
      } else {
        float x = float(v[i]);
        std::memcpy(dst, &x, 4);
      }
    }
  }
  return block;
}

std::optional<std::vector<LoadedMaterial::SampledTexture>> LoadedMaterial::sampledTextures(
    const std::map<std::string, std::string>& images, std::string* error) const {
  const package::MaterialInfo& info = reader_.material();
  for (const auto& [name, path] : images) {
    bool texture = false;
    for (const package::Param& p : info.params) texture = texture || (p.name == name && package::isTexture(p.type));
    if (!texture) {
      *error = "material '" + info.name + "' has no texture parameter '" + name + "' (given image '" + path + "')";
      return std::nullopt;
    }
  }
  std::vector<SampledTexture> out;
  for (const package::Param& p : info.params) {
    if (!package::isTexture(p.type) || p.offset == package::kNoTextureSlot) continue;
    SampledTexture t;
    t.param = p.name;
    t.slot = p.offset;
    t.glslName = abi::kMaterialSamplerPrefix + p.name;
    t.srgb = p.type == package::ParamType::TextureSrgb;
    if (auto it = images.find(p.name); it != images.end()) t.imagePath = it->second;
    for (size_t i = 0; i < 4 && i < p.defaultValue.size(); ++i) t.defaultValue[i] = p.defaultValue[i];
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace facet::runtime
