// Rendering the example scene: both backends agree, and both agree with the maths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "dfg_lookup.h"
#include "facet/eval/standard_model.h"
#include "facet/permutations/variant_key.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "reference/specular_tiers.h"
#include "sphere_pixels.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using facet::runtime::FrameResult;

// Every example material compiled into a scratch folder, as the main job does with matc.
std::string compileExamplePackages() { return facet::test::writeExamplePackages("render-packages"); }

// The example sphere scene rendered once per test process by both backends. Failures are kept
// as text and asserted by every test, so a broken setup shows as failed tests, never skipped ones.
struct SphereRenders {
  std::string error;
  std::string packages;
  facet::runtime::Scene scene;
  std::unique_ptr<facet::runtime::SceneFrame> frame;
  FrameResult vulkan, gl;
};

const SphereRenders& sphereRenders() {
  static SphereRenders r = [] {
    SphereRenders out;
    std::string& error = out.error;
    out.packages = compileExamplePackages();
    auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/sphere.json"), &error);
    if (!scene) return out;
    out.scene = *scene;
    out.frame = facet::runtime::SceneFrame::prepare(*scene, out.packages, &error);
    if (!out.frame) return out;
    // Full-precision vertices: the CPU evaluation below uses the exact sphere normal, and the
    // packed 10-bit normals move the steep flank of the highlight by up to 1.3 % (the packing's
    // own figures: test_vertex_packing).
    facet::runtime::VulkanOptions vkOptions;
    vkOptions.validation = true;
    vkOptions.vertexPacking = facet::runtime::VertexPacking::FullPrecision;
    auto vk = facet::runtime::createVulkanBackend(vkOptions, &error);
    if (!vk || !vk->render(out.frame->frame(), &out.vulkan, &error)) return out;
    for (const auto& m : vk->validationErrors()) error += "Vulkan validation: " + m + "\n";
    facet::runtime::GlOptions glOptions;
    glOptions.vertexPacking = facet::runtime::VertexPacking::FullPrecision;
    auto gl = facet::runtime::createGlBackend(glOptions, &error);
    if (!gl || !gl->render(out.frame->frame(), &out.gl, &error)) return out;
    for (const auto& m : gl->validationErrors()) error += "GL debug output: " + m + "\n";
    if (out.vulkan.ldr.size() != out.gl.ldr.size()) error += "image sizes differ\n";
    return out;
  }();
  return r;
}

class SphereScene : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(r.error, ""); }
  const SphereRenders& r = sphereRenders();
  const FrameResult* vulkan_ = &r.vulkan;
  const FrameResult* gl_ = &r.gl;
};

}  // namespace

// Both backends run the same material through different compilers (SPIR-V on lavapipe, GLSL ES
// on llvmpipe's GL). Tolerance: 1 step of 8 bits in the LDR image; in HDR 1 % + 0.002 per
// channel. Measured: the largest HDR difference is on the flank of the highlight, where D is
// steep and interpolation order moves the value by a few fp16 steps (0.5186 vs 0.5146).
TEST_F(SphereScene, VulkanAndGlAgreePixelByPixel) {
  int maxLdr = 0;
  for (size_t i = 0; i < vulkan_->ldr.size(); ++i)
    maxLdr = std::max(maxLdr, std::abs(int(vulkan_->ldr[i]) - int(gl_->ldr[i])));
  EXPECT_LE(maxLdr, 1);
  for (size_t i = 0; i < vulkan_->hdr.size(); ++i) {
    double a = vulkan_->hdr[i], b = gl_->hdr[i];
    if (std::abs(a - b) > 0.01 * std::abs(b) + 0.002) {
      ADD_FAILURE() << "HDR differs at pixel (" << (i / 4) % vulkan_->width << ", " << (i / 4) / vulkan_->width
                    << ") channel " << i % 4 << ": Vulkan " << a << ", GL " << b;
      break;
    }
  }
}

