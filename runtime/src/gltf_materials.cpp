#include "facet/runtime/gltf_materials.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>

#include "gltf_source.h"

namespace facet::runtime {
namespace {

struct SlotInfo {
  const char* prefix;     // of the feature name
  const char* parameter;  // the texture parameter; its transform's are <parameter>Offset, ...
  const char* pointer;    // under /materials/N
  const char* kind;       // the .mat texture type
  const char* fallback;   // what a missing image samples as
};

constexpr SlotInfo kSlots[kGltfSlots] = {
    {"bc", "baseColorTexture", "/pbrMetallicRoughness/baseColorTexture", "srgb", "vec4(1.0, 1.0, 1.0, 1.0)"},
    {"mr", "metallicRoughnessTexture", "/pbrMetallicRoughness/metallicRoughnessTexture", "linear",
     "vec4(1.0, 1.0, 1.0, 1.0)"},
    {"n", "normalTexture", "/normalTexture", "normal", "vec4(0.5, 0.5, 1.0, 1.0)"},
    {"ao", "occlusionTexture", "/occlusionTexture", "linear", "vec4(1.0, 1.0, 1.0, 1.0)"},
    {"em", "emissiveTexture", "/emissiveTexture", "srgb", "vec4(1.0, 1.0, 1.0, 1.0)"},
    {"sc", "sheenColorTexture", "/extensions/KHR_materials_sheen/sheenColorTexture", "srgb",
     "vec4(1.0, 1.0, 1.0, 1.0)"},
    {"sr", "sheenRoughnessTexture", "/extensions/KHR_materials_sheen/sheenRoughnessTexture", "linear",
     "vec4(1.0, 1.0, 1.0, 1.0)"},
    {"cc", "clearcoatTexture", "/extensions/KHR_materials_clearcoat/clearcoatTexture", "linear",
     "vec4(1.0, 1.0, 1.0, 1.0)"},
    {"ccr", "clearcoatRoughnessTexture", "/extensions/KHR_materials_clearcoat/clearcoatRoughnessTexture", "linear",
     "vec4(1.0, 1.0, 1.0, 1.0)"},
    {"ccn", "clearcoatNormalTexture", "/extensions/KHR_materials_clearcoat/clearcoatNormalTexture", "normal",
     "vec4(0.5, 0.5, 1.0, 1.0)"},
    // The extension's texel where there is none: direction (1, 0), strength 1.
    {"an", "anisotropyTexture", "/extensions/KHR_materials_anisotropy/anisotropyTexture", "linear",
     "vec4(1.0, 0.5, 1.0, 1.0)"},
};

// The extensions the material path reads; any other optional one is reported and skipped (a
// required one was refused with the file: gltf_document.cpp).
constexpr const char* kReadExtensions[] = {
    "KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_ior",        "KHR_materials_specular",
    "KHR_materials_sheen",   "KHR_materials_clearcoat",         "KHR_materials_anisotropy", "KHR_mesh_quantization"};

// A number for a .mat file or a feature name: the shortest text that reads back as the double.
std::string number(double v) {
  char text[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  std::string s = text;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string featureNumber(double v) {
  std::string s = number(v);
  std::replace(s.begin(), s.end(), '.', 'p');
  std::replace(s.begin(), s.end(), '-', 'm');
  std::replace(s.begin(), s.end(), '+', '_');
  return s;
}

class Reader {
 public:
  Reader(const tinygltf::Model& model, GltfMaterialSet* out) : model_(model), out_(out) {}

  bool material(int index, bool vertexColors, std::string* error) {
    GltfMaterial m;
    m.index = index;
    m.features.vertexColors = vertexColors;
    if (index < 0) {  // glTF 2.0 §3.9.6: the default material is metallic 1, roughness 1, white
      out_->materials.push_back(std::move(m));
      return true;
    }
    const tinygltf::Material& g = model_.materials[size_t(index)];
    const std::string at = "/materials/" + std::to_string(index);
    m.name = g.name;
    const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
    if (!factors(pbr.baseColorFactor, 4, at + "/pbrMetallicRoughness/baseColorFactor", 0, 1, m.baseColorFactor.data(),
                 error) ||
        !unit(pbr.metallicFactor, at + "/pbrMetallicRoughness/metallicFactor", &m.metallicFactor, error) ||
        !unit(pbr.roughnessFactor, at + "/pbrMetallicRoughness/roughnessFactor", &m.roughnessFactor, error) ||
        !factors(g.emissiveFactor, 3, at + "/emissiveFactor", 0, 1, m.emissiveFactor.data(), error) ||
        !unit(g.occlusionTexture.strength, at + "/occlusionTexture/strength", &m.occlusionStrength, error))
      return false;
    m.normalScale = g.normalTexture.scale;
    if (!(std::abs(m.normalScale) <= kMaxNormalScale)) {
      *error = at + "/normalTexture/scale: " + number(m.normalScale) + " is outside [-" + number(kMaxNormalScale) +
               ", " + number(kMaxNormalScale) + "]";
      return false;
    }
    const struct {
      int index, texCoord;
      const tinygltf::ExtensionMap& extensions;
    } infos[kGltfSlots] = {
        {pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions},
        {pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
         pbr.metallicRoughnessTexture.extensions},
        {g.normalTexture.index, g.normalTexture.texCoord, g.normalTexture.extensions},
        {g.occlusionTexture.index, g.occlusionTexture.texCoord, g.occlusionTexture.extensions},
        {g.emissiveTexture.index, g.emissiveTexture.texCoord, g.emissiveTexture.extensions},
        {-1, 0, {}},  // the material extensions', read with the extensions below
        {-1, 0, {}},
        {-1, 0, {}},
        {-1, 0, {}},
        {-1, 0, {}},
        {-1, 0, {}},
    };
    for (size_t s = 0; s < kGltfSlots; ++s) {
      if (infos[s].index < 0) continue;
      if (!texture(infos[s].index, infos[s].texCoord, infos[s].extensions, at + kSlots[s].pointer, &m.textures[s],
                   error))
        return false;
      m.features.textured[s] = true;
      m.features.texCoord[s] = m.textures[s].texCoord;
      m.features.transformed[s] = m.textures[s].transformed;
    }
    if (g.alphaMode != "OPAQUE" && g.alphaMode != "MASK" && g.alphaMode != "BLEND") {
      *error = at + "/alphaMode: '" + g.alphaMode + "' is not OPAQUE, MASK or BLEND";
      return false;
    }
    m.features.alphaMode = g.alphaMode;
    if (g.alphaMode == "MASK") {
      if (!(g.alphaCutoff >= 0 && g.alphaCutoff <= 1)) {
        *error = at + "/alphaCutoff: " + number(g.alphaCutoff) + " is outside [0, 1]";
        return false;
      }
      m.features.alphaCutoff = g.alphaCutoff;
    }
    m.features.doubleSided = g.doubleSided;
    for (const auto& [name, value] : g.extensions) {
      const std::string where = at + "/extensions/" + name;
      if (name == "KHR_materials_emissive_strength") {
        const double strength = numberIn(value, "emissiveStrength", 1);
        if (!(strength >= 0 && strength <= kMaxEmissiveStrength)) {
          *error = where + "/emissiveStrength: " + number(strength) + " is outside [0, " +
                   number(kMaxEmissiveStrength) + "]";
          return false;
        }
        for (double& c : m.emissiveFactor) c *= strength;
      } else if (name == "KHR_materials_ior") {
        m.ior = numberIn(value, "ior", 1.5);
        // 0 stands for an infinite index (a perfect mirror, f0 = 1); otherwise at least 1.
        if (!(m.ior == 0 || (m.ior >= 1 && m.ior <= kMaxIor))) {
          *error = where + "/ior: " + number(m.ior) + " is neither 0 nor in [1, " + number(kMaxIor) + "]";
          return false;
        }
      } else if (name == "KHR_materials_specular") {
        if (!specular(value, where, &m, error)) return false;
      } else if (name == "KHR_materials_sheen") {
        if (!sheen(value, where, &m, error)) return false;
      } else if (name == "KHR_materials_clearcoat") {
        if (!clearCoat(value, where, &m, error)) return false;
      } else if (name == "KHR_materials_anisotropy") {
        if (!anisotropy(value, where, &m, error)) return false;
      } else {
        note(where + ": extension not read; the material is drawn without it");
      }
    }
    out_->materials.push_back(std::move(m));
    return true;
  }

  void note(std::string text) {
    if (std::find(out_->notes.begin(), out_->notes.end(), text) == out_->notes.end())
      out_->notes.push_back(std::move(text));
  }

  // Well beyond what content uses; bounds for the .mat parameter ranges.
  static constexpr double kMaxNormalScale = 100;
  static constexpr double kMaxEmissiveStrength = 10000;
  static constexpr double kMaxIor = 10;
  // f0 saturates at 1 once the colour reaches 1 / f0(ior) (25 at ior 1.5, 1 / 0.0007 at ior 1.05).
  static constexpr double kMaxSpecularColor = 10000;

 private:
  // KHR_materials_specular's factors; Facet's f0 is a scalar with f90 = 1, so a coloured factor
  // is drawn by its luminance and a specularFactor below 1 scales f0 but not f90 (both noted),
  // and its textures are not sampled (noted).
  bool specular(const tinygltf::Value& value, const std::string& where, GltfMaterial* m, std::string* error) {
    m->specularFactor = numberIn(value, "specularFactor", 1);
    if (!(m->specularFactor >= 0 && m->specularFactor <= 1)) {
      *error = where + "/specularFactor: " + number(m->specularFactor) + " is outside [0, 1]";
      return false;
    }
    if (!colour(value, "specularColorFactor", where, kMaxSpecularColor, &m->specularColorFactor, error)) return false;
    const auto& c = m->specularColorFactor;
    if (c[0] != c[1] || c[1] != c[2])
      note(where + "/specularColorFactor: drawn by its luminance (Facet's f0 is one number)");
    if (m->specularFactor != 1) note(where + "/specularFactor: scales f0 only (Facet's f90 is 1)");
    for (const char* texture : {"specularTexture", "specularColorTexture"})
      if (value.IsObject() && value.Has(texture)) note(where + "/" + texture + ": not sampled; drawn with the factors");
    return true;
  }

  // KHR_materials_sheen: the factors (colour in [0, 1]³, roughness in [0, 1]) and the two textures,
  // sampled as the extension says: the colour's RGB (sRGB), the roughness's alpha (linear).
  bool sheen(const tinygltf::Value& value, const std::string& where, GltfMaterial* m, std::string* error) {
    m->features.sheen = true;
    if (!value.IsObject()) {
      *error = where + ": expected an object";
      return false;
    }
    if (!colour(value, "sheenColorFactor", where, 1, &m->sheenColorFactor, error)) return false;
    if (!optionalNumber(value, "sheenRoughnessFactor", where, &m->sheenRoughnessFactor, error) ||
        !unit(m->sheenRoughnessFactor, where + "/sheenRoughnessFactor", &m->sheenRoughnessFactor, error))
      return false;
    return extensionTextures(value, where, {GltfSlot::SheenColor, GltfSlot::SheenRoughness}, m, error);
  }

  // KHR_materials_clearcoat: the factors (in [0, 1]), the normal texture's scale and the three
  // textures, sampled as the extension says: the strength's R, the roughness's G (linear), the
  // normal as the core normal texture. Its layering is Facet's clear coat (material-models.md):
  // the base × (1 − Fc(n_c·v)), a coat of IOR 1.5 (f0 0.04).
  bool clearCoat(const tinygltf::Value& value, const std::string& where, GltfMaterial* m, std::string* error) {
    m->features.clearCoat = true;
    if (!value.IsObject()) {
      *error = where + ": expected an object";
      return false;
    }
    for (auto [key, out] : {std::pair{"clearcoatFactor", &m->clearcoatFactor},
                            std::pair{"clearcoatRoughnessFactor", &m->clearcoatRoughnessFactor}})
      if (!optionalNumber(value, key, where, out, error) || !unit(*out, where + "/" + key, out, error)) return false;
    if (value.Has("clearcoatNormalTexture")) {
      m->clearcoatNormalScale = numberIn(value.Get("clearcoatNormalTexture"), "scale", 1);
      if (!(std::abs(m->clearcoatNormalScale) <= kMaxNormalScale)) {
        *error = where + "/clearcoatNormalTexture/scale: " + number(m->clearcoatNormalScale) + " is outside [-" +
                 number(kMaxNormalScale) + ", " + number(kMaxNormalScale) + "]";
        return false;
      }
    }
    return extensionTextures(value, where,
                             {GltfSlot::ClearCoat, GltfSlot::ClearCoatRoughness, GltfSlot::ClearCoatNormal}, m, error);
  }

  // KHR_materials_anisotropy: the strength (in [0, 1]), the rotation (any finite angle: the scene
  // takes its cosine and sine) and the texture (RG the direction, B the strength, linear).
  bool anisotropy(const tinygltf::Value& value, const std::string& where, GltfMaterial* m, std::string* error) {
    m->features.anisotropy = true;
    if (!value.IsObject()) {
      *error = where + ": expected an object";
      return false;
    }
    if (!optionalNumber(value, "anisotropyStrength", where, &m->anisotropyStrength, error) ||
        !optionalNumber(value, "anisotropyRotation", where, &m->anisotropyRotation, error) ||
        !unit(m->anisotropyStrength, where + "/anisotropyStrength", &m->anisotropyStrength, error))
      return false;
    if (!std::isfinite(m->anisotropyRotation)) {
      *error = where + "/anisotropyRotation: " + number(m->anisotropyRotation) + " is not a finite angle";
      return false;
    }
    return extensionTextures(value, where, {GltfSlot::Anisotropy}, m, error);
  }

  // An extension's textureInfo objects (index, texCoord, KHR_texture_transform), into their slots.
  bool extensionTextures(const tinygltf::Value& value, const std::string& where, std::initializer_list<GltfSlot> slots,
                         GltfMaterial* m, std::string* error) {
    for (GltfSlot slot : slots) {
      const size_t s = size_t(slot);
      const char* key = kSlots[s].parameter;
      if (!value.Has(key)) continue;
      const tinygltf::Value& info = value.Get(key);
      const std::string at = where + "/" + key;
      if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt()) {
        *error = at + "/index: expected a texture index";
        return false;
      }
      const int texCoord =
          info.Has("texCoord") && info.Get("texCoord").IsInt() ? info.Get("texCoord").GetNumberAsInt() : 0;
      tinygltf::ExtensionMap extensions;
      if (info.Has("extensions") && info.Get("extensions").IsObject())
        for (const std::string& k : info.Get("extensions").Keys()) extensions[k] = info.Get("extensions").Get(k);
      if (!texture(info.Get("index").GetNumberAsInt(), texCoord, extensions, at, &m->textures[s], error)) return false;
      m->features.textured[s] = true;
      m->features.texCoord[s] = m->textures[s].texCoord;
      m->features.transformed[s] = m->textures[s].transformed;
    }
    return true;
  }

  // An extension's colour factor, when present: 3 numbers in [0, hi].
  bool colour(const tinygltf::Value& object, const char* key, const std::string& where, double hi,
              std::array<double, 3>* out, std::string* error) {
    if (!object.IsObject() || !object.Has(key)) return true;
    const tinygltf::Value& c = object.Get(key);
    if (!c.IsArray() || c.ArrayLen() != 3) {
      *error = where + "/" + key + ": expected 3 numbers";
      return false;
    }
    for (int i = 0; i < 3; ++i) {
      const double v = c.Get(i).IsNumber() ? c.Get(i).GetNumberAsDouble() : -1;
      if (!(v >= 0 && v <= hi)) {
        *error = where + "/" + key + "/" + std::to_string(i) + ": " +
                 (c.Get(i).IsNumber() ? number(v) : std::string("not a number")) + " is outside [0, " +
                 std::to_string(int(hi)) + "]";
        return false;
      }
      (*out)[size_t(i)] = v;
    }
    return true;
  }

  // An extension's number, when present (`out` keeps its default when absent).
  static bool optionalNumber(const tinygltf::Value& object, const char* key, const std::string& where, double* out,
                             std::string* error) {
    if (!object.Has(key)) return true;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsNumber()) {
      *error = where + "/" + key + ": not a number";
      return false;
    }
    *out = v.GetNumberAsDouble();
    return true;
  }

  static double numberIn(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.IsObject() || !object.Has(key) || !object.Get(key).IsNumber()) return fallback;
    return object.Get(key).GetNumberAsDouble();
  }

