// The shadow accuracy metric (shadow_score.h), the renderer's visibility read from its images
// (rendered_visibility.h), and facet-measure-shadows: its figures, its determinism, its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include <nlohmann/json.hpp>

#include "facet/runtime/png.h"
#include "facet/shadow_reference/rendered_visibility.h"
#include "facet/shadow_reference/shadow_score.h"
#include "test_support.h"

namespace facet::shadow_reference {
namespace {

ReferencePixel surface(float footprint) { return {PixelKind::Surface, 0, footprint, footprint}; }

TEST(ShadowScore, CountsLeaksAndAcneAmongExactPixelsOnly) {
  ReferenceImage reference{4, 2, {}};
  reference.pixels = {surface(1),
                      surface(1),
                      surface(0),
                      surface(0),  // lit, lit, occluded, occluded
                      surface(0.5f),
                      {PixelKind::Sky, 0, 0, 0},
                      {PixelKind::FacesAway, 0, 0, 0},
                      surface(1)};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // acne, right, leak, right; partial (unscored), sky, faces away, unmeasured
  const RenderedVisibility rendered{4, 2, {0.2f, 0.5f, 0.5f, 0.49f, 0.0f, 1.0f, 1.0f, nan}};
  std::string error;
  std::optional<ShadowScore> s = scoreShadows(reference, rendered, &error);
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->scored, 4u);
  EXPECT_EQ(s->acne, 1u);
  EXPECT_EQ(s->leaks, 1u);
  EXPECT_EQ(s->wrong, 2u);
  EXPECT_EQ(s->unmeasured, 1u);
  EXPECT_DOUBLE_EQ(s->wrongFraction(), 0.5);
  const ReferenceCounts c = countReference(reference);
  EXPECT_EQ(c.lit, 3u);
  EXPECT_EQ(c.occluded, 2u);
  EXPECT_EQ(c.partial, 1u);
  EXPECT_EQ(c.sky, 1u);
  EXPECT_EQ(c.facesAway, 1u);
}

TEST(ShadowScore, SizesMustAgree) {
  ReferenceImage reference{2, 1, {surface(1), surface(0)}};
  std::string error;
  EXPECT_FALSE(scoreShadows(reference, {1, 2, {1, 1}}, &error));
  EXPECT_EQ(error, "the rendered image is 1x2, the scene's 2x1");
}

void writeGrey(const std::string& path, const std::vector<uint8_t>& values, uint32_t width) {
  std::vector<uint8_t> rgba;
  for (uint8_t v : values) rgba.insert(rgba.end(), {v, v, v, 255});
  std::string error;
  ASSERT_TRUE(runtime::writePng(path, width, uint32_t(values.size() / width), rgba, &error)) << error;
}

TEST(RenderedVisibility, FromFramesIsTheLuminanceRatioAndDarkPixelsAreUnmeasured) {
  const std::string dir = test::scratchDir("rendered-visibility");
  // sRGB 188 is linear 0.5029 of 255's 1.0; 8 is below the measurable luminance.
  writeGrey(dir + "/shadowed.png", {188, 0, 255, 4}, 4);
  writeGrey(dir + "/unshadowed.png", {255, 200, 255, 8}, 4);
  std::string error;
  std::optional<RenderedVisibility> v = visibilityFromFrames(dir + "/shadowed.png", dir + "/unshadowed.png", &error);
  ASSERT_TRUE(v) << error;
  ASSERT_EQ(v->values.size(), 4u);
  EXPECT_NEAR(v->values[0], 0.5029, 1e-4);
  EXPECT_EQ(v->values[1], 0);
  EXPECT_EQ(v->values[2], 1);
  EXPECT_TRUE(std::isnan(v->values[3]));
  writeGrey(dir + "/small.png", {255, 255}, 2);
  EXPECT_FALSE(visibilityFromFrames(dir + "/shadowed.png", dir + "/small.png", &error));
  EXPECT_EQ(error, dir + "/small.png: 2x1, but " + dir + "/shadowed.png is 4x1");
  std::optional<RenderedVisibility> image = visibilityFromImage(dir + "/shadowed.png", &error);
  ASSERT_TRUE(image) << error;
  EXPECT_EQ(image->values, (std::vector<float>{188 / 255.0f, 0, 1, 4 / 255.0f}));
}

std::string tool() { return facet::test::binaryDir() + "/shadow_reference/facet-measure-shadows"; }
std::string scene(const std::string& name) {
  return test::sourceDir() + "/tests/data/scenes/shadows/" + name + ".json";
}

// The tool on a hard case: the reference image, its counts, and a rendering scored against it.
// The reference scored against itself (as a visibility image) has no wrong pixel; with its
// shadow painted over (all white) every occluded pixel is a leak.
TEST(MeasureShadows, ScoresARenderingAgainstTheReference) {
  const std::string dir = test::scratchDir("measure-shadows");
  test::CommandResult r = test::run(tool() + " " + scene("thin_pole") + " --footprint 0.02 --samples 8 --reference " +
                                    dir + "/ref.png --json " + dir + "/ref.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json figures = nlohmann::json::parse(test::readText(dir + "/ref.json"));
  const uint64_t occluded = figures["reference"]["occluded"], lit = figures["reference"]["lit"];
  EXPECT_GT(occluded, 50u);
  EXPECT_GT(figures["reference"]["partial"].get<uint64_t>(), 0u);
  EXPECT_NE(r.out.find("| " + std::to_string(lit) + " | " + std::to_string(occluded) + " |"), std::string::npos)
      << r.out;

  r = test::run(tool() + " " + scene("thin_pole") + " --footprint 0.02 --samples 8 --visibility " + dir +
                "/ref.png --json " + dir + "/self.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json score = nlohmann::json::parse(test::readText(dir + "/self.json"))["score"];
  EXPECT_EQ(score["wrong"], 0);
  EXPECT_EQ(score["scored"], lit + occluded);

  writeGrey(dir + "/white.png", std::vector<uint8_t>(256 * 256, 255), 256);
  r = test::run(tool() + " " + scene("thin_pole") + " --footprint 0.02 --samples 8 --shadowed " + dir +
                "/white.png --unshadowed " + dir + "/white.png --json " + dir + "/white.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  score = nlohmann::json::parse(test::readText(dir + "/white.json"))["score"];
  EXPECT_EQ(score["leaks"], occluded);
  EXPECT_EQ(score["acne"], 0);

  // Deterministic: the same bytes again.
  const std::string first = test::readText(dir + "/ref.json");
  r = test::run(tool() + " " + scene("thin_pole") + " --footprint 0.02 --samples 8 --reference " + dir +
                "/ref2.png --json " + dir + "/ref.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(test::readText(dir + "/ref.json"), first);
  EXPECT_EQ(test::readText(dir + "/ref2.png"), test::readText(dir + "/ref.png"));
}

// A spot light's reference (--spot N): the box's shadow on the ground, and the ground outside the
// cone unreached (counted with the faces turned away).
TEST(MeasureShadows, ASpotLightsReference) {
  const std::string dir = test::scratchDir("measure-spot-shadows");
  const test::CommandResult r = test::run(tool() + " " + scene("spot_box") + " --spot 0 --json " + dir + "/spot.json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json counts = nlohmann::json::parse(test::readText(dir + "/spot.json"))["reference"];
  EXPECT_GT(counts["occluded"].get<uint64_t>(), 2000u);
  EXPECT_GT(counts["lit"].get<uint64_t>(), 10000u);
  EXPECT_GT(counts["facesAway"].get<uint64_t>(), 10000u);
}

TEST(MeasureShadows, BadInputsExitWithAMessageAndWriteNothing) {
  const std::string dir = test::scratchDir("measure-shadows-errors");
  writeGrey(dir + "/small.png", {255, 255}, 2);
  std::filesystem::create_directories(dir + "/scenes");
  test::run("printf '{\"objects\": [{\"material\": \"m\"}]}' > " + dir + "/scenes/sunless.json");
  test::run("printf '{\"sun\": {\"castShadows\": 2}, \"objects\": []}' > " + dir + "/scenes/flag.json");
  struct Case {
    std::string arguments, message;
    int exitCode;
  };
  const Case cases[] = {
      {dir + "/missing.json", dir + "/missing.json: error: cannot open the scene file: no such file", 1},
      {dir + "/scenes/sunless.json", dir + "/scenes/sunless.json: error: the scene has no sun to cast shadows", 1},
      {dir + "/scenes/flag.json", dir + "/scenes/flag.json: error: /sun/castShadows: expected true or false", 1},
      {scene("thin_pole") + " --visibility " + dir + "/small.png",
       dir + "/small.png: error: the rendered image is 2x1, the scene's 256x256", 1},
      {scene("thin_pole") + " --visibility " + dir + "/none.png",
       "facet-measure-shadows: error: " + dir + "/none.png: cannot read image: no such file", 1},
      {scene("thin_pole") + " --shadowed " + dir + "/small.png", "", 2},
      {scene("thin_pole") + " --footprint -1", "", 2},
      {scene("thin_pole") + " --footprint nan", "", 2},
      {scene("spot_box"), scene("spot_box") + ": error: the scene has no sun to cast shadows", 1},
      {scene("spot_box") + " --spot 1", scene("spot_box") + ": error: the scene has no spot light 1 to cast shadows",
       1},
      {scene("thin_pole") + " --spot 0", scene("thin_pole") + ": error: the scene has no spot light 0 to cast shadows",
       1},
      {scene("spot_box") + " --spot -1", "", 2},
      {scene("thin_pole") + " --reference " + scene("thin_pole"), "", 1},  // an output over an input
  };
  for (const Case& c : cases) {
    const test::CommandResult r = test::run(tool() + " " + c.arguments + " --json " + dir + "/out.json");
    EXPECT_EQ(r.exitCode, c.exitCode) << c.arguments << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.json")) << c.arguments;
  }
}

}  // namespace
}  // namespace facet::shadow_reference