// The HDR output at points of the sphere equals a double-precision evaluation of the same
// BRDF for the same light, camera and parameters. Points within 0.25 of grazing are skipped:
// there a pixel's centre and the tessellated silhouette differ by more than the BRDF does.
TEST_F(SphereScene, PixelsMatchCpuEvaluationOfTheBrdf) {
  const auto& scene = r.scene;
  const auto& f = r.frame->frame().frame;
  glm::dvec3 l(f.lightDirection[0], f.lightDirection[1], f.lightDirection[2]);
  glm::dvec3 light(f.lightColor[0], f.lightColor[1], f.lightColor[2]);
  glm::dvec3 ambient(f.ambient[0], f.ambient[1], f.ambient[2]);

  // red_plastic with its package defaults (colour already linear in the package).
  std::string error;
  auto material = facet::runtime::LoadedMaterial::load(r.packages + "/red_plastic.matpkg", &error);
  ASSERT_TRUE(material) << error;
  facet::reference::Surface surface;
  for (const auto& p : material->info().params) {
    if (p.name == "baseColor") surface.baseColor = {p.defaultValue[0], p.defaultValue[1], p.defaultValue[2]};
    if (p.name == "roughness") surface.roughness = p.defaultValue[0];
    if (p.name == "reflectance") surface.reflectance = p.defaultValue[0];
  }
  int checked = 0;
  double worst = 0;
  facet::test::forEachSpherePixel(scene, 8, 0.25, [&](uint32_t x, uint32_t y, glm::dvec3, glm::dvec3 n, glm::dvec3 v) {
    // The constant sky's image-based specular: the environment is `ambient` in every direction and
    // at every level (exact), so the split-sum term is ambient · (f0·A + B) of the DFG table as
    // the shader reads it. The high tier's energy compensation 1 + f0 (1/dfg.y − 1), from the
    // same texel, scales it and the direct specular.
    const double f0 = 0.16 * surface.reflectance * surface.reflectance;
    auto [b, albedo] = facet::test::dfgBilinear(glm::dot(n, v), std::clamp(surface.roughness, 0.089, 1.0));
    const double compensation = 1 + f0 * (1 / albedo - 1);
    glm::dvec3 expected = facet::reference::shadeStandard(surface, n, v, l, light, ambient, glm::dvec3(compensation));
    expected += ambient * (f0 * albedo + (1 - f0) * b) * compensation;
    const float* got = &vulkan_->hdr[(size_t(y) * scene.width + x) * 4];
    for (int ch = 0; ch < 3; ++ch) {
      double relative = std::abs(got[ch] - expected[ch]) / (expected[ch] + 0.01);
      worst = std::max(worst, relative);
      EXPECT_LE(relative, 0.01) << "pixel (" << x << ", " << y << ") channel " << ch << ": GPU " << got[ch] << ", CPU "
                                << expected[ch];
    }
    ++checked;
  });
  EXPECT_GT(checked, 200);  // the sphere covers much of the frame; most grid points are checked
  RecordProperty("worst_relative_error_x1e6", int(worst * 1e6));
}

TEST(SceneErrors, VariantNotBuiltForTheSceneIsAClearError) {
  std::string error;
  // Built for two tiers only, as `matc compile --tiers reference,high` would.
  facet::compiler::BuildOptions options;
  options.tiers = {facet::permutations::Tier::Reference, facet::permutations::Tier::High};
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"), options);
  ASSERT_TRUE(built);
  std::string packages = facet::test::scratchDir("two-tier-packages");
  ASSERT_TRUE(
      facet::package::writeFile(packages + "/red_plastic.matpkg", facet::package::write(built->package), &error));
  auto scene = facet::runtime::parseScene(
      "lowend.json", R"({"tier": "low", "sun": {}, "objects": [{"material": "red_plastic"}]})", &error);
  ASSERT_TRUE(scene) << error;
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
  EXPECT_FALSE(frame);
  EXPECT_NE(
      error.find("was not built with variant 'low.dir1' (built: reference.dir0, reference.dir1, high.dir0, high.dir1)"),
      std::string::npos)
      << error;
}