  bool unit(double v, const std::string& at, double* out, std::string* error) {
    if (!(v >= 0 && v <= 1)) {
      *error = at + ": " + number(v) + " is outside [0, 1]";
      return false;
    }
    *out = v;
    return true;
  }

  // An array factor: exactly `count` numbers in [lo, hi] (tinygltf leaves the default when absent).
  bool factors(const std::vector<double>& values, size_t count, const std::string& at, double lo, double hi,
               double* out, std::string* error) {
    if (values.size() != count) {
      *error = at + ": expected " + std::to_string(count) + " numbers";
      return false;
    }
    for (size_t i = 0; i < count; ++i) {
      if (!(values[i] >= lo && values[i] <= hi)) {
        *error = at + "/" + std::to_string(i) + ": " + number(values[i]) + " is outside [" + number(lo) + ", " +
                 number(hi) + "]";
        return false;
      }
      out[i] = values[i];
    }
    return true;
  }

  bool texture(int index, int texCoord, const tinygltf::ExtensionMap& extensions, const std::string& at,
               GltfTextureUse* use, std::string* error) {
    if (size_t(index) >= model_.textures.size()) {
      *error = at + "/index: texture " + std::to_string(index) + " does not exist";
      return false;
    }
    const tinygltf::Texture& t = model_.textures[size_t(index)];
    const std::string textureAt = "/textures/" + std::to_string(index);
    if (t.source < 0 || size_t(t.source) >= model_.images.size()) {
      *error = textureAt + "/source: " +
               (t.source < 0 ? std::string("no image in a format Facet reads (PNG or JPEG)")
                             : "image " + std::to_string(t.source) + " does not exist");
      return false;
    }
    for (const auto& [name, value] : t.extensions) note(textureAt + "/extensions/" + name + ": extension not read");
    use->texture = index;
    use->image = t.source;
    use->texCoord = texCoord;
    for (const auto& [name, value] : extensions) {
      if (name != "KHR_texture_transform") {
        note(at + "/extensions/" + name + ": extension not read");
        continue;
      }
      const std::string where = at + "/extensions/KHR_texture_transform";
      use->transformed = true;
      if (!pair(value, "offset", where, &use->offset, error) || !pair(value, "scale", where, &use->scale, error))
        return false;
      use->rotation = numberIn(value, "rotation", 0);
      if (!(std::abs(use->rotation) <= kMaxUvValue)) {
        *error = where + "/rotation: " + number(use->rotation) + " is not a finite angle";
        return false;
      }
      if (value.Has("texCoord")) use->texCoord = int(numberIn(value, "texCoord", texCoord));
    }
    if (use->texCoord != 0 && use->texCoord != 1) {
      *error = at + "/texCoord: " + std::to_string(use->texCoord) + " (Facet reads TEXCOORD_0 and TEXCOORD_1)";
      return false;
    }
    if (t.sampler >= 0) {
      if (size_t(t.sampler) >= model_.samplers.size()) {
        *error = textureAt + "/sampler: sampler " + std::to_string(t.sampler) + " does not exist";
        return false;
      }
      if (!sampler(t.sampler, &use->sampler, error)) return false;
    }
    return true;
  }

