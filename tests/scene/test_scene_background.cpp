// The scene's "background" (docs/scene-format.md): its default (the environment drawn when the
// scene has one, the flat mean otherwise), each setting read, and each wrong value ending in an
// error at its JSON pointer.
#include <gtest/gtest.h>

#include <string>

#include "facet/scene/scene.h"

namespace {

using facet::runtime::parseScene;
using facet::runtime::Scene;

Scene sceneOf(const std::string& fields) {
  std::string error;
  auto scene = parseScene("s.json", "{" + fields + R"(, "objects": [{"material": "m"}]})", &error);
  EXPECT_TRUE(scene) << error;
  return scene ? *scene : Scene{};
}

std::string errorOf(const std::string& fields) {
  std::string error;
  EXPECT_FALSE(parseScene("s.json", "{" + fields + R"(, "objects": [{"material": "m"}]})", &error))
      << "accepted: " << fields;
  return error;
}

const char* kSky = R"("environment": {"sky": {}})";

}  // namespace

TEST(SceneBackground, TheEnvironmentIsDrawnWhenTheSceneHasOne) {
  EXPECT_FALSE(sceneOf(R"("sky": {"luminance": 1000})").background.environment);
  EXPECT_FALSE(sceneOf(R"("tier": "high")").background.environment);
  const Scene s = sceneOf(kSky);
  EXPECT_TRUE(s.background.environment);
  EXPECT_EQ(s.background.lod, 0);
  EXPECT_EQ(s.background.intensity, 1);
}

TEST(SceneBackground, EverySettingIsRead) {
  const Scene s =
      sceneOf(std::string(kSky) + R"(, "background": {"show": "environment", "lod": 2.5, "intensity": 0.5})");
  EXPECT_TRUE(s.background.environment);
  EXPECT_EQ(s.background.lod, 2.5);
  EXPECT_EQ(s.background.intensity, 0.5);
  EXPECT_FALSE(sceneOf(std::string(kSky) + R"(, "background": {"show": "flat"})").background.environment);
  // A constant sky drawn: the same picture as its flat mean, at the cost of a draw.
  EXPECT_TRUE(sceneOf(R"("sky": {"luminance": 1000}, "background": {"show": "environment"})").background.environment);
}

TEST(SceneBackground, WrongSettingsAreErrorsAtTheirPointer) {
  EXPECT_EQ(errorOf(std::string(kSky) + R"(, "background": {"show": "sky"})"),
            "s.json: error: /background/show: 'sky' is not one of environment, flat");
  EXPECT_EQ(errorOf(std::string(kSky) + R"(, "background": {"lod": 5})"),
            "s.json: error: /background/lod: value 5 is outside [0.0, 4.0]");
  EXPECT_EQ(errorOf(std::string(kSky) + R"(, "background": {"lod": -1})"),
            "s.json: error: /background/lod: value -1 is outside [0.0, 4.0]");
  EXPECT_EQ(errorOf(std::string(kSky) + R"(, "background": {"intensity": 17})"),
            "s.json: error: /background/intensity: value 17 is outside [0.0, 16.0]");
  EXPECT_EQ(errorOf(std::string(kSky) + R"(, "background": {"intensity": "1"})"),
            "s.json: error: /background/intensity: expected a number");
  EXPECT_EQ(errorOf(std::string(kSky) + R"(, "background": {"show": "flat", "lod": 1})"),
            "s.json: error: /background/lod: applies to the environment drawn, not to \"show\": \"flat\"");
  EXPECT_EQ(errorOf(std::string(kSky) + R"(, "background": {"color": [1, 0, 0]})"),
            "s.json: error: /background/color: unknown key 'color'");
  EXPECT_EQ(errorOf(std::string(kSky) + R"(, "background": "environment")"),
            "s.json: error: /background: expected an object");
}