TEST(SceneErrors, MalformedSceneJsonReportsLineAndColumn) {
  std::string error;
  auto scene = facet::runtime::parseScene("bad.json", "{\n  \"objects\": [\n    {\"material\": }\n  ]\n}\n", &error);
  EXPECT_FALSE(scene);
  EXPECT_EQ(error.rfind("bad.json:3:18: error: invalid JSON", 0), 0u) << error;
}

TEST(SceneErrors, WrongValuesNameTheirJsonPointer) {
  std::string error;
  EXPECT_FALSE(facet::runtime::parseScene("s.json", R"({"objects": [{"material": "m", "radius": -1}]})", &error));
  EXPECT_EQ(error, "s.json: error: /objects/0/radius: value -1 is outside [0.0001, 1000000.0]") << error;
  EXPECT_FALSE(facet::runtime::parseScene("s.json", R"({"sun": {"ilumination": 5}, "objects": []})", &error));
  EXPECT_EQ(error, "s.json: error: /sun/ilumination: unknown key 'ilumination'") << error;
}

TEST(SceneErrors, ParameterOutsideDeclaredRangeIsRejected) {
  std::string error;
  std::string packages = compileExamplePackages();
  auto material = facet::runtime::LoadedMaterial::load(packages + "/red_plastic.matpkg", &error);
  ASSERT_TRUE(material) << error;
  EXPECT_FALSE(material->paramBlock({{"roughness", {1.5}}}, &error));
  EXPECT_NE(error.find("= 1.5 is outside its range [0, 1]"), std::string::npos) << error;
  EXPECT_FALSE(material->paramBlock({{"rougness", {0.5}}}, &error));
  EXPECT_NE(error.find("has no parameter 'rougness'"), std::string::npos) << error;
}

namespace {

// Renders a scene (JSON text, resolved against examples/scenes/) with the given packages.
bool renderScene(const std::string& json, const std::string& packages, facet::runtime::RenderBackend& backend,
                 FrameResult* out, std::string* error) {
  auto scene = facet::runtime::parseScene(facet::test::examplePath("scenes/inline.json"), json, error);
  if (!scene) return false;
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, error);
  return frame && backend.render(frame->frame(), out, error);
}

int maxDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  int d = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) d = std::max(d, std::abs(int(a[i]) - int(b[i])));
  return a.size() == b.size() ? d : 256;
}

const char* kTwoSpheres =
    R"({"width": 96, "height": 64, "sun": {"direction": [-0.4, -0.55, -0.73]}, "sky": {"luminance": 6000},
  "camera": {"position": [0, 0, 6], "fovY": 30},
  "objects": [{"material": "%s", "position": [-1.1, 0, 0]}, {"material": "%s", "position": [1.1, 0, 0]%s}]})";

std::string twoSpheres(const std::string& material, const std::string& secondParams = "") {
  char buf[1024];
  std::snprintf(buf, sizeof buf, kTwoSpheres, material.c_str(), material.c_str(), secondParams.c_str());
  return buf;
}

}  // namespace

// An sRGB texture whose texels are C (here the 1×1 default) must shade exactly like a colour
// parameter C: both arrive linear, one decoded by the sampler, the other by matc.
TEST(Textures, SrgbTextureShadesLikeTheSameColourParameter) {
  std::string packages = facet::test::writePackagesFromTexts(
      "texture-vs-colour",
      {"material by_colour { param c: color = vec3(0.8, 0.4, 0.2)\n surface { baseColor = params.c } }",
       "material by_texture { param t: texture(srgb) = vec4(0.8, 0.4, 0.2, 1.0)\n"
       " surface { baseColor = sample(params.t, vertex.uv0).rgb } }"});
  std::string error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  ASSERT_TRUE(vk) << error;
  FrameResult colour, texture;
  ASSERT_TRUE(renderScene(twoSpheres("by_colour"), packages, *vk, &colour, &error)) << error;
  ASSERT_TRUE(renderScene(twoSpheres("by_texture"), packages, *vk, &texture, &error)) << error;
  // 0.8 in sRGB is stored as 204/255 = 0.8000 exactly, 0.4 as 102/255 and 0.2 as 51/255: one
  // 8-bit step of slack covers the texel quantisation.
  EXPECT_LE(maxDifference(colour.ldr, texture.ldr), 1);
  EXPECT_TRUE(vk->validationErrors().empty());
}