  // glTF 2.0 §3.8.4 and its sampler schema: the enums' GL values; an absent filter is the
  // implementation's choice, trilinear here.
  bool sampler(int index, TextureSampler* out, std::string* error) {
    const tinygltf::Sampler& s = model_.samplers[size_t(index)];
    const std::string at = "/samplers/" + std::to_string(index);
    const auto wrap = [&](int value, const char* key, TextureWrap* w) {
      if (value == TINYGLTF_TEXTURE_WRAP_REPEAT)
        *w = TextureWrap::Repeat;
      else if (value == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE)
        *w = TextureWrap::ClampToEdge;
      else if (value == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT)
        *w = TextureWrap::MirroredRepeat;
      else {
        *error = at + "/" + key + ": " + std::to_string(value) +
                 " is not REPEAT (10497), CLAMP_TO_EDGE (33071) or MIRRORED_REPEAT (33648)";
        return false;
      }
      return true;
    };
    if (!wrap(s.wrapS, "wrapS", &out->wrapS) || !wrap(s.wrapT, "wrapT", &out->wrapT)) return false;
    if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST)
      out->magLinear = false;
    else if (s.magFilter != -1 && s.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR) {
      *error = at + "/magFilter: " + std::to_string(s.magFilter) + " is not NEAREST (9728) or LINEAR (9729)";
      return false;
    }
    switch (s.minFilter) {
      case -1:
      case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: break;
      case TINYGLTF_TEXTURE_FILTER_NEAREST:
      case TINYGLTF_TEXTURE_FILTER_LINEAR:
        out->mipmaps = false;
        out->minLinear = s.minFilter == TINYGLTF_TEXTURE_FILTER_LINEAR;
        break;
      case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
      case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
        out->mipLinear = false;
        out->minLinear = s.minFilter == TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST;
        break;
      case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: out->minLinear = false; break;
      default:
        *error = at + "/minFilter: " + std::to_string(s.minFilter) +
                 " is not a glTF minification filter (9728, 9729, 9984 to 9987)";
        return false;
    }
    return true;
  }

