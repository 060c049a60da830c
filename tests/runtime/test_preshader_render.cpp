// The preshader on the GPU: a variant that reads its inputs from the preshaded block draws the
// same image as the same variant computing them per pixel (every tier, both APIs), and a
// material instance's parameter change re-runs the preshader.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "facet/package/package_reader.h"
#include "facet/runtime/material_instance.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using facet::runtime::FrameResult;

struct Packages {
  std::string preshaded, perPixel;
};

const Packages& packages() {
  static const Packages p = [] {
    facet::compiler::BuildOptions perPixel;
    perPixel.preshader = false;
    return Packages{facet::test::writeExamplePackages("preshader-on"),
                    facet::test::writeExamplePackages("preshader-off", perPixel)};
  }();
  return p;
}

int maxDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  if (a.size() != b.size() || a.empty()) return 256;
  int d = 0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(int(a[i]) - int(b[i])));
  return d;
}

std::vector<uint8_t> render(facet::runtime::RenderBackend& backend, const facet::runtime::Scene& scene,
                            const std::string& packageDir, std::string* error) {
  auto frame = facet::runtime::SceneFrame::prepare(scene, packageDir, error);
  FrameResult result;
  if (!frame || !backend.render(frame->frame(), &result, error)) return {};
  return result.ldr;
}

// Three materials (two fully preshaded, one not at all) and a textured one (roughness only),
// and the models' examples (the clear coat's, anisotropy's and the sheen's parameter-only inputs
// preshaded, with instances' own parameters), in each tier, rendered from both packages: within
// one 8-bit step. The inputs are the same formulas evaluated in fp32 on the CPU instead of at the
// tier's precision per pixel.
void expectSameImages(facet::runtime::RenderBackend& backend) {
  for (const char* file : {"scenes/spheres.json", "scenes/tiles.json", "scenes/car_paint.json",
                           "scenes/brushed_metal.json", "scenes/satin.json", "scenes/velvet.json"}) {
    std::string error;
    auto scene = facet::runtime::loadScene(facet::test::examplePath(file), &error);
    ASSERT_TRUE(scene) << error;
    scene->width = 360;  // half size: the spheres still cover thousands of pixels each
    scene->height = scene->height / 2;
    for (const char* tier : {"reference", "high", "mid", "low"}) {
      scene->tier = tier;
      const std::vector<uint8_t> on = render(backend, *scene, packages().preshaded, &error);
      ASSERT_FALSE(on.empty()) << error;
      const std::vector<uint8_t> off = render(backend, *scene, packages().perPixel, &error);
      ASSERT_FALSE(off.empty()) << error;
      EXPECT_LE(maxDifference(on, off), 1) << file << " " << tier;
      EXPECT_GT(std::count_if(on.begin(), on.end(), [](uint8_t c) { return c > 40; }), 1000) << "lit pixels";
    }
  }
  EXPECT_TRUE(backend.validationErrors().empty())
      << (backend.validationErrors().empty() ? "" : backend.validationErrors().front());
}

}  // namespace

TEST(PreshaderRender, PreshadedVariantsDrawThePerPixelImageOnVulkan) {
  std::string error;
  facet::runtime::VulkanOptions options;
  options.validation = true;
  auto backend = facet::runtime::createVulkanBackend(options, &error);
  ASSERT_NE(backend, nullptr) << error;
  expectSameImages(*backend);
}

TEST(PreshaderRender, PreshadedVariantsDrawThePerPixelImageOnGl) {
  std::string error;
  auto backend = facet::runtime::createGlBackend(&error);
  ASSERT_NE(backend, nullptr) << error;
  expectSameImages(*backend);
}