TEST(Textures, TexturedExampleSceneAgreesOnBothBackends) {
  std::string packages = compileExamplePackages();
  std::string error;
  auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/tiles.json"), &error);
  ASSERT_TRUE(scene) << error;
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
  ASSERT_TRUE(frame) << error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  FrameResult a, b;
  ASSERT_TRUE(vk->render(frame->frame(), &a, &error)) << error;
  ASSERT_TRUE(gl->render(frame->frame(), &b, &error)) << error;
  // Trilinear sampling of a high-contrast image: each rasteriser computes its own LOD and filter
  // weights, so texels at tile edges may differ by a few steps; nearly everything else agrees.
  size_t within1 = 0;
  for (size_t i = 0; i < a.ldr.size(); ++i) within1 += std::abs(int(a.ldr[i]) - int(b.ldr[i])) <= 1;
  double share = double(within1) / double(a.ldr.size());
  std::printf("tiles.json Vulkan vs GL: max %d steps, %.4f%% of values within 1 step\n", maxDifference(a.ldr, b.ldr),
              100.0 * share);
  EXPECT_LE(maxDifference(a.ldr, b.ldr), 6);
  EXPECT_GE(share, 0.995);
  EXPECT_TRUE(vk->validationErrors().empty());
  EXPECT_TRUE(gl->validationErrors().empty());
}

TEST(Textures, UnreadableImageIsAClearErrorNotACrash) {
  std::string packages = compileExamplePackages();
  std::string dir = facet::test::scratchDir("bad-image");
  { std::ofstream(dir + "/broken.png", std::ios::binary) << std::string("\x89PNG\r\n\x1a\nnot really", 18); }
  std::string error;
  auto scene = facet::runtime::parseScene(
      dir + "/scene.json",
      R"({"sun": {}, "objects": [{"material": "painted_tiles", "params": {"albedo": "broken.png"}}]})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*scene, packages, &error));
  EXPECT_NE(error.find("broken.png: cannot read image"), std::string::npos) << error;

  scene = facet::runtime::parseScene(
      dir + "/scene.json",
      R"({"sun": {}, "objects": [{"material": "red_plastic", "params": {"roughness": "tiles.png"}}]})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*scene, packages, &error));
  EXPECT_NE(error.find("has no texture parameter 'roughness'"), std::string::npos) << error;
}

namespace {

struct Rgb {
  double r, g, b;
};

// The HDR colour at the centre of a 32×32 render of one unit sphere with `material`.
Rgb centreOf(facet::runtime::RenderBackend& backend, const std::string& packages, const std::string& material,
             const std::string& params) {
  std::string json =
      R"({"width": 32, "height": 32, "sun": {"direction": [-0.3, -0.5, -0.8]}, "sky": {"luminance": 6000},
    "camera": {"position": [0, 0, 4], "fovY": 40}, "objects": [{"material": ")" +
      material + R"(", "params": {)" + params + "}}]}";
  std::string error;
  FrameResult result;
  EXPECT_TRUE(renderScene(json, packages, backend, &result, &error)) << error;
  if (result.hdr.empty()) return {-1, -1, -1};
  const float* p = &result.hdr[(16 * 32 + 16) * 4];
  return {p[0], p[1], p[2]};
}

void expectNear(Rgb got, Rgb want, const char* what) {
  // RGBA16F storage: 2^-11 relative, plus the same again from the blend of two stored values.
  auto near = [](double a, double b) { return std::abs(a - b) <= 2e-3 * std::abs(b) + 1e-3; };
  EXPECT_TRUE(near(got.r, want.r) && near(got.g, want.g) && near(got.b, want.b))
      << what << ": got (" << got.r << ", " << got.g << ", " << got.b << "), want (" << want.r << ", " << want.g << ", "
      << want.b << ")";
}

}  // namespace

