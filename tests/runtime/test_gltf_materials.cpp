// glTF materials as Facet materials (docs/gltf.md): the feature sets and instances read from
// tests/data/gltf/features.gltf (tests/data/gltf/make_features.py says what each material
// covers), the .mat each feature set becomes (compiled for every tier), `matc import`'s scene,
// and that scene rendered on Vulkan and GLES.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <set>

#include "facet/abi/shader_abi.h"
#include "facet/eval/standard_model.h"
#include "facet/runtime/gl_backend.h"
#include "facet/runtime/gltf_materials.h"
#include "facet/runtime/png.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/runtime/vulkan_backend.h"
#include "test_compile.h"
#include "test_images.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using facet::runtime::GltfMaterial;
using facet::runtime::GltfSlot;

std::string featuresFile() { return facet::test::sourceDir() + "/tests/data/gltf/features.gltf"; }

const GltfMaterial* find(const facet::runtime::GltfMaterialSet& set, int index) {
  for (const GltfMaterial& m : set.materials)
    if (m.index == index) return &m;
  return nullptr;
}

bool hasNote(const std::vector<std::string>& notes, const std::string& text) {
  return std::find(notes.begin(), notes.end(), text) != notes.end();
}

TEST(GltfMaterials, FeatureSetsAndInstancesFollowTheFile) {
  std::string error;
  auto set = facet::runtime::readGltfMaterials(featuresFile(), &error);
  ASSERT_TRUE(set) << error;
  ASSERT_EQ(set->materials.size(), 6u);
  const std::pair<int, const char*> names[] = {{-1, "gltf"},
                                               {0, "gltf_bc0_mr0_n0_ao1_em0"},
                                               {1, "gltf_bc0_mr0_n0_ao1_em0"},
                                               {2, "gltf_bc0_mask0p3_ds"},
                                               {3, "gltf_vc_blend"},
                                               {4, "gltf_bc1t"}};
  for (const auto& [index, name] : names) {
    const GltfMaterial* m = find(*set, index);
    ASSERT_NE(m, nullptr) << index;
    EXPECT_EQ(m->features.name(), name) << index;
  }
  const GltfMaterial& everything = *find(*set, 0);
  EXPECT_EQ(everything.baseColorFactor, (std::array<double, 4>{1, 0.9, 0.8, 1}));
  EXPECT_DOUBLE_EQ(everything.metallicFactor, 0.7);
  EXPECT_DOUBLE_EQ(everything.roughnessFactor, 0.6);
  EXPECT_DOUBLE_EQ(everything.normalScale, 0.5);
  EXPECT_DOUBLE_EQ(everything.occlusionStrength, 0.8);
  // KHR_materials_emissive_strength multiplies the factor.
  EXPECT_EQ(everything.emissiveFactor, (std::array<double, 3>{2, 1, 0.4}));
  EXPECT_EQ(everything.textures[size_t(GltfSlot::Occlusion)].texCoord, 1);
  // The twin shares the feature set, with its own factors and base colour image.
  const GltfMaterial& twin = *find(*set, 1);
  EXPECT_DOUBLE_EQ(twin.metallicFactor, 0.1);
  EXPECT_EQ(twin.textures[size_t(GltfSlot::BaseColor)].image, 4);
  const GltfMaterial& transformed = *find(*set, 4);
  const auto& t = transformed.textures[size_t(GltfSlot::BaseColor)];
  EXPECT_TRUE(t.transformed);
  EXPECT_EQ(t.texCoord, 1);  // the transform's texCoord replaces the textureInfo's
  EXPECT_EQ(t.offset, (std::array<double, 2>{0.25, -0.5}));
  EXPECT_DOUBLE_EQ(t.rotation, 0.5);
  EXPECT_EQ(t.scale, (std::array<double, 2>{2, 3}));
  EXPECT_DOUBLE_EQ(transformed.ior, 1.45);
  // KHR_materials_specular: f0 = min(f0(ior) · colour, 1) · factor, as Facet's reflectance
  // (f0 = 0.16 · reflectance²): a grey colour maps exactly; a coloured one by its luminance.
  EXPECT_NEAR(0.16 * std::pow(transformed.reflectance(), 2), std::pow(0.45 / 2.45, 2) * 1.5, 1e-12);
  EXPECT_NEAR(0.16 * std::pow(find(*set, 2)->reflectance(), 2),
              0.04 * (0.2126 * 1 + 0.7152 * 0.5 + 0.0722 * 0.25) * 0.5, 1e-12);
  EXPECT_NEAR(find(*set, 0)->reflectance(), 0.5, 1e-12);  // neither extension: ior 1.5, f0 = 0.04
  EXPECT_TRUE(hasNote(set->notes,
                      "/materials/2/extensions/KHR_materials_specular/specularColorFactor: drawn by its luminance "
                      "(Facet's f0 is one number)"));
  EXPECT_TRUE(hasNote(
      set->notes, "/materials/2/extensions/KHR_materials_specular/specularFactor: scales f0 only (Facet's f90 is 1)"));
  EXPECT_TRUE(hasNote(set->notes,
                      "/materials/2/extensions/KHR_materials_specular/specularTexture: not sampled; drawn with the "
                      "factors"));
  EXPECT_FALSE(hasNote(set->notes,
                       "/materials/4/extensions/KHR_materials_specular/specularColorFactor: drawn by its luminance "
                       "(Facet's f0 is one number)"));
  // Embedded images keep their bytes; a file beside the glTF is named by its URI.
  ASSERT_EQ(set->images.size(), 5u);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(set->images[i].bytes.size() > 8 ? set->images[i].bytes[1] : 0, 'P') << i;
  EXPECT_EQ(set->images[4].uri, "features_base.png");
  EXPECT_TRUE(hasNote(set->notes, "/extensionsUsed: optional extension 'EXT_facet_unknown' is not read; skipped"));
  EXPECT_TRUE(hasNote(set->notes,
                      "/materials/0/extensions/EXT_facet_unknown: extension not read; the material is "
                      "drawn without it"));
  // glTF samplers are read, not reported: the cutout's clamps, the others' repeat trilinearly.
  const facet::runtime::TextureSampler clamp = find(*set, 2)->textures[size_t(GltfSlot::BaseColor)].sampler;
  EXPECT_EQ(clamp.wrapS, facet::runtime::TextureWrap::ClampToEdge);
  EXPECT_EQ(clamp.wrapT, facet::runtime::TextureWrap::ClampToEdge);
  EXPECT_TRUE(clamp.magLinear && clamp.minLinear && clamp.mipmaps && clamp.mipLinear);
  EXPECT_EQ(everything.textures[size_t(GltfSlot::BaseColor)].sampler, facet::runtime::TextureSampler{});
  for (const std::string& note : set->notes) EXPECT_EQ(note.find("/samplers/"), std::string::npos) << note;
}

TEST(GltfMaterials, EveryFeatureSetCompilesForEveryTier) {
  std::string error;
  auto set = facet::runtime::readGltfMaterials(featuresFile(), &error);
  ASSERT_TRUE(set) << error;
  std::set<std::string> built;
  for (const GltfMaterial& m : set->materials) {
    if (!built.insert(m.features.name()).second) continue;
    const std::string source = facet::runtime::gltfMaterialSource(m.features);
    EXPECT_TRUE(facet::test::buildText(source, m.features.name() + ".mat")) << source;
  }
  EXPECT_EQ(built.size(), 5u);
}

