// The post pass's effects as a renderer runs them: a backend is created with a post variant
// (VulkanOptions::post / GlOptions::post, from a scene's "post"), the variants give the images
// their effects should, and an effect the runtime does not embed is refused at creation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "facet/render_backend.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/scene_frame.h"
#include "test_support.h"

namespace {

using facet::runtime::FrameResult;
using facet::runtime::PostSettings;

struct Frame {
  std::string packages;
  std::unique_ptr<facet::runtime::SceneFrame> frame;
};

const Frame& sphere() {
  static Frame f = [] {
    Frame out;
    facet::compiler::BuildOptions build;
    build.tiers = {facet::permutations::Tier::High};
    out.packages = facet::test::writeExamplePackages("post-effects-packages", build);
    std::string error;
    auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/sphere.json"), &error);
    EXPECT_TRUE(scene) << error;
    if (scene) out.frame = facet::runtime::SceneFrame::prepare(*scene, out.packages, &error);
    EXPECT_TRUE(out.frame) << error;
    return out;
  }();
  return f;
}

FrameResult renderVulkan(const PostSettings& post) {
  facet::runtime::VulkanOptions options;
  options.validation = true;
  options.post = post;
  std::string error;
  auto backend = facet::runtime::createVulkanBackend(options, &error);
  FrameResult result;
  EXPECT_TRUE(backend) << error;
  if (!backend || !sphere().frame) return result;
  EXPECT_TRUE(backend->render(sphere().frame->frame(), &result, &error)) << error;
  EXPECT_TRUE(backend->validationErrors().empty());
  return result;
}

int maxDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  int worst = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  return worst;
}

}  // namespace

TEST(PostEffects, EachToneCurveGivesItsOwnImage) {
  const FrameResult aces = renderVulkan({"aces", false});
  const FrameResult neutral = renderVulkan({"neutral", false});
  const FrameResult none = renderVulkan({"none", false});
  ASSERT_FALSE(aces.ldr.empty());
  ASSERT_EQ(aces.ldr.size(), neutral.ldr.size());
  EXPECT_GT(maxDifference(aces.ldr, neutral.ldr), 8);
  EXPECT_GT(maxDifference(aces.ldr, none.ldr), 8);
  EXPECT_GT(maxDifference(neutral.ldr, none.ldr), 0);
}

// What the post pass quantises, from the HDR the forward pass wrote: the ACES fit, then sRGB
// encoding, in 8-bit steps (chunks/tonemap_aces.glsl, chunks/srgb.glsl).
double exactEncodedSteps(float hdr) {
  const double x = std::clamp(double(hdr), 0.0, 160.0);
  const double display = std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  const double encoded = display <= 0.0031308 ? display * 12.92 : 1.055 * std::pow(display, 1.0 / 2.4) - 0.055;
  return encoded * 255.0;
}

// Dithering moves a pixel by less than one 8-bit step from the exact value it quantises, and on
// average not at all, where plain rounding is off by the fraction it drops (the flat background of
// the sphere scene is one value, so its rounding error does not average out).
TEST(PostEffects, DitheringKeepsTheMeanOfTheExactValue) {
  const FrameResult plain = renderVulkan({"aces", false});
  const FrameResult dithered = renderVulkan({"aces", true});
  ASSERT_FALSE(plain.ldr.empty());
  ASSERT_EQ(plain.ldr.size(), dithered.ldr.size());
  ASSERT_EQ(plain.hdr.size(), plain.ldr.size());
  EXPECT_LE(maxDifference(plain.ldr, dithered.ldr), 1);
  double plainError = 0, ditheredError = 0, worst = 0;
  size_t channels = 0;
  for (size_t i = 0; i < plain.ldr.size(); ++i) {
    if (i % 4 == 3) continue;
    const double exact = exactEncodedSteps(plain.hdr[i]);
    if (exact < 1 || exact > 254) continue;  // at the ends the target clamps one side of the noise
    plainError += plain.ldr[i] - exact;
    ditheredError += dithered.ldr[i] - exact;
    worst = std::max(worst, std::abs(dithered.ldr[i] - exact));
    ++channels;
  }
  ASSERT_GT(channels, plain.ldr.size() / 4);
  plainError /= double(channels);
  ditheredError /= double(channels);
  EXPECT_LT(worst, 1.5);  // |noise| < 1 step, then rounding
  EXPECT_LT(std::abs(ditheredError), 0.02) << "plain rounding: " << plainError;
  EXPECT_GT(std::abs(plainError), 3 * std::abs(ditheredError));
}

TEST(PostEffects, AnEffectNotBuiltInIsRefusedAtCreation) {
  std::string error;
  facet::runtime::VulkanOptions vk;
  vk.post.toneCurve = "filmic";
  EXPECT_FALSE(facet::runtime::createVulkanBackend(vk, &error));
  EXPECT_NE(error.find("no post variant with tone curve 'filmic' (built in: aces, aces with dithering, neutral"),
            std::string::npos) << error;
  facet::runtime::GlOptions gl;
  gl.post.toneCurve = "filmic";
  EXPECT_FALSE(facet::runtime::createGlBackend(gl, &error));
  EXPECT_NE(error.find("no post variant with tone curve 'filmic'"), std::string::npos) << error;
}

TEST(PostEffects, SceneNamesThePostEffects) {
  std::string error;
  auto scene = facet::runtime::parseScene("s.json", R"({"post": {"toneCurve": "neutral", "dither": true}, "objects": []})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_EQ(scene->post, (PostSettings{"neutral", true}));
  EXPECT_FALSE(facet::runtime::parseScene("s.json", R"({"post": {"toneCurve": "filmic"}, "objects": []})", &error));
  EXPECT_NE(error.find("s.json: error: /post/toneCurve: expected \"aces\", \"neutral\" or \"none\", not 'filmic'"),
            std::string::npos) << error;
  EXPECT_FALSE(facet::runtime::parseScene("s.json", R"({"post": {"dither": 1}, "objects": []})", &error));
  EXPECT_NE(error.find("/post/dither: expected true or false"), std::string::npos) << error;
}
