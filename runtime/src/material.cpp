#include "facet/runtime/material.h"
#include "facet/runtime/preshader.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "facet/permutations/tiers.h"
#include "facet/permutations/variant_key.h"
#include "spirv_reflection.h"
#include "untrusted_spirv.h"

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

// Package textures this runtime knows where to bind (shader_abi.h), and the shape the shaders
// address them with. Frame-texture slots: the shaders declare them at these bindings whatever
// material they belong to.
struct GeneratedSlot {
  const char* name;
  uint32_t binding;
  uint32_t width, height;
};
constexpr GeneratedSlot kGeneratedSlots[] = {
    {abi::kSpecularLutName, abi::kSpecularLutBinding, abi::kSpecularLutWidth, abi::kSpecularLutHeight}};

const GeneratedSlot* generatedSlot(const std::string& name) {
  for (const GeneratedSlot& s : kGeneratedSlots)
    if (name == s.name) return &s;
  return nullptr;
}

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

// A parameter's value type in the block: float and vectors, int, bool (4 bytes a component).
ValueType valueTypeOf(const package::Param& p) {
  const ScalarKind kind = p.type == package::ParamType::Int    ? ScalarKind::Int
                          : p.type == package::ParamType::Bool ? ScalarKind::Bool
                                                               : ScalarKind::Float;
  return {kind, uint32_t(p.size / 4)};
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
  // The tables' meaning now; each shader's code when program() first decodes it.
  if (std::string why = reader->semanticError(); !why.empty()) {
    *error = name + ": " + why;
    return std::nullopt;
  }
  // Before format 1.4 a lit material's shaders read the environment as a 2D map: octahedral in
  // 1.2 and 1.3 (both came after the octahedral map), equirect or octahedral in 1.0 and 1.1. This
  // runtime no longer builds either (it binds a cube map there): the package cannot be drawn.
  const uint16_t minor = reader->formatMinor();
  if (reader->material().shading == "lit" && minor < package::kFirstMinorWithCubeEnvironment) {
    *error = name + ": package format 1." + std::to_string(minor) + " samples the environment as " +
             (minor >= 2 ? "an octahedral map" : "a 2D map (equirect or octahedral)") +
             ", which this runtime no longer provides (a cube map since format 1." +
             std::to_string(package::kFirstMinorWithCubeEnvironment) +
             "); rebuild it with this release's compiler: matc compile MATERIAL.mat -o PACKAGE.matpkg";
    return std::nullopt;
  }
  // A table of another shape, even one of the same byte count, would be sampled at the wrong
  // texels: the shaders address it with the ABI's size.
  for (const package::TextureInfo& t : reader->textures()) {
    const GeneratedSlot* slot = generatedSlot(t.name);
    if (slot && (t.width != slot->width || t.height != slot->height)) {
      *error = name + ": texture '" + t.name + "' is " + std::to_string(t.width) + "x" + std::to_string(t.height) +
               "; the shaders address it as " + std::to_string(slot->width) + "x" + std::to_string(slot->height);
      return std::nullopt;
    }
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

std::optional<ProgramInterface> LoadedMaterial::interfaceOf(size_t variant, std::string* error) const {
  const package::MaterialInfo& m = reader_.material();
  const std::string& key = reader_.variants()[variant].key;
  ProgramInterface out;
  out.material = m.name;
  out.variant = key;
  out.parameterBytes = m.paramBlockSize;
  const package::PreshaderProgram* program = reader_.preshaderProgram(key);
  out.materialBlockBytes = program ? reader_.preshader().blockSize : m.paramBlockSize;
  out.preshadedWords.assign(out.materialBlockBytes / 4, false);
  if (program)
    for (const package::PreshaderOp& op : program->ops)
      if (op.code == package::PreshaderOpcode::Store)
        for (uint32_t i = 0; i < op.count && op.offset / 4 + i < out.preshadedWords.size(); ++i)
          out.preshadedWords[op.offset / 4 + i] = true;
  for (const package::Param& p : m.params) {
    if (package::isTexture(p.type)) {
      if (p.offset != package::kNoTextureSlot)
        out.samplers.push_back({abi::kMaterialSamplerPrefix + p.name, abi::materialTextureBinding(p.offset), false});
    } else if (p.size != 0) {
      out.parameters.push_back({p.name, p.offset, valueTypeOf(p)});
    }
  }
  // The frame's textures a lit variant's draws bind (runtime/scene_frame.h): the environment, and
  // the DFG table in the tiers whose ambient model reads it (elsewhere its binding holds a dummy).
  // The key parses: semanticError checked it.
  const std::optional<permutations::VariantKey> parsed = permutations::VariantKey::parse(key);
  const bool splitSum = parsed && permutations::preset(parsed->tier).ambient == permutations::AmbientModel::SplitSum;
  const auto frame = [&](const abi::SamplerDesc& d) { out.samplers.push_back({std::string(d.name), d.binding, d.cube}); };
  if (m.shading == "lit") frame(abi::kEnvironmentSampler);
  if (m.shading == "lit" && splitSum) frame(abi::kDfgLutSampler);
  for (const package::TextureInfo& t : reader_.textures()) {
    if (std::find(t.variants.begin(), t.variants.end(), variant) == t.variants.end()) continue;
    const GeneratedSlot* slot = generatedSlot(t.name);
    if (!slot) {
      *error = unknownTextureError(key, t.name);
      return std::nullopt;
    }
    out.samplers.push_back({t.name, slot->binding, false});
    out.packageTextures.push_back(t.name);
  }
  return out;
}

std::string LoadedMaterial::unknownTextureError(const std::string& variantKey, const std::string& texture) const {
  return "material '" + info().name + "' variant '" + variantKey + "' samples texture '" + texture +
         "', which this runtime does not know; update the runtime or recompile the material";
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
  ShaderProgram p;
  std::vector<ReflectedStage> reflected;
  for (const package::ShaderInfo& s : variants[index].shaders) {
    // Metal is not a backend of this runtime: its code stays compressed.
    if (s.target == package::Target::Msl) continue;
    const std::string what = "material '" + info().name + "' variant " + key + ": the " + package::toString(s.stage) +
                             " shader";
    std::optional<std::span<const uint8_t>> code = reader_.blob(s.blob, error);
    if (!code) {
      *error = what + ": " + *error;
      return std::nullopt;
    }
    if (std::string why = package::shaderCodeError(s.target, *code); !why.empty()) {
      *error = "material '" + info().name + "': the " + package::toString(s.stage) + " " +
               package::toString(s.target) + " shader of variant '" + key + "' " + why;
      return std::nullopt;
    }
    bool vertex = s.stage == package::Stage::Vertex;
    if (s.target == package::Target::GlslEs300) {
      (vertex ? p.vertexGlslEs : p.fragmentGlslEs).assign(code->begin(), code->end());
    } else if (s.target == package::Target::Spirv) {
      std::vector<uint32_t>& words = vertex ? p.vertexSpirv : p.fragmentSpirv;
      words.resize(code->size() / 4);
      if (!words.empty()) std::memcpy(words.data(), code->data(), words.size() * 4);
      std::string why;
      if (!validateUntrustedSpirv(words, &why)) {
        *error = what + " is " + why;
        return std::nullopt;
      }
      // Valid on its own is not enough: its stage and interface must be the package's.
      if (!reflectSpirv(words, s.stage, &reflected.emplace_back(), &why)) {
        *error = what + " (SPIR-V) " + why;
        return std::nullopt;
      }
    }
  }
  std::optional<ProgramInterface> declared = interfaceOf(index, error);
  if (!declared) return std::nullopt;
  if (std::string why = interfaceError(*declared, reflected, true); !why.empty()) {
    *error = why;
    return std::nullopt;
  }
  p.interface = std::move(*declared);
  return p;
}

bool LoadedMaterial::checkEveryVariant(std::string* error) const {
  for (const package::VariantInfo& v : reader_.variants())
    if (!program(v.key, error)) return false;
  return true;
}

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
    const GeneratedSlot* slot = generatedSlot(t.name);
    if (!slot) {
      *error = unknownTextureError(variantKey, t.name);
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
          *error = "parameter '" + p.name + "' of material '" + info.name + "' = " + number(c) + " is outside its range" +
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