  // UV offsets and scales: finite and well inside fp32's exact integers.
  static constexpr double kMaxUvValue = 1e6;

  bool pair(const tinygltf::Value& object, const char* key, const std::string& at, std::array<double, 2>* out,
            std::string* error) {
    if (!object.IsObject() || !object.Has(key)) return true;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber()) {
      *error = at + "/" + key + ": expected 2 numbers";
      return false;
    }
    for (int i = 0; i < 2; ++i) {
      (*out)[size_t(i)] = v.Get(i).GetNumberAsDouble();
      if (!(std::abs((*out)[size_t(i)]) <= kMaxUvValue)) {
        *error =
            at + "/" + key + "/" + std::to_string(i) + ": " + number((*out)[size_t(i)]) + " is outside [-1e6, 1e6]";
        return false;
      }
    }
    return true;
  }

  const tinygltf::Model& model_;
  GltfMaterialSet* out_;
};

bool readImage(const tinygltf::Image& image, size_t index, GltfImage* out, std::string* error) {
  if (!image.image.empty()) {  // a data: URI or a bufferView, delivered by the image callback
    out->bytes.assign(image.image.begin(), image.image.end());
    out->mimeType = image.mimeType;
    return true;
  }
  if (image.uri.empty() || image.uri.rfind("data:", 0) == 0) {
    *error = "/images/" + std::to_string(index) + ": no image data (a uri or a bufferView)";
    return false;
  }
  out->uri = image.uri;
  return true;
}

}  // namespace

