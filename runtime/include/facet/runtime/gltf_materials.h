// glTF 2.0 metallic-roughness materials as Facet materials (docs/gltf.md). A glTF material is
// an instance — factors and textures — of one compiled Facet material per distinct feature set:
// which textures it samples and from which UV set, which of them are transformed
// (KHR_texture_transform), vertex colours, alpha mode and cutoff, double-sidedness. Materials
// with the same feature set share one .mat and so one package.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/runtime/gltf_mesh.h"
#include "facet/scene/texture_sampler.h"

namespace facet::runtime {

// The texture slots of glTF's metallic-roughness material, in the order of this enum.
// KHR_materials_sheen's two textures, KHR_materials_clearcoat's three and
// KHR_materials_anisotropy's one follow the core ones.
enum class GltfSlot {
  BaseColor,
  MetallicRoughness,
  Normal,
  Occlusion,
  Emissive,
  SheenColor,
  SheenRoughness,
  ClearCoat,
  ClearCoatRoughness,
  ClearCoatNormal,
  Anisotropy
};
inline constexpr size_t kGltfSlots = 11;

// One texture a material samples.
struct GltfTextureUse {
  int texture = -1;          // /textures index; -1: none in this slot
  int image = -1;            // its /images index
  int texCoord = 0;          // 0 or 1 (KHR_texture_transform's texCoord, when given, replaces the textureInfo's)
  bool transformed = false;  // KHR_texture_transform present
  std::array<double, 2> offset{0, 0};
  double rotation = 0;  // radians
  std::array<double, 2> scale{1, 1};
  TextureSampler sampler;  // its /samplers entry (default: repeat, trilinear)
};

// What decides the compiled material. Two glTF materials with equal features share one.
struct GltfFeatures {
  std::array<bool, kGltfSlots> textured{};
  std::array<int, kGltfSlots> texCoord{};
  std::array<bool, kGltfSlots> transformed{};
  bool vertexColors = false;  // a primitive drawn with the material has COLOR_0
  std::string alphaMode = "OPAQUE";
  double alphaCutoff = 0.5;  // MASK only
  bool doubleSided = false;
  bool sheen = false;       // KHR_materials_sheen present: a sheen layer (sheenColor, sheenRoughness)
  bool clearCoat = false;   // KHR_materials_clearcoat present: a clear coat (clearCoat, its roughness and normal)
  bool anisotropy = false;  // KHR_materials_anisotropy present: Facet's anisotropy, the roughness remapped

  // The Facet material's name: "gltf" and one part per feature, e.g. gltf_bc0_mr0_n0_ao1_em0_ds.
  std::string name() const;
};

struct GltfMaterial {
  int index = -1;    // /materials index; -1: glTF's default material (primitives without one)
  std::string name;  // the glTF material's own, for messages
  GltfFeatures features;
  std::array<double, 4> baseColorFactor{1, 1, 1, 1};
  double metallicFactor = 1;
  double roughnessFactor = 1;
  double normalScale = 1;
  double occlusionStrength = 1;
  std::array<double, 3> emissiveFactor{0, 0, 0};  // × KHR_materials_emissive_strength
  double ior = 1.5;                               // KHR_materials_ior
  // KHR_materials_specular: the dielectric f0 = min(f0(ior) · specularColorFactor, 1) · specularFactor.
  double specularFactor = 1;
  std::array<double, 3> specularColorFactor{1, 1, 1};
  // KHR_materials_sheen's factors (linear colour, perceptual roughness; the extension's defaults).
  std::array<double, 3> sheenColorFactor{0, 0, 0};
  double sheenRoughnessFactor = 0;
  // KHR_materials_clearcoat's factors and its normal texture's scale (the extension's defaults).
  double clearcoatFactor = 0;
  double clearcoatRoughnessFactor = 0;
  double clearcoatNormalScale = 1;
  // KHR_materials_anisotropy's strength (in [0, 1]) and rotation (radians, counter-clockwise from
  // the tangent; the extension's defaults).
  double anisotropyStrength = 0;
  double anisotropyRotation = 0;
  std::array<GltfTextureUse, kGltfSlots> textures;

  // Facet's `reflectance` (f0 = 0.16 · reflectance², a scalar, f90 = 1; docs/gltf.md): from the
  // ior and KHR_materials_specular's factors, the colour taken by its luminance.
  double reflectance() const;
};

// An image a material uses: a relative URI of a file beside the glTF file (as stored, decoded),
// or the bytes of an embedded one (a data: URI or a bufferView) with its MIME type.
struct GltfImage {
  std::string uri;
  std::vector<uint8_t> bytes;
  std::string mimeType;
};

struct GltfMaterialSet {
  std::vector<GltfMaterial> materials;  // those the file's scene draws, by index (-1 first)
  std::vector<GltfImage> images;        // by /images index
  // What was read but is not drawn as the file says: optional extensions skipped, sampler
  // settings other than repeat and linear filtering. Each names its JSON pointer.
  std::vector<std::string> notes;
  // The placed triangles' bounds (node transforms applied).
  std::array<double, 3> boundsMin{0, 0, 0}, boundsMax{0, 0, 0};
};

// The materials of the primitives the file's scene draws (as loadGltfMeshesByMaterial splits
// them; the file is read with every check loadGltfMesh makes). Errors as loadGltfMesh's:
// `m.gltf: error: <JSON pointer>: ...` for a texture or image that does not exist, a texCoord
// other than 0 and 1, a factor outside the spec's range, a texture without an image.
std::optional<GltfMaterialSet> readGltfMaterials(const std::string& path, std::string* error,
                                                 const GltfReadOptions& options = {});

// The .mat source of the Facet material for a feature set (docs/gltf.md, "The materials").
std::string gltfMaterialSource(const GltfFeatures& features);

}  // namespace facet::runtime

namespace facet::runtime {

// What `matc import` wrote (docs/gltf.md).
struct GltfImport {
  std::string scene;                   // <out>/<file stem>.json
  std::vector<std::string> materials;  // <out>/<feature set>.mat, one per distinct feature set
  std::vector<std::string> images;     // <out>/<file stem>_images/<n>.png|.jpg: the embedded images
  std::vector<std::string> notes;      // GltfMaterialSet::notes
};

// Writes the Facet side of a glTF file into `outDir` (created if missing): one .mat per feature
// set, the file's embedded images, and a scene drawing each material's primitives with its
// material (objects with `gltfMaterial`), lit by a sun and a sky, the camera framing the file's
// bounds. The glTF file and its image files must lie inside `assetRoot` ("": `outDir`), the
// folder the scene will be allowed to read from (a scene reads files from its own folder unless
// the app widens it: facet-view --asset-root); all files are written together or none
// (package::writeFiles).
bool importGltf(const std::string& path, const std::string& outDir, const std::string& assetRoot, GltfImport* result,
                std::string* error);

}  // namespace facet::runtime
