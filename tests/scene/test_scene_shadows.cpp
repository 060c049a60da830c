// The scene's shadow settings as the file gives them (docs/shadows.md, docs/scene-format.md
// "shadows"): their defaults, and each wrong value ending in an error at its JSON pointer.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "facet/scene/scene.h"

namespace {

using facet::runtime::parseScene;
using facet::runtime::Scene;

const char* kObject = R"({"material": "m"})";

Scene sceneOf(const std::string& fields) {
  std::string error;
  auto scene = parseScene("s.json", "{" + fields + R"(, "objects": [)" + kObject + "]}", &error);
  EXPECT_TRUE(scene) << error;
  return scene ? *scene : Scene{};
}

std::string errorOf(const std::string& fields) {
  std::string error;
  EXPECT_FALSE(parseScene("s.json", "{" + fields + R"(, "objects": [)" + kObject + "]}", &error))
      << "accepted: " << fields;
  return error;
}

}  // namespace

TEST(SceneShadows, NothingCastsUnlessTheSunSaysSo) {
  EXPECT_EQ(sunShadowCascades(sceneOf(R"("tier": "high")")), 0u);
  EXPECT_EQ(sunShadowCascades(sceneOf(R"("sun": {})")), 0u);
  EXPECT_EQ(sunShadowCascades(sceneOf(R"("sun": {"castShadows": false}, "shadows": {"cascades": 2})")), 0u);
  const Scene s = sceneOf(R"("sun": {"castShadows": true})");
  EXPECT_EQ(sunShadowCascades(s), 4u);
  EXPECT_EQ(s.shadows.atlasSize, 2048u);
  EXPECT_EQ(s.shadows.distance, 60);
  EXPECT_EQ(s.shadows.splitLambda, 0.75);
  EXPECT_TRUE(s.objects.at(0).castShadows);
  EXPECT_TRUE(s.objects.at(0).receiveShadows);
  EXPECT_EQ(s.shadows.slopeStage, facet::runtime::SlopeBiasStage::Raster);
}

TEST(SceneShadows, EverySettingIsRead) {
  const Scene s = sceneOf(R"("sun": {"castShadows": true}, "shadows": {"atlasSize": 1024, "cascades": 3,
      "distance": 25, "splitLambda": 0.5, "depthBias": 0.5, "slopeBias": 3, "normalBias": 1.5})");
  EXPECT_EQ(sunShadowCascades(s), 3u);
  EXPECT_EQ(s.shadows.atlasSize, 1024u);
  EXPECT_EQ(s.shadows.distance, 25);
  EXPECT_EQ(s.shadows.splitLambda, 0.5);
  EXPECT_EQ(s.shadows.depthBias, 0.5);
  EXPECT_EQ(s.shadows.slopeBias, 3);
  EXPECT_EQ(s.shadows.normalBias, 1.5);
  EXPECT_EQ(s.shadows.slopeStage, facet::runtime::SlopeBiasStage::Raster);
  EXPECT_EQ(sceneOf(R"("shadows": {"slopeStage": "vertex"})").shadows.slopeStage,
            facet::runtime::SlopeBiasStage::Vertex);
  EXPECT_EQ(sceneOf(R"("shadows": {"slopeStage": "raster"})").shadows.slopeStage,
            facet::runtime::SlopeBiasStage::Raster);
}

TEST(SceneShadows, ObjectsChooseToCastAndReceive) {
  std::string error;
  auto s = parseScene("s.json", R"({"objects": [{"material": "m", "castShadows": false, "receiveShadows": false}]})",
                      &error);
  ASSERT_TRUE(s) << error;
  EXPECT_FALSE(s->objects[0].castShadows);
  EXPECT_FALSE(s->objects[0].receiveShadows);
  EXPECT_FALSE(parseScene("s.json", R"({"objects": [{"material": "m", "castShadows": 1}]})", &error));
  EXPECT_EQ(error, "s.json: error: /objects/0/castShadows: expected true or false");
}