double GltfMaterial::reflectance() const {
  // Filament's reflectance: f0 = 0.16 · reflectance². KHR_materials_ior: f0 = ((ior − 1) / (ior + 1))²,
  // ior 0 standing for an infinite index (f0 = 1); KHR_materials_specular scales it by the colour
  // (its Rec. 709 luminance), clamps at 1 and scales by the factor.
  const double f0Ior = ior == 0 ? 1.0 : std::pow((ior - 1) / (ior + 1), 2);
  const auto& c = specularColorFactor;
  const double colour = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
  const double f0 = std::min(f0Ior * colour, 1.0) * specularFactor;
  return std::sqrt(f0 / 0.16);
}

std::string GltfFeatures::name() const {
  std::string name = "gltf";
  for (size_t s = 0; s < kGltfSlots; ++s)
    if (textured[s])
      name += "_" + std::string(kSlots[s].prefix) + std::to_string(texCoord[s]) + (transformed[s] ? "t" : "");
  if (vertexColors) name += "_vc";
  if (alphaMode == "MASK") name += "_mask" + featureNumber(alphaCutoff);
  if (alphaMode == "BLEND") name += "_blend";
  if (doubleSided) name += "_ds";
  if (sheen) name += "_sh";
  if (clearCoat) name += "_cc";
  if (anisotropy) name += "_an";
  return name;
}