// What a file must not get through: an unknown required extension, a material the spec's ranges
// exclude, a texture that does not exist. Each error names the file and the JSON pointer.
TEST(GltfMaterials, BadMaterialsAreErrorsNamingThePlace) {
  const std::string dir = facet::test::scratchDir("gltf-materials-bad");
  const std::string text = facet::test::readText(featuresFile());
  const auto expectError = [&](const std::string& from, const std::string& to, const std::string& why) {
    std::string edited = text;
    const size_t at = edited.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    edited.replace(at, from.size(), to);
    std::ofstream(dir + "/bad.gltf") << edited;
    std::string error;
    EXPECT_FALSE(facet::runtime::readGltfMaterials(dir + "/bad.gltf", &error));
    EXPECT_EQ(error, dir + "/bad.gltf: error: " + why);
  };
  expectError(R"("extensionsUsed": [)", R"("extensionsRequired": ["KHR_draco_mesh_compression"], "extensionsUsed": [)",
              "/extensionsRequired/0: the file requires extension 'KHR_draco_mesh_compression', which this loader does "
              "not implement (it implements KHR_mesh_quantization and KHR_texture_transform; the glTF spec says such "
              "a file must not be loaded)");
  expectError(R"("metallicFactor": 0.7)", R"("metallicFactor": 1.5)",
              "/materials/0/pbrMetallicRoughness/metallicFactor: 1.5 is outside [0, 1]");
  expectError(R"("normalTexture": {"index": 2, "scale": 0.5})", R"("normalTexture": {"index": 9})",
              "/materials/0/normalTexture/index: texture 9 does not exist");
  expectError(R"("occlusionTexture": {"index": 1, "texCoord": 1, "strength": 0.8})",
              R"("occlusionTexture": {"index": 1, "texCoord": 2})",
              "/materials/0/occlusionTexture/texCoord: 2 (Facet reads TEXCOORD_0 and TEXCOORD_1)");
  expectError(R"("alphaMode": "BLEND")", R"("alphaMode": "ADD")",
              "/materials/3/alphaMode: 'ADD' is not OPAQUE, MASK or BLEND");
  expectError(R"("wrapS": 33071)", R"("wrapS": 12345)",
              "/samplers/1/wrapS: 12345 is not REPEAT (10497), CLAMP_TO_EDGE (33071) or MIRRORED_REPEAT (33648)");
  expectError(R"("minFilter": 9987, "wrapS": 33071)", R"("minFilter": 9000, "wrapS": 33071)",
              "/samplers/1/minFilter: 9000 is not a glTF minification filter (9728, 9729, 9984 to 9987)");
  expectError(R"("specularFactor": 0.5)", R"("specularFactor": 1.5)",
              "/materials/2/extensions/KHR_materials_specular/specularFactor: 1.5 is outside [0, 1]");
  expectError(R"("specularColorFactor": [1.5, 1.5, 1.5])", R"("specularColorFactor": [1.5, -1, 1.5])",
              "/materials/4/extensions/KHR_materials_specular/specularColorFactor/1: -1.0 is outside [0, 10000]");
  expectError(R"("specularColorFactor": [1.5, 1.5, 1.5])", R"("specularColorFactor": [1.5, 1.5])",
              "/materials/4/extensions/KHR_materials_specular/specularColorFactor: expected 3 numbers");
}

// features.gltf with its glass (material 3) given material extensions: `extensions` is the JSON
// that follows the glass's `pbrMetallicRoughness` object, written to `dir`/glass.gltf beside a copy
// of the file's base image. Returns the path.
std::string glassWithExtensions(const std::string& dir, const std::string& extensions) {
  const std::string glass = R"("metallicFactor": 0, "roughnessFactor": 0.1}})";
  std::string text = facet::test::readText(featuresFile());
  const size_t at = text.find(glass);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, glass.size(), R"("metallicFactor": 0, "roughnessFactor": 0.1}, "extensions": )" + extensions + "}");
  std::ofstream(dir + "/glass.gltf") << text;
  fs::copy_file(facet::test::sourceDir() + "/tests/data/gltf/features_base.png", dir + "/features_base.png",
                fs::copy_options::overwrite_existing);
  return dir + "/glass.gltf";
}

// The glass with `extensions` edited (`from` replaced by `to`) is refused with `why`, naming the file.
void expectGlassError(const std::string& dir, std::string extensions, const std::string& from, const std::string& to,
                      const std::string& why) {
  const size_t at = extensions.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  extensions.replace(at, from.size(), to);
  const std::string path = glassWithExtensions(dir, extensions);
  std::string message;
  EXPECT_FALSE(facet::runtime::readGltfMaterials(path, &message));
  EXPECT_EQ(message, path + ": error: " + why);
}

