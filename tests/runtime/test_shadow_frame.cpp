// What SceneFrame gives a backend for the sun's shadow (render_backend.h ShadowPassDesc,
// docs/shadows.md "Shadow pass"): the casters with their depth-only programs, the cascades
// fitted to them with the casters each can see and the biases in depth, the uniforms the
// receivers read, and receivers drawn with their `.shN` variant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "facet/runtime/material.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/runtime/spot_shadow.h"
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

// The scene's two materials with the given receivers (the sun's cascades, the point-light counts and
// the spot's `.sp1` twins), in the scratch folder `name`.
std::string packages(const std::string& name = "shadow-frame", const std::vector<int>& cascades = {0, 1, 2, 4},
                     const std::vector<int>& pointLights = {0}, bool spotShadows = false,
                     bool vertexSlopeBias = false) {
  compiler::BuildOptions options;
  options.shadowCascadeCounts = cascades;
  options.pointLightCounts = pointLights;
  options.spotShadows = spotShadows;
  options.vertexSlopeBias = vertexSlopeBias;
  return test::writePackagesFromTexts(name,
                                      {"material plastic { shading lit\n surface { baseColor = vec3(0.8, 0.3, 0.1) } }",
                                       "material glass { shading lit\n blending transparent\n surface { baseColor = "
                                       "vec3(0.2, 0.5, 0.9)\n alpha = 0.5 } }"},
                                      options);
}