// The shader reads roughness only through the derived members: the image changes with the
// parameter only because setParameter re-runs the preshader.
TEST(PreshaderRender, AnInstancesParameterChangeRerunsThePreshader) {
  std::string error;
  auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/sphere.json"), &error);
  ASSERT_TRUE(scene) << error;
  scene->width = scene->height = 128;
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages().preshaded, &error);
  ASSERT_TRUE(frame) << error;
  auto loaded = facet::runtime::LoadedMaterial::load(packages().preshaded + "/red_plastic.matpkg", &error);
  ASSERT_TRUE(loaded) << error;
  auto material = facet::runtime::Material::create(std::move(*loaded), {scene->tier, true, 0}, &error);
  ASSERT_NE(material, nullptr) << error;
  auto instance = material->createInstance();
  ASSERT_EQ(instance->block().bytes.size(), 80u) << "32 bytes of parameters and 48 of derived inputs (std140)";
  auto derived = [&](uint32_t offset) {
    float v;
    std::memcpy(&v, instance->block().bytes.data() + offset, 4);
    return v;
  };
  EXPECT_FLOAT_EQ(derived(44), 0.35f) << "the default perceptual roughness";
  EXPECT_FLOAT_EQ(derived(60), 0.35f * 0.35f) << "α";

  facet::runtime::FrameDesc desc = frame->frame();
  ASSERT_EQ(desc.draws.size(), 1u);
  desc.draws[0].materialBlock = &instance->block();
  auto backend = facet::runtime::createVulkanBackend({true}, &error);
  ASSERT_NE(backend, nullptr) << error;
  FrameResult glossy, rough;
  ASSERT_TRUE(backend->render(desc, &glossy, &error)) << error;
  ASSERT_TRUE(instance->setParameter("roughness", 0.0f, &error)) << error;
  EXPECT_FLOAT_EQ(derived(44), 0.089f) << "clamped to MIN_PERCEPTUAL_ROUGHNESS on the CPU";
  EXPECT_FLOAT_EQ(derived(60), 0.089f * 0.089f);
  ASSERT_TRUE(instance->setParameter("roughness", 0.9f, &error)) << error;
  EXPECT_FLOAT_EQ(derived(44), 0.9f);
  ASSERT_TRUE(backend->render(desc, &rough, &error)) << error;
  EXPECT_GT(maxDifference(glossy.ldr, rough.ldr), 40) << "a rougher sphere loses its sharp highlight";
  EXPECT_TRUE(backend->validationErrors().empty());
}

// An older lit package cannot be drawn: red_plastic as the 1.2 compiler wrote it samples the
// environment as an octahedral map, and this runtime binds a cube map there (format 1.4). The
// reader still reads it (matc info works); loading it for drawing fails with a message that names
// both formats and how to rebuild, rather than drawing garbage or tripping validation.
TEST(PreshaderRender, AnOlderLitPackageIsRefusedWithARebuildMessage) {
  const std::string dir = facet::test::scratchDir("preshader-1.2");
  const std::string path = dir + "/red_plastic.matpkg";
  std::filesystem::copy_file(facet::test::sourceDir() + "/tests/fuzz/package_corpus/red_plastic_high_1_2.matpkg", path);
  std::string error;
  auto reader = facet::package::PackageReader::openFile(path, &error);
  ASSERT_TRUE(reader) << error;
  EXPECT_EQ(reader->formatMinor(), 2);
  EXPECT_FALSE(facet::runtime::LoadedMaterial::load(path, &error));
  EXPECT_NE(error.find(path + ": package format 1.2 samples the environment as an octahedral map"), std::string::npos)
      << error;
  EXPECT_NE(error.find("matc compile"), std::string::npos) << error;

  auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/sphere.json"), &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*scene, dir, &error));
  EXPECT_NE(error.find("octahedral map"), std::string::npos) << error;
}

// The forward shaders read FrameUniforms::lightDirection as a unit vector (shader_abi.h): the
// scene's sun direction may have any length, the frame block's is normalized on the CPU.
TEST(PreshaderRender, TheSunDirectionReachesTheShadersNormalized) {
  std::string error;
  auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/sphere.json"), &error);
  ASSERT_TRUE(scene) << error;
  ASSERT_TRUE(scene->sun);
  scene->sun->direction = {0.0, -30.0, -40.0};
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages().preshaded, &error);
  ASSERT_TRUE(frame) << error;
  const float* l = frame->frame().frame.lightDirection;
  EXPECT_NEAR(std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]), 1.0f, 1e-6f);
  EXPECT_NEAR(l[1], 0.6f, 1e-6f);
  EXPECT_NEAR(l[2], 0.8f, 1e-6f);
}