// KHR_materials_sheen (docs/gltf.md): the glass of features.gltf given a sheen, with factors and
// both textures (the roughness's on TEXCOORD_1, transformed), becomes a feature set with a sheen
// layer whose .mat compiles for every tier, samples the colour's RGB and the roughness's alpha, and
// whose scene object carries the factors; the sheen without textures is its own feature set; bad
// factors and textures are errors naming their JSON pointer.
TEST(GltfMaterials, SheenExtensionBecomesTheSheenLayer) {
  const std::string dir = facet::test::scratchDir("gltf-materials-sheen");
  fs::remove_all(dir + "/out");
  fs::create_directories(dir + "/out");
  const std::string sheen =
      R"({"KHR_materials_sheen": {)"
      R"("sheenColorFactor": [0.9, 0.8, 0.7], "sheenRoughnessFactor": 0.4, "sheenColorTexture": {"index": 0}, )"
      R"("sheenRoughnessTexture": {"index": 1, "texCoord": 1, "extensions": {"KHR_texture_transform": )"
      R"({"scale": [2, 2]}}}}})";
  std::string error;
  auto set = facet::runtime::readGltfMaterials(glassWithExtensions(dir, sheen), &error);
  ASSERT_TRUE(set) << error;
  const GltfMaterial& m = *find(*set, 3);
  EXPECT_EQ(m.features.name(), "gltf_sc0_sr1t_vc_blend_sh");
  EXPECT_EQ(m.sheenColorFactor, (std::array<double, 3>{0.9, 0.8, 0.7}));
  EXPECT_DOUBLE_EQ(m.sheenRoughnessFactor, 0.4);
  EXPECT_EQ(m.textures[size_t(GltfSlot::SheenRoughness)].scale, (std::array<double, 2>{2, 2}));
  for (const std::string& note : set->notes) EXPECT_EQ(note.find("KHR_materials_sheen"), std::string::npos) << note;
  const std::string source = facet::runtime::gltfMaterialSource(m.features);
  EXPECT_NE(source.find("sheenColor = params.sheenColorFactor * sample(params.sheenColorTexture, vertex.uv0).rgb"),
            std::string::npos)
      << source;
  EXPECT_NE(source.find("sheenRoughness = params.sheenRoughnessFactor * sample(params.sheenRoughnessTexture, "
                        "sheenRoughnessTextureUv).a"),
            std::string::npos)
      << source;
  ASSERT_TRUE(facet::test::buildText(source, m.features.name() + ".mat")) << source;
  // The scene object carries the factors and the textures.
  facet::runtime::GltfImport imported;
  ASSERT_TRUE(facet::runtime::importGltf(dir + "/glass.gltf", dir + "/out", dir, &imported, &error)) << error;
  const std::string json = facet::test::readText(imported.scene);
  for (const char* key :
       {"\"sheenColorFactor\"", "\"sheenRoughnessFactor\"", "\"sheenColorTexture\"", "\"sheenRoughnessTextureScale\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  // Factors alone: the layer without textures.
  auto plain = facet::runtime::readGltfMaterials(glassWithExtensions(dir, R"({"KHR_materials_sheen": {}})"), &error);
  ASSERT_TRUE(plain) << error;
  EXPECT_EQ(find(*plain, 3)->features.name(), "gltf_vc_blend_sh");
  EXPECT_EQ(find(*plain, 3)->sheenColorFactor, (std::array<double, 3>{0, 0, 0}));
  EXPECT_TRUE(facet::test::buildText(facet::runtime::gltfMaterialSource(find(*plain, 3)->features), "plain.mat"));
  const auto expectError = [&](const std::string& from, const std::string& to, const std::string& why) {
    expectGlassError(dir, sheen, from, to, why);
  };
  expectError("[0.9, 0.8, 0.7]", "[0.9, 1.8, 0.7]",
              "/materials/3/extensions/KHR_materials_sheen/sheenColorFactor/1: 1.8 is outside [0, 1]");
  expectError("[0.9, 0.8, 0.7]", "[0.9, 0.8]",
              "/materials/3/extensions/KHR_materials_sheen/sheenColorFactor: expected 3 numbers");
  expectError("\"sheenRoughnessFactor\": 0.4", "\"sheenRoughnessFactor\": -0.4",
              "/materials/3/extensions/KHR_materials_sheen/sheenRoughnessFactor: -0.4 is outside [0, 1]");
  expectError("\"sheenRoughnessFactor\": 0.4", "\"sheenRoughnessFactor\": \"rough\"",
              "/materials/3/extensions/KHR_materials_sheen/sheenRoughnessFactor: not a number");
  expectError("\"sheenColorTexture\": {\"index\": 0}", "\"sheenColorTexture\": {\"index\": 9}",
              "/materials/3/extensions/KHR_materials_sheen/sheenColorTexture/index: texture 9 does not exist");
  expectError("\"sheenColorTexture\": {\"index\": 0}", "\"sheenColorTexture\": {\"texCoord\": 0}",
              "/materials/3/extensions/KHR_materials_sheen/sheenColorTexture/index: expected a texture index");
  expectError("\"texCoord\": 1", "\"texCoord\": 3",
              "/materials/3/extensions/KHR_materials_sheen/sheenRoughnessTexture/texCoord: 3 (Facet reads TEXCOORD_0 "
              "and TEXCOORD_1)");
}

// KHR_materials_clearcoat (docs/gltf.md) onto Facet's clear coat, whose layering is the
// extension's (the base × (1 − Fc(n·v)), IOR 1.5): the glass of features.gltf with a coat, its
// factors, the strength's and roughness's textures and a scaled coat normal map becomes a feature
// set whose .mat compiles for every tier and samples R, G and the normal; bad factors are errors
// naming their JSON pointer.
TEST(GltfMaterials, ClearCoatExtensionBecomesTheClearCoat) {
  const std::string dir = facet::test::scratchDir("gltf-materials-clearcoat");
  const std::string coat =
      R"({"KHR_materials_clearcoat": {)"
      R"("clearcoatFactor": 0.8, "clearcoatRoughnessFactor": 0.2, "clearcoatTexture": {"index": 1}, )"
      R"("clearcoatRoughnessTexture": {"index": 1}, "clearcoatNormalTexture": {"index": 2, "scale": 0.5}}})";
  std::string error;
  auto set = facet::runtime::readGltfMaterials(glassWithExtensions(dir, coat), &error);
  ASSERT_TRUE(set) << error;
  const GltfMaterial& m = *find(*set, 3);
  EXPECT_EQ(m.features.name(), "gltf_cc0_ccr0_ccn0_vc_blend_cc");
  EXPECT_DOUBLE_EQ(m.clearcoatFactor, 0.8);
  EXPECT_DOUBLE_EQ(m.clearcoatRoughnessFactor, 0.2);
  EXPECT_DOUBLE_EQ(m.clearcoatNormalScale, 0.5);
  for (const std::string& note : set->notes) EXPECT_EQ(note.find("clearcoat"), std::string::npos) << note;
  const std::string source = facet::runtime::gltfMaterialSource(m.features);
  for (const char* line : {"clearCoat = params.clearcoatFactor * sample(params.clearcoatTexture, vertex.uv0).r",
                           "clearCoatRoughness = params.clearcoatRoughnessFactor * "
                           "sample(params.clearcoatRoughnessTexture, vertex.uv0).g",
                           "clearCoatNormal = vec3(coatMapped.xy * params.clearcoatNormalScale, coatMapped.z)"})
    EXPECT_NE(source.find(line), std::string::npos) << line << "\n" << source;
  EXPECT_TRUE(facet::test::buildText(source, m.features.name() + ".mat")) << source;
  // Factors alone: the coat without textures.
  auto plain = facet::runtime::readGltfMaterials(
      glassWithExtensions(dir, R"({"KHR_materials_clearcoat": {"clearcoatFactor": 1}})"), &error);
  ASSERT_TRUE(plain) << error;
  EXPECT_EQ(find(*plain, 3)->features.name(), "gltf_vc_blend_cc");
  EXPECT_TRUE(facet::test::buildText(facet::runtime::gltfMaterialSource(find(*plain, 3)->features), "plain.mat"));
  const auto expectError = [&](const std::string& from, const std::string& to, const std::string& why) {
    expectGlassError(dir, coat, from, to, why);
  };
  expectError("\"clearcoatFactor\": 0.8", "\"clearcoatFactor\": 1.8",
              "/materials/3/extensions/KHR_materials_clearcoat/clearcoatFactor: 1.8 is outside [0, 1]");
  expectError("\"clearcoatRoughnessFactor\": 0.2", "\"clearcoatRoughnessFactor\": \"smooth\"",
              "/materials/3/extensions/KHR_materials_clearcoat/clearcoatRoughnessFactor: not a number");
  expectError("\"scale\": 0.5", "\"scale\": 500",
              "/materials/3/extensions/KHR_materials_clearcoat/clearcoatNormalTexture/scale: 5e+02 is outside [-1e+02, "
              "1e+02]");
  expectError("\"clearcoatTexture\": {\"index\": 1}", "\"clearcoatTexture\": {\"index\": 7}",
              "/materials/3/extensions/KHR_materials_clearcoat/clearcoatTexture/index: texture 7 does not exist");
}

// KHR_materials_anisotropy onto Facet's anisotropy (docs/gltf.md, "Anisotropy"), as the surface
// program `matc import` writes computes it: the glTF roughness r and strength s give the extension's
// α_t = mix(α, 1, s²) along its direction and α_b = α across (α = r²), each floored at Facet's
// α_min = 0.089²; Facet's lobe takes α′ = (α_t + α_b)/2 as its α (roughness √α′) and k = (α_t − α_b) /
// (α_t + α_b) as its anisotropy.
struct MappedAnisotropy {
  double roughness, anisotropy;
};
constexpr double kAlphaMin = 0.089 * 0.089;
glm::dvec2 gltfAnisotropicAlpha(double roughness, double strength) {
  const double alpha = roughness * roughness;
  return {std::max(alpha + (1 - alpha) * strength * strength, kAlphaMin), std::max(alpha, kAlphaMin)};
}
MappedAnisotropy mapGltfAnisotropy(double roughness, double strength) {
  const glm::dvec2 a = gltfAnisotropicAlpha(roughness, strength);
  return {std::sqrt(0.5 * (a.x + a.y)), (a.x - a.y) / (a.x + a.y)};
}

// The mapping draws the extension's lobe: for a grid of roughness and strength, Facet's D · V with
// (α′, k) (the chunk's clamps: eval's standard model) equals the extension's D · V with (α_t, α_b)
// to 1e-6 over views and lights across the hemisphere and round the tangent.
TEST(GltfMaterials, AnisotropyMappingReproducesTheExtensionsLobe) {
  double worst = 0;
  for (double r : {0.0, 0.03, 0.06, 0.089, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}) {
    for (int si = 0; si <= 20; ++si) {
      const double s = si / 20.0;
      const MappedAnisotropy mapped = mapGltfAnisotropy(r, s);
      const double facetRoughness = std::clamp(mapped.roughness, 0.089, 1.0);
      const glm::dvec2 facet = facet::reference::anisotropicAlpha(facetRoughness * facetRoughness, mapped.anisotropy);
      const glm::dvec2 gltf = gltfAnisotropicAlpha(r, s);
      for (double thetaV : {0.05, 0.6, 1.2, 1.5})
        for (double phiV : {0.0, 0.7, 1.6, 2.9})
          for (double thetaL : {0.0, 0.3, 0.9, 1.4})
            for (double phiL : {0.0, 1.1, 2.2, 4.0}) {
              const glm::dvec3 v(std::sin(thetaV) * std::cos(phiV), std::sin(thetaV) * std::sin(phiV),
                                 std::cos(thetaV));
              const glm::dvec3 l(std::sin(thetaL) * std::cos(phiL), std::sin(thetaL) * std::sin(phiL),
                                 std::cos(thetaL));
              const double expected = facet::reference::anisotropicLobe(gltf, v, l);
              const double got = facet::reference::anisotropicLobe(facet, v, l);
              worst = std::max(worst, std::abs(got - expected) / expected);
            }
    }
  }
  std::printf("KHR_materials_anisotropy mapped: worst relative difference of D V %.3g\n", worst);
  EXPECT_LE(worst, 1e-6);
}

// The extension's factors and texture reach the feature set, the .mat and the scene; bad values
// are errors naming their JSON pointer.
TEST(GltfMaterials, AnisotropyExtensionBecomesFacetsAnisotropy) {
  const std::string dir = facet::test::scratchDir("gltf-materials-anisotropy");
  fs::remove_all(dir + "/out");
  fs::create_directories(dir + "/out");
  const std::string anisotropy =
      R"({"KHR_materials_anisotropy": {"anisotropyStrength": 0.6, "anisotropyRotation": 0.5, )"
      R"("anisotropyTexture": {"index": 1, "texCoord": 1}}})";
  std::string error;
  auto set = facet::runtime::readGltfMaterials(glassWithExtensions(dir, anisotropy), &error);
  ASSERT_TRUE(set) << error;
  const GltfMaterial& m = *find(*set, 3);
  EXPECT_EQ(m.features.name(), "gltf_an1_vc_blend_an");
  EXPECT_DOUBLE_EQ(m.anisotropyStrength, 0.6);
  EXPECT_DOUBLE_EQ(m.anisotropyRotation, 0.5);
  EXPECT_EQ(m.textures[size_t(GltfSlot::Anisotropy)].texCoord, 1);
  for (const std::string& note : set->notes) EXPECT_EQ(note.find("anisotropy"), std::string::npos) << note;
  const std::string source = facet::runtime::gltfMaterialSource(m.features);
  for (const char* line : {"let anisotropyTexel = sample(params.anisotropyTexture, vertex.uv1)",
                           "let anisotropyStrength = params.anisotropyStrength * anisotropyTexel.b",
                           "roughness = sqrt(0.5 * (alphaAlong + alphaAcross))",
                           "anisotropy = (alphaAlong - alphaAcross) / (alphaAlong + alphaAcross)",
                           "let texelDirection = anisotropyTexel.rg * 2.0 - 1.0"})
    EXPECT_NE(source.find(line), std::string::npos) << line << "\n" << source;
  ASSERT_TRUE(facet::test::buildText(source, m.features.name() + ".mat")) << source;
  facet::runtime::GltfImport imported;
  ASSERT_TRUE(facet::runtime::importGltf(dir + "/glass.gltf", dir + "/out", dir, &imported, &error)) << error;
  const std::string json = facet::test::readText(imported.scene);
  for (const char* key : {"\"anisotropyStrength\": 0.6", "\"anisotropyRotation\"", "\"anisotropyTexture\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  // Without TANGENT or a normal texture (the extension requires one), the direction turns from +x: noted.
  EXPECT_FALSE(hasNote(set->notes,
                       "/meshes/0/primitives/3: KHR_materials_anisotropy without TANGENT or a normal "
                       "texture; its direction turns from +x"));
  {
    std::string text = facet::test::readText(dir + "/glass.gltf");
    const std::string tangent = R"("TANGENT": 2, "TEXCOORD_0": 3, "TEXCOORD_1": 4, "COLOR_0": 5)";
    const size_t at = text.find(tangent);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, tangent.size(), R"("TEXCOORD_0": 3, "TEXCOORD_1": 4, "COLOR_0": 5)");
    std::ofstream(dir + "/untangented.gltf") << text;
    auto untangented = facet::runtime::readGltfMaterials(dir + "/untangented.gltf", &error);
    ASSERT_TRUE(untangented) << error;
    EXPECT_TRUE(hasNote(untangented->notes,
                        "/meshes/0/primitives/3: KHR_materials_anisotropy without TANGENT or a "
                        "normal texture; its direction turns from +x"));
  }
  // Factors alone: the direction is the rotation's, no texture.
  auto plain = facet::runtime::readGltfMaterials(
      glassWithExtensions(dir, R"({"KHR_materials_anisotropy": {"anisotropyStrength": 1}})"), &error);
  ASSERT_TRUE(plain) << error;
  EXPECT_EQ(find(*plain, 3)->features.name(), "gltf_vc_blend_an");
  const std::string plainSource = facet::runtime::gltfMaterialSource(find(*plain, 3)->features);
  EXPECT_NE(plainSource.find("anisotropyDirection = vec3(params.anisotropyRotation, 0.0)"), std::string::npos)
      << plainSource;
  EXPECT_TRUE(facet::test::buildText(plainSource, "plain.mat"));
  const auto expectError = [&](const std::string& from, const std::string& to, const std::string& why) {
    expectGlassError(dir, anisotropy, from, to, why);
  };
  expectError("\"anisotropyStrength\": 0.6", "\"anisotropyStrength\": 1.5",
              "/materials/3/extensions/KHR_materials_anisotropy/anisotropyStrength: 1.5 is outside [0, 1]");
  expectError("\"anisotropyStrength\": 0.6", "\"anisotropyStrength\": -0.1",
              "/materials/3/extensions/KHR_materials_anisotropy/anisotropyStrength: -0.1 is outside [0, 1]");
  expectError("\"anisotropyRotation\": 0.5", "\"anisotropyRotation\": \"east\"",
              "/materials/3/extensions/KHR_materials_anisotropy/anisotropyRotation: not a number");
  // An angle beyond double's range is refused by the JSON reader, at its place in the file.
  std::string overflow = anisotropy;
  overflow.replace(overflow.find("0.5"), 3, "1e999");
  EXPECT_FALSE(facet::runtime::readGltfMaterials(glassWithExtensions(dir, overflow), &error));
  EXPECT_NE(error.find("glass.gltf:1:"), std::string::npos) << error;
  EXPECT_NE(error.find("number overflow parsing '1e999'"), std::string::npos) << error;
  expectError("\"index\": 1", "\"index\": 8",
              "/materials/3/extensions/KHR_materials_anisotropy/anisotropyTexture/index: texture 8 does not exist");
  expectError("\"texCoord\": 1", "\"texCoord\": 2",
              "/materials/3/extensions/KHR_materials_anisotropy/anisotropyTexture/texCoord: 2 (Facet reads "
              "TEXCOORD_0 and TEXCOORD_1)");
}

// `gltfMaterial` picks a glTF material's primitives: only on a glTF mesh, an integer, and one the
// file's scene draws.
TEST(GltfMaterials, SceneObjectsPickPrimitivesByMaterial) {
  const std::string dir = facet::test::scratchDir("gltf-material-pick");
  for (const char* name : {"features.gltf", "features_base.png"})
    fs::copy_file(facet::test::sourceDir() + "/tests/data/gltf/" + name, dir + "/" + name);
  const auto scene = [&](const std::string& mesh, const std::string& index) {
    return R"({"objects": [{"mesh": ")" + mesh + R"(", "gltfMaterial": )" + index + R"(, "material": "m"}]})";
  };
  std::string error;
  EXPECT_FALSE(facet::runtime::parseScene(dir + "/s.json", scene("sphere", "0"), &error));
  EXPECT_NE(error.find("/objects/0/gltfMaterial: only a glTF mesh has materials to choose from"), std::string::npos)
      << error;
  EXPECT_FALSE(facet::runtime::parseScene(dir + "/s.json", scene("features.gltf", "1.5"), &error));
  EXPECT_NE(error.find("/objects/0/gltfMaterial: expected a material index (an integer, or -1)"), std::string::npos)
      << error;
  EXPECT_FALSE(facet::runtime::parseScene(dir + "/s.json", scene("features.gltf", "-2"), &error));
  const std::string packages = facet::test::writePackagesFromTexts(
      "gltf-material-pick-packages", {"material m { shading unlit\n surface { baseColor = vec3(1.0) } }"});
  auto parsed = facet::runtime::parseScene(dir + "/s.json", scene("features.gltf", "7"), &error);
  ASSERT_TRUE(parsed) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*parsed, packages, &error));
  EXPECT_EQ(error, "object 0: " + dir +
                       "/features.gltf: error: no primitive of the file's scene uses /materials/7 "
                       "(the object's gltfMaterial)");
  // Each material's primitives are a Mesh of their own: the quad of material 2 (2 triangles).
  auto meshes = facet::runtime::loadGltfMeshesByMaterial(dir + "/features.gltf", &error);
  ASSERT_TRUE(meshes) << error;
  EXPECT_EQ(meshes->size(), 6u);
  EXPECT_EQ(meshes->at(2).indices.size(), 6u);
  EXPECT_EQ(meshes->at(-1).indices.size(), 6u);
}

// A normal-mapped primitive without TANGENT gets MikkTSpace's, from the normal texture's UV set,
// after its node's transform: the quads turned 90° about z have u along +y, and v down the
// image along +x, so the tangent is +y and the bitangent w · (n × t) = −x points up the image
// (green's direction in glTF's normal maps). A primitive that is not normal-mapped keeps the
// default tangent.
TEST(GltfMaterials, MissingTangentsOfNormalMappedPrimitivesAreMikkTSpaces) {
  const std::string dir = facet::test::scratchDir("gltf-mikktspace");
  std::string text = facet::test::readText(featuresFile());
  for (size_t at; (at = text.find(R"("TANGENT": 2, )")) != std::string::npos;) text.erase(at, 14);
  const std::string node = R"("nodes": [{"mesh": 0}])";
  ASSERT_NE(text.find(node), std::string::npos);
  text.replace(text.find(node), node.size(), R"("nodes": [{"mesh": 0, "rotation": [0, 0, 0.70710678, 0.70710678]}])");
  std::ofstream(dir + "/f.gltf") << text;
  fs::copy_file(facet::test::sourceDir() + "/tests/data/gltf/features_base.png", dir + "/features_base.png");
  std::string error;
  auto meshes = facet::runtime::loadGltfMeshesByMaterial(dir + "/f.gltf", &error);
  ASSERT_TRUE(meshes) << error;
  const auto tangentsOf = [&](int material) {
    // The tangents of the vertices the material's triangles use (every primitive of the file
    // shares one accessor, so each brings all 24 vertices and indexes 4).
    std::vector<std::array<float, 4>> out;
    const facet::runtime::Mesh& m = meshes->at(material);
    for (uint32_t index : m.indices) {
      const float* t = &m.vertices[size_t(index) * facet::abi::kVertexFloats + 14];
      out.push_back({t[0], t[1], t[2], t[3]});
    }
    return out;
  };
  for (const auto& t : tangentsOf(0)) {
    EXPECT_NEAR(t[0], 0, 1e-5);
    EXPECT_NEAR(t[1], 1, 1e-5);
    EXPECT_NEAR(t[2], 0, 1e-5);
    EXPECT_EQ(t[3], 1);
  }
  for (const auto& t : tangentsOf(2)) EXPECT_EQ(t, (std::array<float, 4>{1, 0, 0, 1}));
}

// `matc import` writes a scene only over files the scene may read: the glTF file and its image
// files inside the asset root, image URIs read as RFC 3986 says (no %00 cutting a name short).
TEST(GltfMaterials, ImportRefusesFilesOutsideTheAssetRoot) {
  const std::string dir = facet::test::scratchDir("gltf-import-outside");
  fs::create_directories(dir + "/out");
  const std::string text = facet::test::readText(featuresFile());
  const auto importWith = [&](const std::string& uri, const std::string& outDir) {
    std::string edited = text;
    edited.replace(edited.find(R"("features_base.png")"), 19, "\"" + uri + "\"");
    std::ofstream(dir + "/out/f.gltf") << edited;
    facet::runtime::GltfImport imported;
    std::string error;
    EXPECT_FALSE(facet::runtime::importGltf(dir + "/out/f.gltf", outDir, "", &imported, &error));
    return error;
  };
  EXPECT_EQ(importWith("../secret.png", dir + "/out"),
            dir + "/out/f.gltf: error: /images/4/uri: the image is outside " + dir +
                "/out, the folder the scene may read files from (the output folder, or --asset-root)");
  EXPECT_EQ(importWith("a%00b.png", dir + "/out"),
            dir + "/out/f.gltf: error: /images/4/uri: 'a%00b.png' has a malformed %-escape or %00 at character 1");
  EXPECT_EQ(importWith("features_base.png", dir + "/out/scenes"),
            dir + "/out/f.gltf: error: the glTF file is outside " + dir +
                "/out/scenes, the folder the scene may read files from (the output folder, or --asset-root)");
  EXPECT_FALSE(fs::exists(dir + "/out/scenes/f.json"));
}

int maxDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  int worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  return worst;
}