TEST(SceneShadows, WrongSettingsAreErrorsAtTheirPointer) {
  EXPECT_EQ(errorOf(R"("shadows": {"atlasSize": 3000})"),
            "s.json: error: /shadows/atlasSize: expected a power of two, not 3000");
  EXPECT_EQ(errorOf(R"("shadows": {"atlasSize": 16384})"),
            "s.json: error: /shadows/atlasSize: value 16384 is outside [256.0, 8192.0]");
  EXPECT_EQ(errorOf(R"("shadows": {"atlasSize": 1024.5})"),
            "s.json: error: /shadows/atlasSize: expected a whole number, not 1024.5");
  EXPECT_EQ(errorOf(R"("shadows": {"cascades": 0})"),
            "s.json: error: /shadows/cascades: value 0 is outside [1.0, 4.0]");
  EXPECT_EQ(errorOf(R"("shadows": {"cascades": 5})"),
            "s.json: error: /shadows/cascades: value 5 is outside [1.0, 4.0]");
  EXPECT_EQ(errorOf(R"("shadows": {"distance": -1})"),
            "s.json: error: /shadows/distance: value -1 is outside [0.01, 1000000.0]");
  EXPECT_EQ(errorOf(R"("shadows": {"splitLambda": 1.5})"),
            "s.json: error: /shadows/splitLambda: value 1.5 is outside [0.0, 1.0]");
  EXPECT_EQ(errorOf(R"("shadows": {"normalBias": -0.5})"),
            "s.json: error: /shadows/normalBias: value -0.5 is outside [0.0, 64.0]");
  EXPECT_EQ(errorOf(R"("shadows": {"slopeBias": "2"})"), "s.json: error: /shadows/slopeBias: expected a number");
  EXPECT_EQ(errorOf(R"("shadows": {"slopeStage": "fragment"})"),
            "s.json: error: /shadows/slopeStage: 'fragment' is not one of raster, vertex");
  EXPECT_EQ(errorOf(R"("shadows": {"slopeStage": true})"), "s.json: error: /shadows/slopeStage: expected a string");
  EXPECT_EQ(errorOf(R"("shadows": {"split": 0.5})"), "s.json: error: /shadows/split: unknown key 'split'");
  EXPECT_EQ(errorOf(R"("sun": {"castShadows": "yes"})"), "s.json: error: /sun/castShadows: expected true or false");
}

// JSON has no NaN literal; the reader's own extension or an overflowing number must still not
// become one.
TEST(SceneShadows, NonFiniteNumbersAreRefused) {
  std::string error;
  EXPECT_FALSE(parseScene("s.json", R"({"shadows": {"splitLambda": NaN}, "objects": []})", &error));
  EXPECT_NE(error.find("s.json:1:"), std::string::npos) << error;
  EXPECT_FALSE(parseScene("s.json", R"({"shadows": {"distance": 1e999}, "objects": []})", &error));
  EXPECT_NE(error.find("s.json"), std::string::npos) << error;
}

TEST(SceneShadows, PointLightsDoNotCast) {
  EXPECT_EQ(errorOf(R"("lights": [{"type": "point", "castShadows": true}])"),
            "s.json: error: /lights/0/castShadows: point-light shadows are not supported; only the sun and spot "
            "lights cast shadows");
  EXPECT_EQ(sceneOf(R"("lights": [{"type": "point", "castShadows": false}])").lights.size(), 1u);
  EXPECT_EQ(errorOf(R"("lights": [{"type": "spot", "castShadows": "yes"}])"),
            "s.json: error: /lights/0/castShadows: expected true or false");
}

// One spot light casts at most (kMaxShadowSpotLights): the second is an error at its own pointer,
// whatever lights lie between them.
TEST(SceneShadows, OneSpotLightCasts) {
  const Scene s = sceneOf(R"("lights": [{"type": "point"}, {"type": "spot", "castShadows": false},
                                        {"type": "spot", "castShadows": true}])");
  EXPECT_EQ(facet::runtime::shadowSpotLights(s), std::vector<size_t>{2});
  EXPECT_TRUE(s.lights[2].castShadows);
  EXPECT_FALSE(s.lights[1].castShadows);
  EXPECT_TRUE(facet::runtime::shadowSpotLights(sceneOf(R"("lights": [{"type": "spot"}])")).empty());
  EXPECT_EQ(sceneOf(R"("lights": [{"type": "spot", "castShadows": true, "outerAngle": 60}])").lights.size(), 1u);
  EXPECT_EQ(errorOf(R"("lights": [{"type": "spot", "castShadows": true, "outerAngle": 61}])"),
            "s.json: error: /lights/0/outerAngle: a spot light casting shadows has an outerAngle of at most 60 degrees "
            "(one perspective view)");
  EXPECT_EQ(sceneOf(R"("lights": [{"type": "spot", "outerAngle": 80}])").lights.size(), 1u);
  EXPECT_EQ(errorOf(R"("lights": [{"type": "spot", "castShadows": true}, {"type": "point"},
                                   {"type": "spot", "castShadows": true}])"),
            "s.json: error: /lights/2/castShadows: a scene has at most 1 spot light casting shadows (docs/shadows.md, "
            "\"Spot shadows\")");
}