// Each blending mode composites as its formula says, on both backends: transparent is
// premultiplied "over", additive adds, masked discards below its cutoff.
TEST(Blending, EveryModeCompositesAsItsFormulaSays) {
  const std::string surface = "baseColor = vec3(0.8, 0.2, 0.1)\n roughness = 0.6\n";
  std::string packages = facet::test::writePackagesFromTexts(
      "blending", {"material solid { surface { " + surface + " } }",
                   "material glass { blending transparent\n param a: float = 0.25 in [0, 1]\n surface { " + surface +
                       " alpha = params.a } }",
                   "material glow { blending additive\n surface { " + surface + " } }",
                   "material cutout { blending masked(0.5)\n param a: float = 0 in [0, 1]\n surface { " + surface +
                       " alpha = params.a } }"});
  std::string error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  for (facet::runtime::RenderBackend* backend : {vk.get(), gl.get()}) {
    SCOPED_TRACE(backend->name());
    Rgb solid = centreOf(*backend, packages, "solid", "");
    Rgb background = centreOf(*backend, packages, "cutout", R"("a": 0.0)");  // discarded: the sky shows
    // The clear colour is the pre-exposed sky: 6000 cd/m² × 2.60e-5 = 0.156.
    EXPECT_NEAR(background.r, 6000 * 2.604e-5, 1e-3);
    expectNear(centreOf(*backend, packages, "cutout", R"("a": 1.0)"), solid, "masked above cutoff");
    expectNear(centreOf(*backend, packages, "glass", ""),
               {0.25 * solid.r + 0.75 * background.r, 0.25 * solid.g + 0.75 * background.g,
                0.25 * solid.b + 0.75 * background.b},
               "transparent");
    expectNear(centreOf(*backend, packages, "glow", ""),
               {solid.r + background.r, solid.g + background.g, solid.b + background.b}, "additive");
    EXPECT_TRUE(backend->validationErrors().empty());
  }
}

// ---- The low tier: colours and the LUT decode, end to end ----------------------------------------

// Every preset lights linear colours (low too: linear lighting measures better than the gamma hack,
// docs/eval.md): the runtime decodes sRGB colour parameters and lets the sampler decode sRGB
// textures in every tier, so an unlit surface shows the sRGB decode of what was authored, in low as
// in high. (The hack remains a swap of `matc eval`, whose contract
// EvalPreparedFrame.AGammaHackSwapSeesColoursAsAuthored checks.) The texture's texels are 204, 102,
// 51 (0.8, 0.4, 0.2).
TEST(LowTier, UnlitOutputIsTheSrgbDecodeAsInEveryTier) {
  std::string packages = facet::test::writePackagesFromTexts(
      "low-unlit", {"material flat_colour { shading unlit\n param c: color = vec3(0.8, 0.4, 0.2)\n surface { baseColor "
                    "= params.c } }",
                    "material flat_texture { shading unlit\n param t: texture(srgb) = vec4(0.8, 0.4, 0.2, 1.0)\n"
                    " surface { baseColor = sample(params.t, vertex.uv0).rgb } }"});
  std::string error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  const auto render = [&](facet::runtime::RenderBackend& backend, const std::string& material,
                          const std::string& tier) {
    std::string json = R"({"width": 32, "height": 32, "tier": ")" + tier + R"(", "sky": {"luminance": 6000},
      "camera": {"position": [0, 0, 4], "fovY": 40}, "objects": [{"material": ")" +
                       material + R"("}]})";
    FrameResult result;
    EXPECT_TRUE(renderScene(json, packages, backend, &result, &error)) << error;
    if (result.hdr.empty()) return Rgb{-1, -1, -1};
    const float* p = &result.hdr[(16 * 32 + 16) * 4];
    return Rgb{p[0], p[1], p[2]};
  };
  const Rgb linear{std::pow((0.8 + 0.055) / 1.055, 2.4), std::pow((0.4 + 0.055) / 1.055, 2.4),
                   std::pow((0.2 + 0.055) / 1.055, 2.4)};
  for (facet::runtime::RenderBackend* backend : {vk.get(), gl.get()}) {
    SCOPED_TRACE(backend->name());
    for (const char* tier : {"low", "high"}) {
      SCOPED_TRACE(tier);
      expectNear(render(*backend, "flat_colour", tier), linear, "colour parameter");
      expectNear(render(*backend, "flat_texture", tier), linear, "sRGB texture");
    }
    EXPECT_TRUE(backend->validationErrors().empty());
  }
}