// `matc import` writes a .mat per feature set, the embedded images and a scene that draws every
// primitive with its own material; the scene renders on both APIs, and they agree.
TEST(GltfMaterials, ImportedSceneRendersOnVulkanAndGles) {
  const std::string dir = facet::test::scratchDir("gltf-import");
  fs::remove_all(dir + "/out");
  fs::create_directories(dir + "/out/asset");
  for (const char* name : {"features.gltf", "features_base.png"})
    fs::copy_file(facet::test::sourceDir() + "/tests/data/gltf/" + name, dir + "/out/asset/" + name,
                  fs::copy_options::overwrite_existing);
  facet::runtime::GltfImport imported;
  std::string error;
  ASSERT_TRUE(facet::runtime::importGltf(dir + "/out/asset/features.gltf", dir + "/out", "", &imported, &error))
      << error;
  EXPECT_EQ(imported.materials.size(), 5u);
  EXPECT_EQ(imported.images.size(), 5u);  // four embedded, written out; one file beside the glTF
  EXPECT_TRUE(fs::exists(dir + "/out/features_images/0.png"));
  std::vector<std::string> texts;
  for (const std::string& path : imported.materials) texts.push_back(facet::test::readText(path));
  const std::string packages = facet::test::writePackagesFromTexts("gltf-import-packages", texts);
  auto scene = facet::runtime::loadScene(imported.scene, &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_EQ(scene->objects.size(), 6u);
  // The cutout's clamping sampler reaches its scene object; repeating trilinear ones are left out.
  for (const auto& object : scene->objects) {
    if (object.gltfMaterial == 2) {
      ASSERT_EQ(object.samplers.size(), 1u);
      EXPECT_EQ(object.samplers.at("baseColorTexture").wrapS, facet::runtime::TextureWrap::ClampToEdge);
    } else {
      EXPECT_TRUE(object.samplers.empty()) << object.material;
    }
  }
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
  ASSERT_TRUE(frame) << error;
  EXPECT_EQ(frame->frame().draws.size(), 6u);
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  facet::runtime::FrameResult a, b;
  ASSERT_TRUE(vk->render(frame->frame(), &a, &error)) << error;
  ASSERT_TRUE(gl->render(frame->frame(), &b, &error)) << error;
  ASSERT_EQ(a.ldr.size(), b.ldr.size());
  size_t beyond1 = 0;
  for (size_t i = 0; i < a.ldr.size(); ++i) beyond1 += std::abs(int(a.ldr[i]) - int(b.ldr[i])) > 1;
  std::printf("features.gltf Vulkan vs GLES: max %d steps, %zu of %zu values beyond 1 step\n",
              maxDifference(a.ldr, b.ldr), beyond1, a.ldr.size());
  EXPECT_LE(maxDifference(a.ldr, b.ldr), 2);
  EXPECT_LE(double(beyond1), 0.001 * double(a.ldr.size()));
  EXPECT_TRUE(vk->validationErrors().empty());
  EXPECT_TRUE(gl->validationErrors().empty());

  // Each tier against `reference` (Vulkan; docs/gltf.md quotes these lines).
  facet::runtime::FrameResult reference;
  for (const char* tier : {"reference", "high", "mid", "low"}) {
    scene->tier = tier;
    auto tierFrame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
    ASSERT_TRUE(tierFrame) << error;
    facet::runtime::FrameResult result;
    ASSERT_TRUE(vk->render(tierFrame->frame(), &result, &error)) << error;
    if (std::string(tier) == "reference") {
      reference = std::move(result);
      continue;
    }
    const double db = facet::test::psnr(reference.ldr, result.ldr);
    std::printf("features.gltf %s vs reference: PSNR %.1f dB\n", tier, db);
    // Every tier lights these flat quads close to the reference (measured: docs/gltf.md).
    EXPECT_GE(db, 30.0) << tier;
  }
}

// Renders `frame` on `backend`; an empty result on failure (the test has failed already).
std::vector<uint8_t> renderLdr(facet::runtime::RenderBackend& backend, const facet::runtime::SceneFrame& frame) {
  facet::runtime::FrameResult r;
  std::string error;
  EXPECT_TRUE(backend.render(frame.frame(), &r, &error)) << error;
  EXPECT_TRUE(backend.validationErrors().empty()) << backend.name();
  return r.ldr;
}

// tests/data/gltf/anisotropy.gltf (make_anisotropy.py: two spheres, the extension with factors
// only and with a texture, both rotated) imported and drawn: Vulkan and GLES agree within the glTF
// tolerances, and each tier that shades the lobe draws what a hand-written Facet material with the
// mapped constants (roughness √α′, anisotropy k, the turned direction) draws, within 1 step. The
// same spheres drawn isotropic differ by far more: the comparison sees the lobe.
TEST(GltfMaterials, AnisotropyExtensionDrawsTheExtensionsLobe) {
  const std::string dir = facet::test::scratchDir("gltf-anisotropy-render");
  fs::remove_all(dir);
  fs::create_directories(dir + "/asset");
  fs::copy_file(facet::test::sourceDir() + "/tests/data/gltf/anisotropy.gltf", dir + "/asset/anisotropy.gltf");
  facet::runtime::GltfImport imported;
  std::string error;
  ASSERT_TRUE(facet::runtime::importGltf(dir + "/asset/anisotropy.gltf", dir, "", &imported, &error)) << error;
  ASSERT_EQ(imported.materials.size(), 2u);
  EXPECT_EQ(fs::path(imported.materials[0]).stem().string(), "gltf_an");
  EXPECT_EQ(fs::path(imported.materials[1]).stem().string(), "gltf_an0_an");
  std::vector<std::string> texts;
  for (const std::string& path : imported.materials) texts.push_back(facet::test::readText(path));
  texts.push_back(
      "material mapped_anisotropy {\n    shading lit\n"
      "    param color: vec3 = vec3(1.0, 1.0, 1.0) in [0, 1]\n"
      "    param rough: float = 1.0 in [0, 1]\n"
      "    param aniso: float = 0.0 in [-1, 1]\n"
      "    param direction: vec3 = vec3(1.0, 0.0, 0.0) in [-1, 1]\n"
      "    surface {\n"
      "        baseColor = params.color\n        metallic = 1.0\n        roughness = params.rough\n"
      "        anisotropy = params.aniso\n        anisotropyDirection = params.direction\n"
      "    }\n}\n");
  const std::string packages = facet::test::writePackagesFromTexts("gltf-anisotropy-render-packages", texts);
  auto scene = facet::runtime::loadScene(imported.scene, &error);
  ASSERT_TRUE(scene) << error;
  ASSERT_EQ(scene->objects.size(), 2u);
  // The hand-written twin: the mapped constants of each sphere (the textured one's texel is
  // (238, 191, 204) / 255, make_anisotropy.py).
  struct Sphere {
    std::vector<double> color;
    double roughness, strength, rotation;
    glm::dvec2 texelDirection;
  };
  const Sphere spheres[2] = {
      {{0.95, 0.93, 0.88}, 0.3, 0.6, 0.5, {1, 0}},
      {{0.9, 0.7, 0.5}, 0.25, 0.9 * 204 / 255.0, -0.3, {2 * 238 / 255.0 - 1, 2 * 191 / 255.0 - 1}}};
  const auto twin = [&](bool isotropic) {
    facet::runtime::Scene s = *scene;
    for (auto& object : s.objects) {
      const Sphere& sphere = spheres[size_t(*object.gltfMaterial)];
      const MappedAnisotropy mapped = mapGltfAnisotropy(sphere.roughness, sphere.strength);
      const double c = std::cos(sphere.rotation), sn = std::sin(sphere.rotation);
      const glm::dvec2 d = sphere.texelDirection;
      object.material = "mapped_anisotropy";
      object.textures.clear();
      object.params = {{"color", sphere.color},
                       {"rough", {isotropic ? sphere.roughness : mapped.roughness}},
                       {"aniso", {isotropic ? 0.0 : mapped.anisotropy}},
                       {"direction", {c * d.x - sn * d.y, sn * d.x + c * d.y, 0.0}}};
    }
    return s;
  };
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  for (const char* tier : {"reference", "high"}) {
    scene->tier = tier;
    auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
    ASSERT_TRUE(frame) << error;
    const std::vector<uint8_t> a = renderLdr(*vk, *frame), b = renderLdr(*gl, *frame);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    size_t beyond1 = 0;
    for (size_t i = 0; i < a.size(); ++i) beyond1 += std::abs(int(a[i]) - int(b[i])) > 1;
    std::printf("anisotropy.gltf %s: Vulkan vs GLES max %d steps, %zu of %zu values beyond 1 step\n", tier,
                maxDifference(a, b), beyond1, a.size());
    EXPECT_LE(maxDifference(a, b), 2) << tier;
    EXPECT_LE(double(beyond1), 0.001 * double(a.size())) << tier;
    facet::runtime::Scene mappedScene = twin(false), isotropicScene = twin(true);
    mappedScene.tier = isotropicScene.tier = tier;
    auto mappedFrame = facet::runtime::SceneFrame::prepare(mappedScene, packages, &error);
    auto isotropicFrame = facet::runtime::SceneFrame::prepare(isotropicScene, packages, &error);
    ASSERT_TRUE(mappedFrame && isotropicFrame) << error;
    const std::vector<uint8_t> mapped = renderLdr(*vk, *mappedFrame), isotropic = renderLdr(*vk, *isotropicFrame);
    std::printf(
        "anisotropy.gltf %s (Vulkan): imported vs hand-written mapped material max %d steps; vs isotropic "
        "max %d steps\n",
        tier, maxDifference(a, mapped), maxDifference(a, isotropic));
    EXPECT_LE(maxDifference(a, mapped), 1) << tier;
    EXPECT_GE(maxDifference(a, isotropic), 20) << tier;
  }
}

// A scene object's `samplers` on both APIs, seen at the border: a plane looked at head-on samples
// its 2-texel image at uv · 3 − 1, so the middle third of the plane shows the two texels X, Y and
// the outer thirds what the wrap mode makes of [-1, 0] and [1, 2]. Read at the centre of each
// sixth along the axis: repeat X Y X Y X Y, clampToEdge X X X Y Y Y, mirroredRepeat Y X X Y Y X
// (whichever way the axis runs on screen). Nearest magnification leaves no blended pixel between
// X and Y; linear does.
TEST(GltfMaterials, SamplerWrapAndFilterModesShowAtTheBorder) {
  const std::string dir = facet::test::scratchDir("gltf-sampler-modes");
  std::string error;
  // Red | green along s (2 × 1) and red over green along t (1 × 2).
  const std::vector<uint8_t> texels = {255, 0, 0, 255, 0, 255, 0, 255};
  ASSERT_TRUE(facet::runtime::writePng(dir + "/s.png", 2, 1, texels, &error)) << error;
  ASSERT_TRUE(facet::runtime::writePng(dir + "/t.png", 1, 2, texels, &error)) << error;
  const std::string packages = facet::test::writePackagesFromTexts(
      "gltf-sampler-modes-packages", {"material wrap_probe {\n    shading unlit\n"
                                      "    param tex: texture(srgb) = vec4(1.0, 1.0, 1.0, 1.0)\n"
                                      "    surface {\n"
                                      "        baseColor = sample(params.tex, vertex.uv0 * 3.0 - vec2(1.0, 1.0)).rgb\n"
                                      "    }\n}\n"});
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  const struct {
    const char* axis;  // "s" or "t"
    const char* wrap;
    const char* mag;
    const char* expected;  // at the sixths, X the first texel seen in the middle third
  } cases[] = {
      {"s", "repeat", "nearest", "XYXYXY"},         {"s", "clampToEdge", "nearest", "XXXYYY"},
      {"s", "mirroredRepeat", "nearest", "YXXYYX"}, {"t", "repeat", "nearest", "XYXYXY"},
      {"t", "clampToEdge", "nearest", "XXXYYY"},    {"t", "mirroredRepeat", "nearest", "YXXYYX"},
      {"s", "repeat", "linear", "XYXYXY"},
  };
  for (const auto& c : cases) {
    const std::string what = std::string(c.axis) + " " + c.wrap + " " + c.mag;
    const std::string wrapKey = std::string("wrap") + (c.axis[0] == 's' ? "S" : "T");
    std::ofstream(dir + "/scene.json") << R"({"width": 120, "height": 120, "tier": "high",
              "camera": {"position": [0, 2.5, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fovY": 40, "near": 1, "far": 10},
              "sky": {"luminance": 1000},
              "objects": [{"mesh": "plane", "material": "wrap_probe", "params": {"tex": ")"
                                       << c.axis << R"(.png"}, "samplers": {"tex": {")" << wrapKey << R"(": ")"
                                       << c.wrap << R"(", "magFilter": ")" << c.mag
                                       << R"(", "minFilter": "nearest"}}}]})";
    auto scene = facet::runtime::loadScene(dir + "/scene.json", &error);
    ASSERT_TRUE(scene) << error;
    auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
    ASSERT_TRUE(frame) << error;
    for (facet::runtime::RenderBackend* backend : {vk.get(), gl.get()}) {
      facet::runtime::FrameResult r;
      ASSERT_TRUE(backend->render(frame->frame(), &r, &error)) << error;
      // 'R', 'G', 'b' (a blend of both), or ' ' (the grey sky; the texels have no blue).
      const auto kind = [&](uint32_t x, uint32_t y) {
        const uint8_t* p = &r.ldr[4 * (size_t(y) * r.width + x)];
        if (std::abs(int(p[0]) - int(p[2])) < 12 && std::abs(int(p[1]) - int(p[2])) < 12) return ' ';
        if (p[0] > p[1] + 60) return 'R';
        if (p[1] > p[0] + 60) return 'G';
        return 'b';
      };
      const bool alongX = c.axis[0] == 's';  // the plane's u runs along screen x, its v along y
      const auto at = [&](uint32_t i) { return alongX ? kind(i, r.height / 2 + 3) : kind(r.width / 2 + 3, i); };
      const uint32_t n = alongX ? r.width : r.height;
      uint32_t first = n, last = 0, blended = 0;
      for (uint32_t i = 0; i < n; ++i) {
        if (at(i) == ' ') continue;
        first = std::min(first, i);
        last = i;
        blended += at(i) == 'b';
      }
      ASSERT_LT(first + 24, last) << what << ": the plane is not in view";
      std::string seen;
      for (int k = 0; k < 6; ++k) seen += at(first + uint32_t((k + 0.5) * (last + 1 - first) / 6));
      // Named by the middle third: X is whichever texel its first sixth shows.
      std::string named;
      for (char t : seen) named += t == seen[2] ? 'X' : (t == 'R' || t == 'G') ? 'Y' : '?';
      EXPECT_NE(seen[2], seen[3]) << what;
      EXPECT_EQ(named, c.expected) << what << " on " << backend->name() << ": " << seen;
      if (std::string(c.mag) == "nearest") {
        EXPECT_EQ(blended, 0u) << what << " on " << backend->name();
      } else {
        EXPECT_GT(blended, 4u) << what << " on " << backend->name();
      }
      EXPECT_TRUE(backend->validationErrors().empty()) << what;
    }
  }
  // A wrong sampler is an error at its pointer.
  std::ofstream(dir + "/bad.json") << R"({"objects": [{"mesh": "plane", "material": "wrap_probe",
                                         "samplers": {"tex": {"wrapS": "clamp"}}}]})";
  EXPECT_FALSE(facet::runtime::loadScene(dir + "/bad.json", &error));
  EXPECT_NE(error.find("/objects/0/samplers/tex/wrapS: 'clamp' is not one of repeat, clampToEdge, mirroredRepeat"),
            std::string::npos)
      << error;
  std::ofstream(dir + "/bad.json") << R"({"objects": [{"mesh": "plane", "material": "wrap_probe",
                                         "samplers": {"albedo": {"wrapS": "repeat"}}}]})";
  auto scene = facet::runtime::loadScene(dir + "/bad.json", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*scene, packages, &error));
  EXPECT_NE(error.find("/objects/0/samplers/albedo: material 'wrap_probe' has no texture parameter 'albedo'"),
            std::string::npos)
      << error;
}

