// Materials and their instances, as an engine uses them: a Material is made once per package and
// variant (tier and lights pick the variant, as for scenes); each MaterialInstance holds its own
// parameter values and textures. Parameter names resolve once to handles; the std140 bytes live
// in a UniformBlock the backends keep on the GPU and upload again only when a value changed.
//
//   auto material = Material::create(std::move(loaded), {"high", true, 0}, &error);
//   auto roughness = material->parameter("roughness");
//   auto a = material->createInstance(), b = material->createInstance();
//   b->setParameter(*roughness, 0.8f, &error);
//   frame.draws.push_back(a->draw(mesh, modelLeft));
//   frame.draws.push_back(b->draw(mesh, modelRight));
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/runtime/material.h"
#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// A parameter of one Material, resolved from its name once.
struct ParameterHandle {
  uint32_t index = 0;  // into the package's parameter list
};

// What picks the variant: the tier ("reference", "high", "mid", "low") and the lights the frame
// has (a directional sun, 0..kMaxPunctualLights point/spot lights).
struct VariantRequest {
  std::string tier = "high";
  bool sun = true;
  int pointLights = 0;
  int shadowCascades = 0;   // the sun's cascades the variant receives (0: no shadow; docs/shadows.md)
  bool spotShadow = false;  // it receives light slot 0's spot shadow (`.sp1`; docs/shadows.md, "Spot shadows")
};

class MaterialInstance;

class Material : public std::enable_shared_from_this<Material> {
 public:
  // Picks the variant, extracts its shaders once (SPIR-V validated, LoadedMaterial::program) and
  // its package textures, and packs the default parameter block. nullptr and *error on failure.
  static std::shared_ptr<Material> create(LoadedMaterial loaded, const VariantRequest& request, std::string* error);

  const LoadedMaterial& loaded() const { return loaded_; }
  const std::string& variantKey() const { return variantKey_; }
  const ShaderProgram& program() const { return program_; }
  ColorEncoding colors() const { return colors_; }
  Blending blending() const { return blending_; }
  bool masked() const { return masked_; }  // blending masked: alpha tested (DrawItem::masked)
  bool doubleSided() const { return doubleSided_; }
  // The package textures the variant samples (LoadedMaterial::generatedTextures), made once.
  const std::vector<TextureBinding>& generatedTextures() const { return generated_; }

  // nullopt when the material has no parameter of that name.
  std::optional<ParameterHandle> parameter(std::string_view name) const;
  // An instance with the declared defaults and default textures. It keeps this Material alive.
  std::unique_ptr<MaterialInstance> createInstance() const;

 private:
  friend class MaterialInstance;
  explicit Material(LoadedMaterial loaded) : loaded_(std::move(loaded)) {}

  LoadedMaterial loaded_;
  std::string variantKey_;
  ShaderProgram program_;
  ColorEncoding colors_ = ColorEncoding::Linear;
  Blending blending_ = Blending::Opaque;
  bool masked_ = false;
  bool doubleSided_ = false;
  std::vector<uint8_t> defaults_;                        // std140 block of the declared defaults
  std::vector<TextureBinding> generated_;                // package textures of the variant
  std::vector<TextureBinding> defaultTextures_;          // package textures, then one per texture param
  std::vector<std::unique_ptr<Texture>> solidTextures_;  // the texture params' default colours
  std::vector<int> textureOfParam_;                      // per parameter: its index in defaultTextures_, or -1
};

class MaterialInstance {
 public:
  // Typed setters: the value's type must be the parameter's (float; int; bool; 2/3/4 floats for
  // vec2/vec3 or color/vec4; colours sRGB-encoded as authored). Range, type and finiteness are
  // checked as for scenes (LoadedMaterial::paramBlock). False with *error, the value unchanged,
  // on a mismatch. Setting the value a parameter already has does not count as a change.
  bool setParameter(ParameterHandle handle, float value, std::string* error);
  bool setParameter(ParameterHandle handle, int32_t value, std::string* error);
  bool setParameter(ParameterHandle handle, bool value, std::string* error);
  bool setParameter(ParameterHandle handle, const std::array<float, 2>& value, std::string* error);
  bool setParameter(ParameterHandle handle, const std::array<float, 3>& value, std::string* error);
  bool setParameter(ParameterHandle handle, const std::array<float, 4>& value, std::string* error);
  // The same by name (resolved on every call: keep a handle for per-frame updates).
  template <class T>
  bool setParameter(std::string_view name, const T& value, std::string* error) {
    auto handle = resolve(name, error);
    return handle && setParameter(*handle, value, error);
  }

  // The texture a texture parameter samples; it must outlive the draws that use it. Its format
  // is used as given (Rgba8Srgb to have the sampler decode sRGB).
  bool setTexture(ParameterHandle handle, const Texture* texture, std::string* error);
  bool setTexture(std::string_view name, const Texture* texture, std::string* error);

  // A draw of `mesh` with this instance, `model` column-major (object to world). The draw points
  // at this instance's block and textures: the instance must outlive the frame it is drawn in.
  DrawItem draw(const Mesh& mesh, const std::array<float, 16>& model) const;
  // One draw of `mesh` at each of `models` (an instance each, drawn in this order): what N
  // objects sharing the mesh and this instance cost as one draw call. At most
  // abi::kMaxInstancesPerDraw models (the backend refuses the frame otherwise).
  DrawItem draw(const Mesh& mesh, std::span<const std::array<float, 16>> models) const;

  const Material& material() const { return *material_; }
  const UniformBlock& block() const { return block_; }

 private:
  friend class Material;
  explicit MaterialInstance(std::shared_ptr<const Material> material);
  std::optional<ParameterHandle> resolve(std::string_view name, std::string* error) const;
  bool set(ParameterHandle handle, std::vector<double> values, bool typeMatches, bool isBool, std::string* error);

  std::shared_ptr<const Material> material_;
  UniformBlock block_;
  std::vector<TextureBinding> textures_;
};

}  // namespace facet::runtime