// Ambient occlusion scales the ambient light alone, in every tier and on both APIs: under the sun
// alone an occluded sphere is lit as an open one (mid and low light diffuse per vertex: the sun's
// goes to the fragment stage apart from the ambient's); under the sky alone AO = 1 changes nothing,
// AO = 0 leaves no light (diffuse and specular ambient both occluded), and with the AO multi-bounce
// (every tier's preset) a white sphere at AO = 0.5 keeps more than half the light of an open one
// (0.5 → 0.85 for albedo 0.9, Jimenez et al.'s fit, less the specular ambient's occlusion).
TEST(AmbientOcclusion, OccludesTheAmbientAloneInEveryTier) {
  const std::string surface = "baseColor = vec3(0.9)\n roughness = 0.5\n";
  std::string packages = facet::test::writePackagesFromTexts(
      "ambient-occlusion", {"material open { surface { " + surface + " } }",
                            "material occluded { param ao: float = 1 in [0, 1]\n surface { " + surface +
                                " ambientOcclusion = params.ao } }"});
  std::string error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  const auto render = [&](facet::runtime::RenderBackend& backend, const std::string& tier, const std::string& light,
                          const std::string& material, const std::string& ao) {
    std::string json = R"({"width": 32, "height": 32, "tier": ")" + tier + R"(", )" + light +
                       R"(, "camera": {"position": [0, 0, 4], "fovY": 40}, "objects": [{"material": ")" + material +
                       R"(", "params": {)" + (ao.empty() ? "" : R"("ao": )" + ao) + "}}]}";
    FrameResult result;
    EXPECT_TRUE(renderScene(json, packages, backend, &result, &error)) << error;
    if (result.hdr.empty()) return Rgb{-1, -1, -1};
    const float* p = &result.hdr[(16 * 32 + 16) * 4];
    return Rgb{p[0], p[1], p[2]};
  };
  const std::string sun = R"("sun": {"direction": [-0.3, -0.5, -0.8]})", sky = R"("sky": {"luminance": 6000})";
  for (facet::runtime::RenderBackend* backend : {vk.get(), gl.get()}) {
    SCOPED_TRACE(backend->name());
    for (const char* tier : {"reference", "high", "mid", "low"}) {
      SCOPED_TRACE(tier);
      const Rgb sunLit = render(*backend, tier, sun, "open", "");
      ASSERT_GT(sunLit.g, 0.05);
      expectNear(render(*backend, tier, sun, "occluded", "0"), sunLit, "occluded under the sun alone");
      const Rgb skyLit = render(*backend, tier, sky, "open", "");
      ASSERT_GT(skyLit.g, 0.05);
      expectNear(render(*backend, tier, sky, "occluded", "1"), skyLit, "AO = 1 under the sky");
      expectNear(render(*backend, tier, sky, "occluded", "0"), Rgb{0, 0, 0}, "AO = 0 under the sky");
      EXPECT_GT(render(*backend, tier, sky, "occluded", "0.5").g, 0.7 * skyLit.g) << "multi-bounce AO at 0.5";
    }
    EXPECT_TRUE(backend->validationErrors().empty());
  }
}

