// What SceneFrame gives a backend for the sun's shadow (render_backend.h ShadowPassDesc,
// docs/shadows.md "Shadow pass"): the casters with their depth-only programs, the cascades
// fitted to them with the casters each can see and the biases in depth, the uniforms the
// receivers read, and receivers drawn with their `.shN` variant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>
#include <string>
#include <vector>

#include "facet/runtime/material.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/runtime/sun_shadow.h"
#include "test_compile.h"
#include "test_support.h"

namespace facet::runtime {
namespace {

// A box over a plane, a box that casts but does not receive, a sphere that receives but does not
// cast, and a transparent sphere (never a caster).
const char* kScene = R"({"width": 96, "height": 64, "tier": "high",
  "camera": {"position": [2.2, 1.4, 3.2], "target": [0.3, 0.2, 0.3], "fovY": 40},
  "sun": {"direction": [0.5, -0.6, -0.62], "illuminance": 100000, "castShadows": true},
  "shadows": {"atlasSize": 1024, "cascades": 3, "depthBias": 1.5, "slopeBias": 2.5},
  "objects": [
    {"mesh": "plane", "material": "plastic", "scale": [40, 1, 40]},
    {"mesh": "box", "material": "plastic", "position": [0, 0.5, 0], "rotation": [0, 20, 0]},
    {"mesh": "box", "material": "plastic", "position": [30, 0.5, -30], "scale": [2, 1, 1], "receiveShadows": false},
    {"mesh": "sphere", "material": "plastic", "position": [-1, 0.5, 1], "radius": 0.5, "castShadows": false},
    {"mesh": "sphere", "material": "glass", "position": [1, 0.5, 1], "radius": 0.5}
  ]})";

std::string packages() {
  compiler::BuildOptions options;
  options.shadowCascadeCounts = {0, 1, 2, 4};
  return test::writePackagesFromTexts("shadow-frame",
                                      {"material plastic { shading lit\n surface { baseColor = vec3(0.8, 0.3, 0.1) } }",
                                       "material glass { shading lit\n blending transparent\n surface { baseColor = "
                                       "vec3(0.2, 0.5, 0.9)\n alpha = 0.5 } }"},
                                      options);
}

std::unique_ptr<SceneFrame> prepared(const Scene& scene, const std::string& dir) {
  std::string error;
  auto frame = SceneFrame::prepare(scene, dir, &error);
  EXPECT_TRUE(frame) << error;
  return frame;
}

ShaderProgram programOf(const std::string& dir, const std::string& material, const std::string& key) {
  std::string error;
  auto loaded = LoadedMaterial::load(dir + "/" + material + ".matpkg", &error);
  EXPECT_TRUE(loaded) << error;
  auto program = loaded->program(key, &error);
  EXPECT_TRUE(program) << error;
  return *program;
}

TEST(ShadowFrame, CastersCascadesBiasesAndUniformsComeFromTheFit) {
  std::string error;
  auto scene = parseScene("s.json", kScene, &error);
  ASSERT_TRUE(scene) << error;
  const std::string dir = packages();
  auto frame = prepared(*scene, dir);
  ASSERT_TRUE(frame);
  ASSERT_TRUE(frame->frame().shadow);
  const ShadowPassDesc& shadow = *frame->frame().shadow;
  EXPECT_EQ(shadow.atlasSize, 1024u);
  // The plane and two boxes cast; the sphere with castShadows false and the transparent one do not.
  ASSERT_EQ(shadow.casters.size(), 3u);
  const ShaderProgram depth = programOf(dir, "plastic", "high.depth");
  for (const DrawItem& c : shadow.casters) EXPECT_EQ(c.program->vertexSpirv, depth.vertexSpirv);

  // The casters' spheres as the test derives them: the unit plane's and box's corners.
  const double plane = std::sqrt(2.0) * 0.5 * 40, box = std::sqrt(3.0) * 0.5;
  std::vector<CasterBounds> bounds = {
      {{0, 0, 0}, plane}, {{0, 0.5, 0}, box}, {{30, 0.5, -30}, std::sqrt(4.0 + 1 + 1) * 0.5 * 2}};
  const SunShadowFit fit = fitSunShadow(*scene, bounds);
  ASSERT_EQ(shadow.cascades.size(), 3u);
  ASSERT_EQ(fit.cascades.size(), 3u);
  EXPECT_EQ(std::memcmp(&shadow.uniforms, &fit.uniforms, sizeof fit.uniforms), 0);
  bool farBoxSkipped = false;
  for (size_t k = 0; k < fit.cascades.size(); ++k) {
    const SunCascade& c = fit.cascades[k];
    const ShadowCascadeDesc& d = shadow.cascades[k];
    const glm::mat4 expected(c.viewProjection);
    EXPECT_EQ(std::memcmp(d.viewProjection, glm::value_ptr(expected), sizeof d.viewProjection), 0) << k;
    EXPECT_EQ(std::vector<uint32_t>(d.viewport, d.viewport + 4),
              std::vector<uint32_t>(c.viewport.begin(), c.viewport.end()));
    EXPECT_NEAR(d.depthBias, 1.5 * c.texelSize / c.depthRange, 1e-6 * d.depthBias) << k;
    EXPECT_EQ(d.slopeBias, 2.5f);
    std::vector<uint32_t> kept;
    for (uint32_t i = 0; i < bounds.size(); ++i)
      if (casterInCascade(c, bounds[i], scene->sun->direction)) kept.push_back(i);
    EXPECT_EQ(d.casters, kept) << k;
    EXPECT_TRUE(std::find(kept.begin(), kept.end(), 0u) != kept.end()) << "the ground shadows every cascade";
    farBoxSkipped |= std::find(kept.begin(), kept.end(), 2u) == kept.end();
  }
  EXPECT_TRUE(farBoxSkipped) << "the box 42 m away is culled from the near cascades";

  // Receivers draw the 4-cascade variant (3 cascades use .sh4); the box that does not receive the
  // plain one.
  const ShaderProgram receiver = programOf(dir, "plastic", "high.dir1.sh4");
  const ShaderProgram plain = programOf(dir, "plastic", "high.dir1");
  size_t receivers = 0, plainDraws = 0;
  for (const DrawItem& d : frame->frame().draws) {
    receivers += d.program->fragmentSpirv == receiver.fragmentSpirv ? d.instances.size() : 0;
    plainDraws += d.program->fragmentSpirv == plain.fragmentSpirv ? d.instances.size() : 0;
  }
  EXPECT_EQ(receivers, 3u);  // plane, box, sphere
  EXPECT_EQ(plainDraws, 1u);
}