// KHR_texture_transform's rotation turns the UVs counter-clockwise in glTF's UV space (v down),
// so drawn upright the image turns clockwise: a quad showing a 2 × 2 image (red, green over blue,
// white) with rotation π/2 and offset (0, 1), uv' = (v, 1 − u), shows blue, red over white, green.
// The extension's GLSL listing (its transpose) would show green, white over red, blue (the repeat
// wrap brings its uv' = (−v, u + 1) back into the image). Every quadrant's centre maps to a texel's.
TEST(GltfMaterials, TextureTransformRotationTurnsTheImageClockwise) {
  const std::string dir = facet::test::scratchDir("gltf-texture-rotation");
  fs::remove_all(dir);
  fs::create_directories(dir + "/asset");
  std::string error;
  const std::vector<uint8_t> texels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  ASSERT_TRUE(facet::runtime::writePng(dir + "/asset/quad.png", 2, 2, texels, &error)) << error;
  // A quad facing +z, its image upright seen from +z: uv (0, 0) at the top left.
  const float positions[4][3] = {{-1, 1, 0}, {1, 1, 0}, {-1, -1, 0}, {1, -1, 0}};
  const float uvs[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  const uint16_t indices[6] = {0, 2, 1, 1, 2, 3};
  {
    std::ofstream bin(dir + "/asset/quad.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.write(reinterpret_cast<const char*>(uvs), sizeof uvs);
    bin.write(reinterpret_cast<const char*>(indices), sizeof indices);
  }
  std::ofstream(dir + "/asset/quad.gltf") << R"({"asset": {"version": "2.0"},
    "extensionsUsed": ["KHR_texture_transform"],
    "buffers": [{"uri": "quad.bin", "byteLength": 92}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                    {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    "images": [{"uri": "quad.png"}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}],
    "materials": [{"pbrMetallicRoughness": {"metallicFactor": 0, "baseColorTexture": {"index": 0,
      "extensions": {"KHR_texture_transform": {"rotation": 1.5707963267948966, "offset": [0, 1]}}}}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
  facet::runtime::GltfImport imported;
  ASSERT_TRUE(facet::runtime::importGltf(dir + "/asset/quad.gltf", dir, "", &imported, &error)) << error;
  ASSERT_EQ(imported.materials.size(), 1u);
  EXPECT_EQ(fs::path(imported.materials[0]).stem().string(), "gltf_bc0t");
  const std::string packages = facet::test::writePackagesFromTexts("gltf-texture-rotation-packages",
                                                                   {facet::test::readText(imported.materials[0])});
  auto scene = facet::runtime::loadScene(imported.scene, &error);
  ASSERT_TRUE(scene) << error;
  scene->camera.position = {0, 0, 3};
  scene->camera.target = {0, 0, 0};
  scene->camera.up = {0, 1, 0};
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
  ASSERT_TRUE(frame) << error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  for (facet::runtime::RenderBackend* backend : {vk.get(), gl.get()}) {
    facet::runtime::FrameResult r;
    ASSERT_TRUE(backend->render(frame->frame(), &r, &error)) << error;
    // The quadrants' centres (±0.5, ±0.5, 0) seen from 3 m with a 40° vertical field of view.
    const double ndcY = 0.5 / (3 * std::tan(20 * M_PI / 180)), ndcX = ndcY * r.height / r.width;
    const auto kind = [&](double x, double y) {
      const auto px = uint32_t((x * ndcX + 1) / 2 * r.width), py = uint32_t((1 - y * ndcY) / 2 * r.height);
      const uint8_t* p = &r.ldr[4 * (size_t(py) * r.width + px)];
      const int red = p[0], green = p[1], blue = p[2];
      if (red > 80 && green > 80 && blue > 80 && std::abs(red - blue) < 40 && std::abs(green - blue) < 40) return 'W';
      if (red > green + 60 && red > blue + 60) return 'R';
      if (green > red + 60 && green > blue + 60) return 'G';
      if (blue > red + 60 && blue > green + 60) return 'B';
      return '?';
    };
    const std::string seen = {kind(-1, 1), kind(1, 1), kind(-1, -1), kind(1, -1)};
    EXPECT_EQ(seen, "BRWG") << backend->name() << " (the extension's GLSL listing would show GWRB)";
    EXPECT_TRUE(backend->validationErrors().empty());
  }
}

// `matc import`'s camera brackets the asset's bounding sphere with a near plane close to it (far /
// near about 8, not 400), so that a close-up resolves the depths of nearby surfaces (docs/gltf.md:
// with far / 400 a pixel where the avocado's pit meets its cut face took the pit on one API and
// the flesh on the other).
TEST(GltfMaterials, ImportedCameraFitsNearAndFarToTheAsset) {
  const std::string examples = facet::test::sourceDir() + "/examples";
  const std::string gltf = examples + "/assets/avocado/Avocado.gltf";
  const std::string dir = facet::test::scratchDir("gltf-import-camera");
  fs::remove_all(dir);
  facet::runtime::GltfImport imported;
  std::string error;
  ASSERT_TRUE(facet::runtime::importGltf(gltf, dir, examples, &imported, &error)) << error;
  auto set = facet::runtime::readGltfMaterials(gltf, &error, {.assetRoot = examples});
  ASSERT_TRUE(set) << error;
  auto scene = facet::runtime::loadScene(imported.scene, &error, {.assetRoot = examples});
  ASSERT_TRUE(scene) << error;
  glm::dvec3 lo(set->boundsMin[0], set->boundsMin[1], set->boundsMin[2]);
  glm::dvec3 hi(set->boundsMax[0], set->boundsMax[1], set->boundsMax[2]);
  const double radius = glm::length(hi - lo) / 2;
  const double distance = glm::length(scene->camera.position - (lo + hi) / 2.0);
  const facet::runtime::Camera& camera = scene->camera;
  std::printf("Avocado: bounding sphere at %.4f..%.4f, near %.4f, far %.4f (far / near %.1f)\n", distance - radius,
              distance + radius, camera.nearPlane, camera.farPlane, camera.farPlane / camera.nearPlane);
  EXPECT_LE(camera.nearPlane, distance - radius);
  EXPECT_GE(camera.farPlane, distance + radius);
  EXPECT_LE(camera.farPlane / camera.nearPlane, 10.0);
}

// The committed third-party assets (examples/assets/, CC0 and CC BY) as the example scenes draw them
// (examples/scenes/gltf/<name>.json: the asset's own materials, imported by `matc import`, under an
// analytic sky, drawn behind them): every feature set the scene names is one `matc import` writes, and the scene
// renders on both APIs (at most 2 steps and 0.1 % of the values more than 1 step apart), each tier
// measured against `reference` (docs/gltf.md quotes the printed lines). The 2 steps hold at
// silhouettes because GL's render() draws its rows in Vulkan's memory order (runtime/gl/gl_row_order.h):
// drawn bottom-up, the water bottle had a pixel 3 steps apart, a texture level chosen from the other
// row of its 2×2 quad (docs/gltf.md, "Vulkan and GLES at silhouettes").
struct RealAsset {
  const char* scene;  // examples/scenes/gltf/<scene>.json
  const char* gltf;   // examples/assets/<scene>/<gltf>
  size_t featureSets;
  size_t notes;  // what `matc import` reports it does not draw as the file says
};

// Names the asset in test listings (gtest would print the struct's bytes).
void PrintTo(const RealAsset& asset, std::ostream* os) { *os << asset.gltf; }

class GltfRealAssets : public testing::TestWithParam<RealAsset> {};

TEST_P(GltfRealAssets, RenderOnVulkanAndGlesWithTheirOwnMaterials) {
  const RealAsset asset = GetParam();
  const std::string examples = facet::test::sourceDir() + "/examples";
  const std::string dir = facet::test::scratchDir(std::string("gltf-asset-") + asset.scene);
  fs::remove_all(dir);
  facet::runtime::GltfImport imported;
  std::string error;
  ASSERT_TRUE(facet::runtime::importGltf(examples + "/assets/" + asset.scene + "/" + asset.gltf, dir, examples,
                                         &imported, &error))
      << error;
  ASSERT_EQ(imported.materials.size(), asset.featureSets);
  EXPECT_EQ(imported.notes.size(), asset.notes);
  for (const std::string& note : imported.notes) std::printf("%s\n", note.c_str());
  std::vector<std::string> texts;
  std::set<std::string> featureSets;
  for (const std::string& path : imported.materials) {
    texts.push_back(facet::test::readText(path));
    featureSets.insert(fs::path(path).stem().string());
  }
  const std::string packages =
      facet::test::writePackagesFromTexts(std::string("gltf-asset-packages-") + asset.scene, texts);

  auto scene =
      facet::runtime::loadScene(examples + "/scenes/gltf/" + asset.scene + ".json", &error, {.assetRoot = examples});
  ASSERT_TRUE(scene) << error;
  for (const auto& object : scene->objects) EXPECT_TRUE(featureSets.count(object.material)) << object.material;
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
  ASSERT_TRUE(frame) << error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  facet::runtime::FrameResult a, b;
  ASSERT_TRUE(vk->render(frame->frame(), &a, &error)) << error;
  ASSERT_TRUE(gl->render(frame->frame(), &b, &error)) << error;
  ASSERT_EQ(a.ldr.size(), b.ldr.size());
  size_t beyond1 = 0, covered = 0;
  for (size_t i = 0; i < a.ldr.size(); ++i) beyond1 += std::abs(int(a.ldr[i]) - int(b.ldr[i])) > 1;
  // The asset is drawn: a tenth of the pixels at least differ from the background's colour
  // (the corner pixel of the frame with a flat background; the avocado covers 13 %, the bottle
  // 21 %, the truck 23 %, the alpha test board 46 %, the vertex colour board 32 %, the two-UV cube
  // 38 %, the texture transform quads 26 %), so an empty frame cannot pass.
  facet::runtime::Scene flatScene = *scene;
  flatScene.background.environment = false;
  auto flatFrame = facet::runtime::SceneFrame::prepare(flatScene, packages, &error);
  ASSERT_TRUE(flatFrame) << error;
  facet::runtime::FrameResult flat;
  ASSERT_TRUE(vk->render(flatFrame->frame(), &flat, &error)) << error;
  for (size_t i = 0; i + 3 < flat.ldr.size(); i += 4)
    covered += std::abs(int(flat.ldr[i]) - int(flat.ldr[0])) + std::abs(int(flat.ldr[i + 1]) - int(flat.ldr[1])) +
                   std::abs(int(flat.ldr[i + 2]) - int(flat.ldr[2])) >
               6;
  std::printf("%s Vulkan vs GLES: max %d steps, %zu of %zu values beyond 1 step; %zu of %zu pixels drawn\n", asset.gltf,
              maxDifference(a.ldr, b.ldr), beyond1, a.ldr.size(), covered, a.ldr.size() / 4);
  EXPECT_LE(maxDifference(a.ldr, b.ldr), 2);
  EXPECT_LE(double(beyond1), 0.001 * double(a.ldr.size()));
  EXPECT_GE(double(covered), double(a.ldr.size() / 4) / 10.0);
  EXPECT_TRUE(vk->validationErrors().empty());
  EXPECT_TRUE(gl->validationErrors().empty());

  facet::runtime::FrameResult reference;
  for (const char* tier : {"reference", "high", "mid", "low"}) {
    scene->tier = tier;
    auto tierFrame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
    ASSERT_TRUE(tierFrame) << error;
    facet::runtime::FrameResult result;
    ASSERT_TRUE(vk->render(tierFrame->frame(), &result, &error)) << error;
    if (std::string(tier) == "reference") {
      reference = std::move(result);
      continue;
    }
    const double db = facet::test::psnr(reference.ldr, result.ldr);
    std::printf("%s %s vs reference: PSNR %.1f dB\n", asset.gltf, tier, db);
    EXPECT_GE(db, 30.0) << tier;
  }
}

INSTANTIATE_TEST_SUITE_P(Committed, GltfRealAssets,
                         testing::Values(RealAsset{"avocado", "Avocado.gltf", 1, 0},
                                         RealAsset{"water_bottle", "WaterBottle.gltf", 1, 0},
                                         RealAsset{"milk_truck", "CesiumMilkTruck.gltf", 2, 0},
                                         RealAsset{"alpha_blend_mode", "AlphaBlendModeTest.gltf", 6, 0},
                                         RealAsset{"vertex_color_test", "VertexColorTest.gltf", 2, 0},
                                         RealAsset{"multi_uv_test", "MultiUVTest.gltf", 1, 0},
                                         RealAsset{"texture_transform_test", "TextureTransformTest.gltf", 2, 0}),
                         [](const testing::TestParamInfo<RealAsset>& param) { return std::string(param.param.scene); });

}  // namespace