TEST(LowTier, ColourParametersStayAsAuthoredForTheGammaHack) {
  std::string error;
  std::string packages = compileExamplePackages();
  auto material = facet::runtime::LoadedMaterial::load(packages + "/red_plastic.matpkg", &error);
  ASSERT_TRUE(material) << error;
  // red_plastic: baseColor (0.80, 0.08, 0.06) authored, at offset 0 of its block.
  auto floats = [](const std::vector<uint8_t>& block) {
    float f[3];
    std::memcpy(f, block.data(), sizeof f);
    return std::vector<double>{f[0], f[1], f[2]};
  };
  using facet::runtime::ColorEncoding;
  auto encoded = material->paramBlock({}, &error, ColorEncoding::Srgb);
  ASSERT_TRUE(encoded) << error;
  std::vector<double> defaults = floats(*encoded);
  EXPECT_NEAR(defaults[0], 0.80, 1e-6);
  EXPECT_NEAR(defaults[1], 0.08, 1e-6);
  EXPECT_NEAR(defaults[2], 0.06, 1e-6);
  auto given = material->paramBlock({{"baseColor", {0.5, 0.25, 1.0}}}, &error, ColorEncoding::Srgb);
  ASSERT_TRUE(given) << error;
  EXPECT_EQ(floats(*given), (std::vector<double>{0.5, 0.25, 1.0}));
  auto linear = material->paramBlock({{"baseColor", {0.5, 0.25, 1.0}}}, &error);
  ASSERT_TRUE(linear) << error;
  EXPECT_NEAR(floats(*linear)[0], 0.21404, 1e-5);  // the linear tiers still decode
}

