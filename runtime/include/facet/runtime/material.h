// A material package loaded by an app: variant lookup and parameter block packing.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "facet/package/package.h"
#include "facet/package/package_reader.h"
#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// How colour values reach the shaders. Linear: colour parameters converted from sRGB, sRGB
// textures decoded by the sampler. Srgb: both left encoded, for the variants that light with
// the gamma hack (chunks/shading_standard.glsl), which square their result back: no preset does
// (in low it loses error and costs more than lighting in linear: docs/eval.md, "Why the tiers
// are built as they are"); `matc eval` selects it for its colour-space swap (eval/prepared_frame.h).
enum class ColorEncoding { Linear, Srgb };

class LoadedMaterial {
 public:
  // Reads and validates a .matpkg (its tables and meaning, package::loadError; no shader is
  // decompressed until program() asks for its variant); nullopt with *error on any problem with
  // the file.
  static std::optional<LoadedMaterial> load(const std::string& path, std::string* error);
  // The same from bytes the app owns, which must outlive the LoadedMaterial: shaders stored
  // uncompressed are used in place. `name` prefixes messages as the path does for load().
  static std::optional<LoadedMaterial> loadFromMemory(std::span<const uint8_t> bytes, const std::string& name,
                                                      std::string* error);

  const package::MaterialInfo& info() const { return reader_.material(); }
  const package::PackageReader& reader() const { return reader_; }

  // The shaders of one variant, for every API, decompressed on the first request for the
  // variant. A key the package was not built with is an error that lists the keys it has (the
  // compiler builds only what a scene asks for). Each shader's code is checked before any
  // backend sees it (package::checkVariant, facet/package/checks.h): its kind, SPIR-V validated
  // (SPIRV-Tools) with one entry point of its slot's stage, and each SPIR-V stage's interface
  // against the package's (program_interface.h); the program carries that interface, which the GL
  // backend checks its linked program against.
  std::optional<ShaderProgram> program(const std::string& variantKey, std::string* error) const;
  // program()'s checks on every variant (package::checkEveryVariant, which `matc info` runs to
  // say whether an app would draw the package). False with the first variant's error.
  bool checkEveryVariant(std::string* error) const;

  // The std140 "MaterialParams" bytes: declared defaults, overridden by `values` (by name;
  // colour values are sRGB-encoded, as authored, and converted to linear here). Unknown names,
  // wrong component counts and values outside a declared range are errors.
  // With ColorEncoding::Srgb colour values stay as authored, and defaults are encoded back.
  // `givenAsBool` names the values the scene wrote as true/false: only a bool parameter takes
  // one, and a bool parameter takes nothing else; an int parameter takes whole numbers only.
  std::optional<std::vector<uint8_t>> paramBlock(const std::map<std::string, std::vector<double>>& values,
                                                 std::string* error, ColorEncoding colors = ColorEncoding::Linear,
                                                 const std::set<std::string>& givenAsBool = {}) const;

  // Completes a paramBlock() for a variant: with a preshader program (format 1.3), the block
  // grows to the preshaded size and the program writes the derived members after the parameters
  // (runtime/preshader.h); without one the block is left as it is. Run it after every change of
  // the parameters. False with *error when the program is refused.
  bool preshade(const std::string& variantKey, std::vector<uint8_t>* block, std::string* error) const;

  // The textures the compiler generated for the variant's shaders (package section TEXS, e.g.
  // the `lut` tier's specular table), bound at their shader_abi.h slots. The Textures are made
  // once per package and live as long as this LoadedMaterial. A texture this
  // runtime has no slot for is an error for the variants that sample it.
  // A texture is decompressed on the first request for a variant that samples it.
  std::optional<std::vector<TextureBinding>> generatedTextures(const std::string& variantKey, std::string* error) const;

  struct SampledTexture {
    std::string param;      // texture parameter name
    uint32_t slot = 0;      // sampler slot: binding abi::kMaterialTextureBase + slot
    std::string glslName;   // abi::kMaterialSamplerPrefix + <param>
    std::string imagePath;  // "" when the scene gives none: use defaultValue
    bool srgb = false;
    std::array<double, 4> defaultValue{};
  };
  // The textures the material samples, with the image a scene gives for each (by parameter
  // name) or none. Naming an image for a parameter that is not a texture is an error.
  std::optional<std::vector<SampledTexture>> sampledTextures(const std::map<std::string, std::string>& images,
                                                             std::string* error) const;

 private:
  explicit LoadedMaterial(package::PackageReader reader);
  static std::optional<LoadedMaterial> checked(std::optional<package::PackageReader> reader, const std::string& name,
                                               std::string* error);

  package::PackageReader reader_;
  // Parallel to reader_.textures(), made on first use; unique_ptr so that the Texture pointers
  // generatedTextures() hands out survive a move of the LoadedMaterial.
  mutable std::vector<std::unique_ptr<Texture>> textures_;
};

}  // namespace facet::runtime