std::optional<GltfMaterialSet> readGltfMaterials(const std::string& path, std::string* error,
                                                 const GltfReadOptions& options) {
  // The primitives the scene draws, split by material: which materials are used, and the file
  // checked as a scene would load it.
  auto meshes = loadGltfMeshesByMaterial(path, error, options);
  if (!meshes) return std::nullopt;
  GltfBudget own;
  uint64_t bytesRead = 0;
  std::optional<tinygltf::Model> model =
      gltf::readSource(path, {options.assetRoot, own.fileBytes, true}, &bytesRead, error);
  if (!model) return std::nullopt;
  GltfMaterialSet set;
  set.boundsMin.fill(std::numeric_limits<double>::max());
  set.boundsMax.fill(std::numeric_limits<double>::lowest());
  for (const auto& [index, mesh] : *meshes) {
    for (size_t v = 0; v + abi::kVertexFloats <= mesh.vertices.size(); v += abi::kVertexFloats) {
      for (size_t c = 0; c < 3; ++c) {
        set.boundsMin[c] = std::min(set.boundsMin[c], double(mesh.vertices[v + c]));
        set.boundsMax[c] = std::max(set.boundsMax[c], double(mesh.vertices[v + c]));
      }
    }
  }
  Reader reader(*model, &set);
  for (const std::string& name : model->extensionsUsed)
    if (std::find(std::begin(kReadExtensions), std::end(kReadExtensions), name) == std::end(kReadExtensions))
      reader.note("/extensionsUsed: optional extension '" + name + "' is not read; skipped");
  // Vertex colours belong to primitives: a material gets them when any primitive drawn with it
  // has COLOR_0 (a primitive without them reads white, runtime::Vertex's default).
  std::set<int> coloured;
  for (const tinygltf::Mesh& mesh : model->meshes)
    for (const tinygltf::Primitive& p : mesh.primitives)
      if (p.attributes.count("COLOR_0")) coloured.insert(std::max(p.material, -1));
  std::string why;
  for (const auto& [index, mesh] : *meshes) {
    if (!reader.material(index, coloured.count(index) > 0, &why)) {
      *error = path + ": error: " + why;
      return std::nullopt;
    }
  }
  // KHR_materials_anisotropy's direction lives in the tangent frame: a primitive without TANGENT
  // gets tangents only from its normal texture (MikkTSpace; the extension requires one of the two),
  // otherwise its tangent is +x (runtime::Vertex's default), which the note says.
  for (size_t mi = 0; mi < model->meshes.size(); ++mi) {
    const std::vector<tinygltf::Primitive>& primitives = model->meshes[mi].primitives;
    for (size_t pi = 0; pi < primitives.size(); ++pi) {
      const tinygltf::Primitive& p = primitives[pi];
      const auto m = std::find_if(set.materials.begin(), set.materials.end(),
                                  [&](const GltfMaterial& g) { return g.index == p.material && g.index >= 0; });
      if (m == set.materials.end() || !m->features.anisotropy || p.attributes.count("TANGENT") ||
          m->features.textured[size_t(GltfSlot::Normal)])
        continue;
      reader.note("/meshes/" + std::to_string(mi) + "/primitives/" + std::to_string(pi) +
                  ": KHR_materials_anisotropy without TANGENT or a normal texture; its direction turns from +x");
    }
  }
  set.images.resize(model->images.size());
  for (size_t i = 0; i < model->images.size(); ++i) {
    if (!readImage(model->images[i], i, &set.images[i], &why)) {
      *error = path + ": error: " + why;
      return std::nullopt;
    }
  }
  return set;
}