// The low tier's brushed_gold (a metal: no diffuse; the sky is switched off, so no ambient) against the documented
// formula in double (chunks/specular_lut_lobe.glsl): HDR = S · E_dfg · c_ms · E · n·l with S the table sampled
// bilinearly at u = max(R·L, 0)⁴, v = roughness, decoded as its square × 16/π (√ encoding; each row already divided by
// its lobe's albedo), E_dfg = f0 · A + B the environment BRDF and c_ms = 1 + f0 (1/albedo − 1) the energy compensation,
// both from the DFG table at (n·v, r), and f0 the tint, linear. The tessellated sphere's normals differ from the
// analytic one's and the table is steep in the highlight, so each point accepts the range the formula takes for R·L
// within ±0.01 of the analytic value, widened by one table step (see `lsb`), ±1 % ± 0.002. A wrong scale, table, f0
// encoding or output square fails it.
TEST(LowTier, MetalPixelsMatchTheLutFormula) {
  std::string error;
  std::string packages = compileExamplePackages();
  auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/sphere.json"), &error);
  ASSERT_TRUE(scene) << error;
  scene->tier = "low";
  scene->objects[0].material = "brushed_gold";
  scene->skyLuminance = 0;  // a metal's ambient is all environment specular; this test is the LUT's
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
  ASSERT_TRUE(frame) << error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  ASSERT_TRUE(vk) << error;
  FrameResult image;
  ASSERT_TRUE(vk->render(frame->frame(), &image, &error)) << error;
  EXPECT_TRUE(vk->validationErrors().empty());

  auto material = facet::runtime::LoadedMaterial::load(packages + "/brushed_gold.matpkg", &error);
  ASSERT_TRUE(material) << error;
  glm::dvec3 f0(0);
  double roughness = 0;
  for (const auto& p : material->info().params) {
    if (p.name == "tint") f0 = {p.defaultValue[0], p.defaultValue[1], p.defaultValue[2]};
    if (p.name == "roughness") roughness = p.defaultValue[0];
  }
  ASSERT_GT(roughness, 0.0);
  ASSERT_FALSE(material->reader().textures().empty());
  const auto& table = material->reader().textures().at(0);
  ASSERT_EQ(table.name, "facet_specularLut");
  auto texels = material->reader().texels(0, &error);
  ASSERT_TRUE(texels) << error;
  const std::vector<uint8_t> tableTexels(texels->begin(), texels->end());
  const double scale = 16.0 / facet::reference::kPi;
  // lavapipe (like llvmpipe) filters 8-bit UNORM textures in 8-bit arithmetic: each sample comes
  // back as a whole number of table steps (measured: within 3e-4 of one), the bilinear value
  // rounded. So one step of slack, in the encoded domain (before the square).
  const double lsb = 1.0 / 255.0;
  auto encoded = [&](double RoL) {
    double c = std::clamp(RoL, 0.0, 1.0);
    double u = facet::reference::lutTexelCoordinate(c * c * c * c, table.width);
    double v = facet::reference::lutTexelCoordinate(roughness, table.height);
    return facet::reference::sampleR8Bilinear(tableTexels, table.width, table.height, u, v);
  };
  auto decode = [&](double e) { return std::max(e, 0.0) * std::max(e, 0.0) * scale; };

  const auto& cam = scene->camera;
  glm::dmat4 inverse =
      glm::inverse(glm::perspective(glm::radians(cam.fovYDegrees), double(scene->width) / scene->height, cam.nearPlane,
                                    cam.farPlane) *
                   glm::lookAt(cam.position, cam.target, cam.up));
  const auto& f = frame->frame().frame;
  glm::dvec3 l(f.lightDirection[0], f.lightDirection[1], f.lightDirection[2]);
  glm::dvec3 light(f.lightColor[0], f.lightColor[1], f.lightColor[2]);
  int checked = 0, lit = 0;
  for (uint32_t y = 4; y < scene->height; y += 4) {
    for (uint32_t x = 4; x < scene->width; x += 4) {
      glm::dvec4 ndcNear((x + 0.5) / scene->width * 2 - 1, 1 - (y + 0.5) / scene->height * 2, -1, 1);
      glm::dvec4 ndcFar = ndcNear;
      ndcFar.z = 1;
      glm::dvec4 a = inverse * ndcNear, b = inverse * ndcFar;
      glm::dvec3 origin = glm::dvec3(a) / a.w;
      glm::dvec3 dir = glm::normalize(glm::dvec3(b) / b.w - origin);
      double half = glm::dot(origin, dir), c = glm::dot(origin, origin) - 1.0, disc = half * half - c;
      if (disc <= 0) continue;
      glm::dvec3 n = glm::normalize(origin + (-half - std::sqrt(disc)) * dir);  // unit sphere at the origin
      glm::dvec3 v = -dir;
      if (glm::dot(n, v) < 0.25) continue;
      double NoL = std::clamp(glm::dot(n, l), 0.0, 1.0);
      double RoL = glm::dot(glm::reflect(-v, n), l);
      double lo = 1e30, hi = 0;
      for (int k = -4; k <= 4; ++k) {
        double s = encoded(RoL + 0.0025 * k);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
      }
      const float* got = &image.hdr[(size_t(y) * scene->width + x) * 4];
      const auto [fresnelWeighted, albedo] = facet::test::dfgBilinear(glm::dot(n, v), roughness);
      for (int ch = 0; ch < 3; ++ch) {
        double environmentBrdf = f0[ch] * (albedo - fresnelWeighted) + fresnelWeighted;
        double compensation = 1.0 + f0[ch] * (1.0 / albedo - 1.0);
        double k = environmentBrdf * compensation * light[ch] * NoL;
        EXPECT_GE(got[ch], decode(lo - lsb) * k * 0.99 - 0.002) << "pixel (" << x << ", " << y << ") channel " << ch;
        EXPECT_LE(got[ch], decode(hi + lsb) * k * 1.01 + 0.002) << "pixel (" << x << ", " << y << ") channel " << ch;
      }
      ++checked;
      lit += decode(lo) * NoL > 0.5;
    }
  }
  EXPECT_GT(checked, 500);
  EXPECT_GT(lit, 10);  // the highlight is among the points, not only the black tail
}
