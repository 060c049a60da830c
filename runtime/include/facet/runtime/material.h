// A material package loaded by an app: variant lookup and parameter block packing.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "facet/package.h"
#include "facet/render_backend.h"

namespace facet::runtime {

class LoadedMaterial {
 public:
  // Reads and validates a .matpkg; nullopt with *error on any problem with the file.
  static std::optional<LoadedMaterial> load(const std::string& path, std::string* error);

  const package::MaterialInfo& info() const { return package_.material; }
  const package::Package& package() const { return package_; }

  // The shaders of one variant, for every API. A key the package was not built with is an
  // error that lists the keys it has (the compiler builds only what a scene asks for).
  std::optional<ShaderProgram> program(const std::string& variantKey, std::string* error) const;

  // The std140 "MaterialParams" bytes: declared defaults, overridden by `values` (by name;
  // colour values are sRGB-encoded, as authored, and converted to linear here). Unknown names,
  // wrong component counts and values outside a declared range are errors.
  std::optional<std::vector<uint8_t>> paramBlock(const std::map<std::string, std::vector<double>>& values,
                                                 std::string* error) const;

  struct SampledTexture {
    std::string param;        // texture parameter name
    uint32_t slot = 0;        // sampler slot: binding abi::kMaterialTextureBase + slot
    std::string glslName;     // "material_<param>"
    std::string imagePath;    // "" when the scene gives none: use defaultValue
    bool srgb = false;
    std::array<double, 4> defaultValue{};
  };
  // The textures the material samples, with the image a scene gives for each (by parameter
  // name) or none. Naming an image for a parameter that is not a texture is an error.
  std::optional<std::vector<SampledTexture>> sampledTextures(const std::map<std::string, std::string>& images,
                                                             std::string* error) const;

 private:
  package::Package package_;
};

}  // namespace facet::runtime