namespace {

// KHR_materials_anisotropy onto Facet's anisotropic lobe (docs/gltf.md, "Anisotropy"). The
// extension's lobe is the anisotropic GGX with α_t = mix(α, 1, s²) along its direction and α_b = α
// across, α = r²; Facet's is the same D and V with α_t = α′(1 + k), α_b = α′(1 − k), α′ = r′²
// (chunks/anisotropy_frame.glsl). So α′ = (α_t + α_b) / 2 and k = (α_t − α_b) / (α_t + α_b) give
// the extension's pair exactly. Both are first floored at Facet's α_min = 0.089², the floor every
// Facet lobe takes (α′ ≥ α_min then, so the division is by at least 2 α_min and Facet's own clamps
// leave the pair as it is). The direction is the extension's, (cos ρ, sin ρ) turning the texture's
// 2 · rg − 1 counter-clockwise; it is not normalized: the frame normalizes it after projecting it
// onto the shading normal's plane (a zero texel direction takes the frame's fallback, not a NaN).
// `texel`: the anisotropy texture's sample, "" without one.
std::string anisotropySource(const std::string& texel) {
  std::string text =
      "        // KHR_materials_anisotropy: the extension's (alpha along, alpha across) as Facet's\n"
      "        // roughness and anisotropy (docs/gltf.md, \"Anisotropy\")\n";
  std::string strength = "params.anisotropyStrength";
  if (!texel.empty()) {
    text += "        let anisotropyTexel = " + texel + "\n";
    strength += " * anisotropyTexel.b";
  }
  text += "        let anisotropyStrength = " + strength +
          "\n"
          "        let gltfAlpha = gltfRoughness * gltfRoughness\n"
          "        let alphaAcross = max(gltfAlpha, 0.007921)\n"
          "        let alphaAlong = max(mix(gltfAlpha, 1.0, anisotropyStrength * anisotropyStrength), 0.007921)\n"
          "        roughness = sqrt(0.5 * (alphaAlong + alphaAcross))\n"
          "        anisotropy = (alphaAlong - alphaAcross) / (alphaAlong + alphaAcross)\n";
  if (texel.empty()) {
    text += "        anisotropyDirection = vec3(params.anisotropyRotation, 0.0)\n";
  } else {
    text +=
        "        let texelDirection = anisotropyTexel.rg * 2.0 - 1.0\n"
        "        anisotropyDirection = vec3(params.anisotropyRotation.x * texelDirection.x - "
        "params.anisotropyRotation.y * texelDirection.y,\n"
        "            params.anisotropyRotation.y * texelDirection.x + params.anisotropyRotation.x * texelDirection.y, "
        "0.0)\n";
  }
  return text;
}

}  // namespace