// The box behind the camera (tests/data/scenes/shadows/behind_camera.json) is out of the view
// but its shadow reaches into it: it is drawn into the cascades it can shadow.
TEST(ShadowFrame, ACasterBehindTheCameraIsDrawn) {
  std::string error;
  auto scene = loadScene(test::sourceDir() + "/tests/data/scenes/shadows/behind_camera.json", &error);
  ASSERT_TRUE(scene) << error;
  compiler::BuildOptions options;
  options.shadowCascadeCounts = {0, 1, 2, 4};
  auto frame = prepared(*scene, test::writeExamplePackages("shadow-frame-behind", options));
  ASSERT_TRUE(frame);
  ASSERT_TRUE(frame->frame().shadow);
  const ShadowPassDesc& shadow = *frame->frame().shadow;
  ASSERT_EQ(shadow.casters.size(), 2u);
  ASSERT_EQ(shadow.cascades.size(), 4u);
  size_t cascadesWithTheBox = 0;
  for (const ShadowCascadeDesc& c : shadow.cascades)
    cascadesWithTheBox += std::count(c.casters.begin(), c.casters.end(), 1u);
  EXPECT_GT(cascadesWithTheBox, 0u);
}

TEST(ShadowFrame, WithoutACastingSunThereIsNoShadowPass) {
  std::string error;
  auto scene = parseScene("s.json", kScene, &error);
  ASSERT_TRUE(scene) << error;
  scene->sun->castShadows = false;
  auto frame = prepared(*scene, packages());
  ASSERT_TRUE(frame);
  EXPECT_FALSE(frame->frame().shadow);
}

// Packages built without shadows hold no receiver: the scene is refused with the key it needs.
TEST(ShadowFrame, PackagesWithoutReceiversAreRefused) {
  std::string error;
  auto scene = parseScene("s.json", kScene, &error);
  ASSERT_TRUE(scene) << error;
  const std::string dir = test::writePackagesFromTexts(
      "shadow-frame-none", {"material plastic { shading lit\n surface { baseColor = vec3(0.8, 0.3, 0.1) } }",
                            "material glass { shading lit\n blending transparent\n surface { alpha = 0.5 } }"});
  EXPECT_FALSE(SceneFrame::prepare(*scene, dir, &error));
  EXPECT_NE(error.find("high.dir1.sh4"), std::string::npos) << error;
}

// A casting spot light is fitted and drawn (shadowPassDesc) but no variant receives it yet: the
// scene is refused at the light's pointer rather than rendered with its objects lit through their
// casters.
TEST(ShadowFrame, ACastingSpotLightIsRefusedUntilReceiversExist) {
  std::string error;
  auto scene = parseScene("s.json", kScene, &error);
  ASSERT_TRUE(scene) << error;
  PunctualLight spot;
  spot.spot = true;
  spot.castShadows = true;
  scene->lights = {PunctualLight{}, spot};
  EXPECT_FALSE(SceneFrame::prepare(*scene, packages(), &error));
  EXPECT_EQ(error,
            "/lights/1/castShadows: spot-light shadows are not rendered yet: no material variant receives them "
            "(docs/shadows.md, \"Spot shadows\")");
  // Without it the scene goes on to ask for its variant (these packages have no point lights).
  scene->lights[1].castShadows = false;
  EXPECT_FALSE(SceneFrame::prepare(*scene, packages(), &error));
  EXPECT_NE(error.find("high.dir1.sh4.pt2"), std::string::npos) << error;
}

}  // namespace
}  // namespace facet::runtime