// A casting spot light 4 m above the scene, pointing straight down.
PunctualLight castingSpotAbove() {
  PunctualLight spot;
  spot.spot = true;
  spot.castShadows = true;
  spot.position = {-1, 4, 0.5};
  spot.direction = {0, -1, 0};
  return spot;
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

// The instances the frame draws with `program`'s fragment stage.
size_t instancesDrawnWith(const SceneFrame& frame, const ShaderProgram& program) {
  size_t count = 0;
  for (const DrawItem& d : frame.frame().draws)
    count += d.program->fragmentSpirv == program.fragmentSpirv ? d.instances.size() : 0;
  return count;
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
  EXPECT_EQ(instancesDrawnWith(*frame, programOf(dir, "plastic", "high.dir1.sh4")), 3u);  // plane, box, sphere
  EXPECT_EQ(instancesDrawnWith(*frame, programOf(dir, "plastic", "high.dir1")), 1u);
}

// What both backends draw (FrameDraws): the forward draws, then each view's casters in view order,
// the very DrawItems of the frame and of ShadowPassDesc::casters, not copies.
TEST(ShadowFrame, TheBackendsReadTheCastersInPlace) {
  std::string error;
  auto scene = parseScene("s.json", kScene, &error);
  ASSERT_TRUE(scene) << error;
  auto frame = prepared(*scene, packages());
  ASSERT_TRUE(frame);
  const FrameDesc& desc = frame->frame();
  ASSERT_TRUE(desc.shadow);
  ASSERT_EQ(shadowPassError(*desc.shadow, 8192), "");
  const FrameDraws draws(desc);
  EXPECT_EQ(draws.forwardCount(), desc.draws.size());
  ASSERT_EQ(draws.size(), desc.draws.size() + shadowDrawCount(desc));
  size_t i = 0;
  for (; i < desc.draws.size(); ++i) {
    EXPECT_EQ(&draws[i], &desc.draws[i]) << i;
    EXPECT_FALSE(draws.isCaster(i)) << i;
  }
  size_t fromViews = 0;
  for (const ShadowCascadeDesc& view : desc.shadow->cascades)
    for (uint32_t caster : view.casters) {
      EXPECT_EQ(&draws[i], &desc.shadow->casters[caster]) << i;
      EXPECT_TRUE(draws.isCaster(i++));
      ++fromViews;
    }
  EXPECT_GT(fromViews, desc.shadow->casters.size()) << "the ground is drawn into every cascade";
  size_t iterated = 0;
  for (const DrawItem& draw : draws) EXPECT_EQ(&draw, &draws[iterated++]);
  EXPECT_EQ(iterated, draws.size());
  EXPECT_THROW(draws[draws.size()], std::out_of_range);

  FrameDesc unshadowed;
  unshadowed.draws = desc.draws;
  EXPECT_EQ(FrameDraws(unshadowed).size(), desc.draws.size());
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

// A casting spot light (docs/shadows.md, "Spot shadows"): it takes light slot 0, whatever its place
// in the scene, since `.sp1` receivers shadow slot 0; receiving objects draw the `.sp1` variant, the
// others the plain one; its view follows the cascades and the uniforms carry its matrix and normal
// offset. Packages without the spot's receivers are refused with the key.
TEST(ShadowFrame, ACastingSpotLightTakesSlotZeroAndItsReceiversDrawSp1) {
  std::string error;
  auto scene = parseScene("s.json", kScene, &error);
  ASSERT_TRUE(scene) << error;
  PunctualLight point, spot;
  point.position = {3, 2, 1};
  spot.spot = true;
  spot.castShadows = true;
  spot.position = {-1, 4, 0.5};
  spot.direction = glm::normalize(glm::dvec3(0.2, -1, 0));
  spot.outerAngleDegrees = 40;
  scene->lights = {point, spot};
  EXPECT_FALSE(SceneFrame::prepare(*scene, packages(), &error));
  EXPECT_NE(error.find("high.dir1.sh4.pt2.sp1"), std::string::npos) << error;

  const std::string dir = packages("shadow-frame-spot", {0, 4}, {2}, true);
  auto frame = prepared(*scene, dir);
  ASSERT_TRUE(frame);
  const abi::FrameUniforms& f = frame->frame().frame;
  EXPECT_FLOAT_EQ(f.punctualLights[0].positionFalloff[1], 4.0f);  // the spot
  EXPECT_NE(f.punctualLights[0].spotScaleOffset[0], 0.0f);
  EXPECT_FLOAT_EQ(f.punctualLights[1].positionFalloff[0], 3.0f);  // the point light
  EXPECT_EQ(f.punctualLights[1].spotScaleOffset[0], 0.0f);

  ASSERT_TRUE(frame->frame().shadow);
  const ShadowPassDesc& shadow = *frame->frame().shadow;
  ASSERT_EQ(shadow.cascades.size(), 4u);  // 3 cascades, then the spot
  EXPECT_EQ(shadow.spotViews, 1u);
  const ShadowCascadeDesc& view = shadow.cascades[3];
  const SpotShadow fitted =
      fitSpotShadow(*scene, 1, {view.viewport[0], view.viewport[1], view.viewport[2], view.viewport[3]});
  for (int i = 0; i < 16; ++i)
    EXPECT_EQ(shadow.uniforms.spotAtlasFromWorld[i], float(glm::value_ptr(fitted.atlasFromWorld)[i])) << i;
  EXPECT_FLOAT_EQ(shadow.uniforms.spotNormalOffset[0], float(scene->shadows.normalBias * fitted.texelPerMetre));
  EXPECT_EQ(shadow.uniforms.fadeAtlas[2], 1024.0f);

  EXPECT_EQ(instancesDrawnWith(*frame, programOf(dir, "plastic", "high.dir1.sh4.pt2.sp1")), 3u);  // plane, box, sphere
  EXPECT_EQ(instancesDrawnWith(*frame, programOf(dir, "plastic", "high.dir1.pt2")), 1u);
}

// A spot light alone casts: the pass is its view over the whole atlas, and the sun's fields stay 0.
TEST(ShadowFrame, ASpotLightCastsWithoutTheSun) {
  std::string error;
  auto scene = parseScene("s.json", kScene, &error);
  ASSERT_TRUE(scene) << error;
  scene->sun.reset();
  scene->lights = {castingSpotAbove()};
  const std::string dir = packages("shadow-frame-spot-alone", {0}, {1}, true);
  auto frame = prepared(*scene, dir);
  ASSERT_TRUE(frame);
  ASSERT_TRUE(frame->frame().shadow);
  const ShadowPassDesc& shadow = *frame->frame().shadow;
  ASSERT_EQ(shadow.cascades.size(), 1u);
  EXPECT_EQ(std::vector<uint32_t>(shadow.cascades[0].viewport, shadow.cascades[0].viewport + 4),
            (std::vector<uint32_t>{0, 0, 1024, 1024}));
  EXPECT_EQ(shadow.uniforms.fadeAtlas[2], 1024.0f);
  EXPECT_EQ(shadow.uniforms.fadeAtlas[3], 1.0f / 1024);
  EXPECT_EQ(shadow.uniforms.cascadeScale[0][0], 0.0f);
  EXPECT_EQ(shadow.casters.size(), 3u);  // the plane and both boxes; neither sphere casts
}

// "slopeStage": "vertex" (docs/shadows.md, "Bias"): the casters draw with `<tier>.depth.slope`, the
// rasteriser's slope factor is 0, and each view carries the vertex stage's constant and its light:
// slopeBias texels' width along the rays in window depth and the direction to the sun for a
// cascade; slopeBias × texelPerMetre × f·n / (f − n) and the position for the spot. A backend
// writes them into the view's frame block (lightDirection.w doubled on GL). A package without the
// program is refused with its key.
TEST(ShadowFrame, TheVertexSlopeStageDrawsTheCastersWithItsProgramAndConstants) {
  std::string error;
  auto scene = parseScene("s.json", kScene, &error);
  ASSERT_TRUE(scene) << error;
  scene->shadows.slopeStage = SlopeBiasStage::Vertex;
  EXPECT_FALSE(SceneFrame::prepare(*scene, packages(), &error));
  EXPECT_NE(error.find("high.depth.slope"), std::string::npos) << error;

  scene->lights = {castingSpotAbove()};
  const std::string dir = packages("shadow-frame-vertex-slope", {0, 4}, {1}, true, true);
  auto frame = prepared(*scene, dir);
  ASSERT_TRUE(frame);
  ASSERT_TRUE(frame->frame().shadow);
  const ShadowPassDesc& shadow = *frame->frame().shadow;
  const ShaderProgram slope = programOf(dir, "plastic", "high.depth.slope");
  for (const DrawItem& c : shadow.casters) EXPECT_EQ(c.program->vertexSpirv, slope.vertexSpirv);
  ASSERT_EQ(shadow.cascades.size(), 4u);
  const std::vector<CasterBounds> bounds = {
      {{0, 0, 0}, std::sqrt(2.0) * 0.5 * 40}, {{0, 0.5, 0}, std::sqrt(3.0) * 0.5}, {{30, 0.5, -30}, std::sqrt(6.0)}};
  const SunShadowFit fit = fitSunShadow(*scene, bounds);
  const glm::dvec3 toSun = -glm::normalize(scene->sun->direction);
  for (size_t k = 0; k < 3; ++k) {
    const ShadowCascadeDesc& d = shadow.cascades[k];
    const SunCascade& c = fit.cascades[k];
    EXPECT_EQ(d.slopeBias, 0.0f) << k;
    EXPECT_NEAR(d.vertexSlopeBias, 2.5 * c.texelSize / c.depthRange, 1e-6 * d.vertexSlopeBias) << k;
    for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(d.lightAxis[i], float(toSun[i])) << k;
    EXPECT_EQ(std::vector<float>(d.lightPosition, d.lightPosition + 4), std::vector<float>(4, 0.0f)) << k;
  }
  const ShadowCascadeDesc& view = shadow.cascades[3];
  const SpotShadow fitted =
      fitSpotShadow(*scene, 0, {view.viewport[0], view.viewport[1], view.viewport[2], view.viewport[3]});
  const double n = fitted.nearPlane, f = fitted.farPlane;
  EXPECT_EQ(view.slopeBias, 0.0f);
  EXPECT_FLOAT_EQ(view.vertexSlopeBias, float(2.5 * fitted.texelPerMetre * f * n / (f - n)));
  EXPECT_EQ(std::vector<float>(view.lightPosition, view.lightPosition + 4), (std::vector<float>{-1, 4, 0.5, 1}));
  EXPECT_EQ(std::vector<float>(view.lightAxis, view.lightAxis + 3), (std::vector<float>{0, 1, 0}));  // up to it
  // The constant is the window depth of slopeBias texels along the axis at distance z, times z.
  const double z = 3.0;
  EXPECT_NEAR(view.vertexSlopeBias / z, spotDepthBias(fitted, 2.5) * (n + f) / 2 / z, 1e-6 * view.vertexSlopeBias);

  // What a backend writes into a view's frame block.
  abi::FrameUniforms block = frame->frame().frame;
  setVertexSlopeBias(view, 2.0f, &block);
  EXPECT_FLOAT_EQ(block.lightDirection[3], 2 * view.vertexSlopeBias);
  EXPECT_EQ(block.lightDirection[1], 1.0f);
  EXPECT_EQ(std::vector<float>(block.lightColor, block.lightColor + 4), (std::vector<float>{-1, 4, 0.5, 1}));
  abi::FrameUniforms raster = frame->frame().frame;
  setVertexSlopeBias(ShadowCascadeDesc{}, 2.0f, &raster);
  EXPECT_EQ(std::memcmp(&raster, &frame->frame().frame, sizeof raster), 0);
}

}  // namespace
}  // namespace facet::runtime
