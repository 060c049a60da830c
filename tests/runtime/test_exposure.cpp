// Physical camera exposure: lights are pre-exposed on the CPU (docs/lighting-units.md), so a
// scene lit 110 000 times more brightly, seen through a camera that lets in 110 000 times less
// light, is the same image. This pins the contract that keeps every shader value O(1) in fp16:
// nothing downstream of the exposure may depend on the absolute scale of the lights.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "facet/runtime/exposure.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/scene/scene.h"
#include "test_compile.h"

namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// A sun, a point light and a sky, all `scale` times the bright values, seen by `camera`.
std::string sceneJson(double scale, const std::string& camera) {
  return R"({"width": 64, "height": 64, "camera": {"position": [0, 0.5, 4], )" + camera + R"(},
    "sun": {"direction": [-0.4, -0.7, -0.6], "illuminance": )" +
         number(110000 * scale) + R"(},
    "lights": [{"type": "point", "position": [1.5, 1, 2], "intensity": )" +
         number(2e6 * scale) + R"(, "range": 10}],
    "sky": {"luminance": )" +
         number(8000 * scale) + R"(},
    "objects": [{"material": "red_plastic", "position": [-0.6, 0, 0], "radius": 0.6},
                {"material": "brushed_gold", "position": [0.7, 0, 0], "radius": 0.6}]})";
}

facet::runtime::FrameResult render(const std::string& json, const std::string& packages) {
  std::string error;
  auto scene = facet::runtime::parseScene("exposure.json", json, &error);
  EXPECT_TRUE(scene) << error;
  if (!scene) return {};
  auto frame = facet::runtime::SceneFrame::prepare(*scene, packages, &error);
  EXPECT_TRUE(frame) << error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  EXPECT_TRUE(vk) << error;
  facet::runtime::FrameResult result;
  if (!frame || !vk) return result;
  EXPECT_TRUE(vk->render(frame->frame(), &result, &error)) << error;
  EXPECT_TRUE(vk->validationErrors().empty());
  return result;
}

}  // namespace

TEST(Exposure, A110000LuxSunAndA1LuxSunWithAMatchedCameraGiveTheSameImage) {
  facet::compiler::BuildOptions build;
  build.tiers = {facet::permutations::Tier::High};
  build.pointLightCounts = {1};
  const std::string packages = facet::test::writeExamplePackages("exposure-packages", build);
  // Daylight: f/16, 1/125 s, ISO 100 (the "sunny 16" rule), EV100 ≈ 14.97.
  const auto bright = render(sceneJson(1.0, R"("aperture": 16, "shutter": 0.008, "iso": 100)"), packages);
  // The same scene at 1/110 000 of the light: a 1 lux sun. f/1, ISO 100 and the shutter that
  // lowers EV100 by log2(110 000) ≈ 16.75 give an exposure 110 000 times larger.
  const double ev = facet::runtime::ev100(16, 0.008, 100) - std::log2(110000.0);
  const double shutter = 1.0 / std::exp2(ev);  // EV100 = log2(N² / t) at f/1, ISO 100
  ASSERT_GT(shutter, 1.0);
  ASSERT_LT(shutter, 60.0);
  const auto dim =
      render(sceneJson(1.0 / 110000, R"("aperture": 1, "shutter": )" + number(shutter) + R"(, "iso": 100)"), packages);
  ASSERT_EQ(bright.ldr.size(), dim.ldr.size());
  ASSERT_FALSE(bright.ldr.empty());
  int maxDifference = 0;
  size_t lit = 0;
  for (size_t i = 0; i < bright.ldr.size(); ++i) {
    maxDifference = std::max(maxDifference, std::abs(int(bright.ldr[i]) - int(dim.ldr[i])));
    lit += (i % 4 != 3 && bright.ldr[i] > 32) ? 1 : 0;
  }
  EXPECT_LE(maxDifference, 1) << "the images differ by more than one 8-bit step";
  EXPECT_GT(lit, bright.ldr.size() / 8) << "the scene is too dark to show a difference";
  // Pre-exposed HDR values agree to fp16 rounding (2^-11 relative).
  ASSERT_EQ(bright.hdr.size(), dim.hdr.size());
  double worst = 0;
  for (size_t i = 0; i < bright.hdr.size(); ++i)
    if (i % 4 != 3 && bright.hdr[i] > 1e-3f)
      worst = std::max(worst, std::abs(double(dim.hdr[i]) / double(bright.hdr[i]) - 1.0));
  EXPECT_LT(worst, 2.0 * std::exp2(-11.0));
}