std::string gltfMaterialSource(const GltfFeatures& f) {
  using S = GltfSlot;
  const auto has = [&](S s) { return f.textured[size_t(s)]; };
  std::string text =
      "// glTF 2.0 metallic-roughness (glTF 2.0 §3.9), written by `matc import` for the feature set\n"
      "// its name spells (docs/gltf.md, \"The materials\"). Factors multiply texels and vertex\n"
      "// colours as the specification's appendix B does.\n";
  text += "material " + f.name() + " {\n    shading lit\n";
  if (f.alphaMode == "MASK") text += "    blending masked(" + number(f.alphaCutoff) + ")\n";
  if (f.alphaMode == "BLEND") text += "    blending transparent\n";
  if (f.doubleSided) text += "    doubleSided\n";
  text +=
      "\n    param baseColorFactor: vec4 = vec4(1.0, 1.0, 1.0, 1.0) in [0, 1]\n"
      "    param metallicFactor: float = 1.0 in [0, 1]\n"
      "    param roughnessFactor: float = 1.0 in [0, 1]\n"
      "    param emissiveFactor: vec3 = vec3(0.0, 0.0, 0.0) in [0, " +
      number(Reader::kMaxEmissiveStrength) +
      "]\n"
      "    // Filament's reflectance from KHR_materials_ior: f0 = ((ior - 1) / (ior + 1))^2 = 0.16 reflectance^2\n"
      "    param reflectance: float = 0.5 in [0, 2.5]\n";
  if (has(S::Normal)) text += "    param normalScale: float = 1.0 in [-100, 100]\n";
  if (has(S::Occlusion)) text += "    param occlusionStrength: float = 1.0 in [0, 1]\n";
  if (f.sheen)
    text +=
        "    // KHR_materials_sheen: a sheen layer over the base (docs/material-models.md, \"Sheen layer\")\n"
        "    param sheenColorFactor: vec3 = vec3(0.0, 0.0, 0.0) in [0, 1]\n"
        "    param sheenRoughnessFactor: float = 0.0 in [0, 1]\n";
  if (f.clearCoat)
    text +=
        "    // KHR_materials_clearcoat: Facet's clear coat (docs/material-models.md, \"Clear coat\")\n"
        "    param clearcoatFactor: float = 0.0 in [0, 1]\n"
        "    param clearcoatRoughnessFactor: float = 0.0 in [0, 1]\n";
  if (f.anisotropy)
    text +=
        "    // KHR_materials_anisotropy: its strength, and (cos, sin) of its rotation\n"
        "    param anisotropyStrength: float = 0.0 in [0, 1]\n"
        "    param anisotropyRotation: vec2 = vec2(1.0, 0.0) in [-1, 1]\n";
  if (has(S::ClearCoatNormal)) text += "    param clearcoatNormalScale: float = 1.0 in [-100, 100]\n";
  for (size_t s = 0; s < kGltfSlots; ++s) {
    if (!f.textured[s]) continue;
    const SlotInfo& slot = kSlots[s];
    text += "    param " + std::string(slot.parameter) + ": texture(" + slot.kind + ") = " + slot.fallback + "\n";
    if (f.transformed[s])
      text += "    param " + std::string(slot.parameter) + "Offset: vec2 = vec2(0.0, 0.0) in [-1e6, 1e6]\n" +
              "    param " + slot.parameter + "Rotation: float = 0.0 in [-1e6, 1e6]\n" + "    param " + slot.parameter +
              "Scale: vec2 = vec2(1.0, 1.0) in [-1e6, 1e6]\n";
  }
  text += "\n    surface {\n";
  // KHR_texture_transform: uv' = T · R · S · uv, R turning the UVs counter-clockwise by `rotation`
  // in glTF's UV space, whose v points down: u' = cos · u + sin · v, v' = −sin · u + cos · v. That
  // is the extension's prose, which Khronos's TextureTransformTest sample follows; its GLSL
  // listing, mat3(cos, sin, 0, -sin, cos, 0, 0, 0, 1) column-major, is the transpose (a
  // counter-clockwise turn with v up), with which the sample's rotated arrow points at its red
  // "rotated the wrong way" marker (TextureTransformRotationTurnsTheImageClockwise). v' is written
  // −sin · u + cos · v: as cos · v − sin · u, Mesa's Adreno 630 compiler takes 209 fragment
  // instructions for `gltf_bc1t` instead of 201 (Mali-G57 the same either way; docs/gltf.md).
  std::string sampled[kGltfSlots];
  for (size_t s = 0; s < kGltfSlots; ++s) {
    if (!f.textured[s]) continue;
    const std::string p = kSlots[s].parameter, uv = "vertex.uv" + std::to_string(f.texCoord[s]);
    std::string coordinate = uv;
    if (f.transformed[s]) {
      text += "        let " + p + "Uv = vec2(cos(params." + p + "Rotation) * params." + p + "Scale.x * " + uv +
              ".x + sin(params." + p + "Rotation) * params." + p + "Scale.y * " + uv + ".y,\n" +
              "            -sin(params." + p + "Rotation) * params." + p + "Scale.x * " + uv + ".x + cos(params." + p +
              "Rotation) * params." + p + "Scale.y * " + uv + ".y) + params." + p + "Offset\n";
      coordinate = p + "Uv";
    }
    sampled[s] = "sample(params." + p + ", " + coordinate + ")";
  }
  const std::string colour = f.vertexColors ? " * vertex.color" : "";
  if (has(S::BaseColor)) {
    text += "        let base = params.baseColorFactor * " + sampled[size_t(S::BaseColor)] + colour + "\n";
  } else {
    text += "        let base = params.baseColorFactor" + colour + "\n";
  }
  text += "        baseColor = base.rgb\n";
  if (f.alphaMode != "OPAQUE") text += "        alpha = base.a\n";
  // With KHR_materials_anisotropy the glTF roughness is the extension's α = r² across the direction,
  // remapped below.
  const std::string roughness = f.anisotropy ? "let gltfRoughness" : "roughness";
  if (has(S::MetallicRoughness)) {
    text += "        let metalRough = " + sampled[size_t(S::MetallicRoughness)] + "\n" +
            "        metallic = params.metallicFactor * metalRough.b\n" + "        " + roughness +
            " = params.roughnessFactor * metalRough.g\n";
  } else {
    text += "        metallic = params.metallicFactor\n        " + roughness + " = params.roughnessFactor\n";
  }
  if (f.anisotropy) text += anisotropySource(has(S::Anisotropy) ? sampled[size_t(S::Anisotropy)] : "");
  text += "        reflectance = params.reflectance\n";
  if (has(S::Normal)) {
    text += "        let mapped = " + sampled[size_t(S::Normal)] + "\n" +
            "        normal = vec3(mapped.xy * params.normalScale, mapped.z)\n";
  }
  if (has(S::Occlusion))
    text +=
        "        ambientOcclusion = 1.0 + params.occlusionStrength * (" + sampled[size_t(S::Occlusion)] + ".r - 1.0)\n";
  text += has(S::Emissive) ? "        emissive = params.emissiveFactor * " + sampled[size_t(S::Emissive)] + ".rgb\n"
                           : "        emissive = params.emissiveFactor\n";
  if (f.sheen) {
    text += "        sheenColor = params.sheenColorFactor" +
            (has(S::SheenColor) ? " * " + sampled[size_t(S::SheenColor)] + ".rgb" : std::string()) + "\n";
    text += "        sheenRoughness = params.sheenRoughnessFactor" +
            (has(S::SheenRoughness) ? " * " + sampled[size_t(S::SheenRoughness)] + ".a" : std::string()) + "\n";
  }
  if (f.clearCoat) {
    text += "        clearCoat = params.clearcoatFactor" +
            (has(S::ClearCoat) ? " * " + sampled[size_t(S::ClearCoat)] + ".r" : std::string()) + "\n";
    text += "        clearCoatRoughness = params.clearcoatRoughnessFactor" +
            (has(S::ClearCoatRoughness) ? " * " + sampled[size_t(S::ClearCoatRoughness)] + ".g" : std::string()) + "\n";
    if (has(S::ClearCoatNormal))
      text += "        let coatMapped = " + sampled[size_t(S::ClearCoatNormal)] + "\n" +
              "        clearCoatNormal = vec3(coatMapped.xy * params.clearcoatNormalScale, coatMapped.z)\n";
  }
  text += "    }\n}\n";
  return text;
}

}  // namespace facet::runtime
