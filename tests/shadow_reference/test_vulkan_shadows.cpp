// The sun's shadow pass on Vulkan (docs/shadows.md, "Shadow pass"), scored against the ray-cast
// reference (shadow_reference/): frames lit by the sun alone, with and without the pass, give the
// rendered visibility as their luminance ratio ("Visibility from the renderer"), and the scored
// pixels' wrong fraction is bounded per tier.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "facet/runtime/png.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/runtime/vulkan_backend.h"
#include "facet/scene/scene.h"
#include "facet/shadow_reference/reference_image.h"
#include "facet/shadow_reference/rendered_visibility.h"
#include "facet/shadow_reference/shadow_score.h"
#include "facet/shadow_reference/sun_visibility.h"
#include "test_compile.h"
#include "test_support.h"

namespace facet::runtime {
namespace {

using shadow_reference::PixelKind;
using shadow_reference::ReferenceImage;
using shadow_reference::RenderedVisibility;

// A 1 m box rotated 20° on a 40 m ground, lit by the sun alone (no sky, no other light).
std::string boxOverPlane(const std::string& tier) {
  return R"({"width": 160, "height": 120, "tier": ")" + tier + R"(",
  "camera": {"position": [2.6, 2.2, 3.6], "target": [0.2, 0.2, 0.2], "fovY": 45},
  "sun": {"direction": [0.7, -0.4, -0.5], "illuminance": 100000, "castShadows": true},
  "sky": {"luminance": 0},
  "shadows": {"atlasSize": 1024, "cascades": 2},
  "objects": [
    {"mesh": "plane", "material": "plastic", "scale": [40, 1, 40]},
    {"mesh": "box", "material": "plastic", "position": [0, 0.5, 0], "rotation": [0, 20, 0]}
  ]})";
}

const std::string& packages() {
  static const std::string dir = [] {
    compiler::BuildOptions options;
    options.shadowCascadeCounts = {0, 1, 2, 4};
    return test::writePackagesFromTexts(
        "vulkan-shadows", {"material plastic { shading lit\n surface { baseColor = vec3(0.7, 0.7, 0.7) } }"}, options);
  }();
  return dir;
}

// The scene as text with the sun's castShadows set.
std::string withSunCasting(const std::string& json, bool casts) {
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(json);
  scene["sun"]["castShadows"] = casts;
  return scene.dump();
}

// The frame's LDR as a PNG in the test's scratch folder.
std::string renderToPng(RenderBackend& backend, const std::string& json, const std::string& name) {
  std::string error;
  auto scene = parseScene(name + ".json", json, &error);
  EXPECT_TRUE(scene) << error;
  if (!scene) return "";
  auto frame = SceneFrame::prepare(*scene, packages(), &error);
  EXPECT_TRUE(frame) << error;
  if (!frame) return "";
  FrameResult result;
  EXPECT_TRUE(backend.render(frame->frame(), &result, &error)) << error;
  EXPECT_TRUE(backend.validationErrors().empty()) << backend.validationErrors().front();
  std::vector<uint8_t> png;
  EXPECT_TRUE(encodePng(result.width, result.height, result.ldr, &png, &error)) << error;
  static const std::string frames = test::scratchDir("vulkan-shadows-frames");
  const std::string path = frames + "/" + name + ".png";
  FILE* file = std::fopen(path.c_str(), "wb");
  EXPECT_NE(file, nullptr) << path;
  if (!file) return "";
  std::fwrite(png.data(), 1, png.size(), file);
  std::fclose(file);
  return path;
}

struct Measured {
  ReferenceImage reference;
  RenderedVisibility rendered;
  shadow_reference::ShadowScore score;
};

// The scene rendered on Vulkan with and without its shadow pass, and the reference over a
// footprint of `footprint` metres.
Measured measure(const std::string& json, const std::string& name, double footprint) {
  Measured out;
  std::string error;
  auto backend = createVulkanBackend({true}, &error);
  EXPECT_TRUE(backend) << error;
  if (!backend) return out;
  const std::string shadowed = renderToPng(*backend, withSunCasting(json, true), name + "-shadowed");
  const std::string unshadowed = renderToPng(*backend, withSunCasting(json, false), name + "-unshadowed");
  auto rendered = shadow_reference::visibilityFromFrames(shadowed, unshadowed, &error);
  EXPECT_TRUE(rendered) << error;
  auto scene = shadow_reference::parseShadowScene(name + ".json", json, &error);
  EXPECT_TRUE(scene) << error;
  if (!rendered || !scene) return out;
  auto sun = shadow_reference::SunVisibility::build(*scene, &error);
  EXPECT_TRUE(sun) << error;
  if (!sun) return out;
  shadow_reference::ReferenceOptions options;
  options.footprintRadius = footprint;
  options.footprintSamples = 16;
  out.reference = renderReference(*scene, *sun, options);
  out.rendered = *rendered;
  auto score = shadow_reference::scoreShadows(out.reference, out.rendered, &error);
  EXPECT_TRUE(score) << error;
  if (score) out.score = *score;
  return out;
}

// Mean rendered visibility over the measurable surface pixels whose footprint is all `visible`.
double meanVisibility(const Measured& m, float visible, size_t* count) {
  double sum = 0;
  *count = 0;
  for (size_t i = 0; i < m.reference.pixels.size(); ++i) {
    const auto& pixel = m.reference.pixels[i];
    if (pixel.kind != PixelKind::Surface || pixel.footprint != visible || std::isnan(m.rendered.values[i])) continue;
    sum += m.rendered.values[i];
    ++*count;
  }
  return *count ? sum / double(*count) : std::nan("");
}

// The footprint: a 3×3 PCF kernel reaches 1.5 texels of the finest cascade; at 1024² with two
// cascades over this view a texel is under 1 cm, so 3 cm covers the kernel and the normal offset.
constexpr double kFootprint = 0.03;

TEST(VulkanShadows, ABoxOverAPlaneMatchesTheRayCastReferencePerTier) {
  // Measured on lavapipe: 0.072 %, 0.066 %, 0.066 % wrong (13, 12, 12 leaks at the box's foot, no
  // acne). The bound leaves 2×, and fails the casters drawn with the wrong winding (their back
  // faces in the atlas: 0.23 % measured) as well as an atlas never drawn (5 %).
  const std::pair<const char*, double> tiers[] = {{"high", 0.0015}, {"mid", 0.0015}, {"low", 0.0015}};
  for (const auto& [tier, bound] : tiers) {
    const Measured m = measure(boxOverPlane(tier), std::string("box-") + tier, kFootprint);
    ASSERT_GT(m.score.scored, 5000u) << tier;
    std::printf("tier %-4s scored %llu wrong %.4f%% (leaks %llu, acne %llu, unmeasured %llu)\n", tier,
                static_cast<unsigned long long>(m.score.scored), 100 * m.score.wrongFraction(),
                static_cast<unsigned long long>(m.score.leaks), static_cast<unsigned long long>(m.score.acne),
                static_cast<unsigned long long>(m.score.unmeasured));
    EXPECT_LE(m.score.wrongFraction(), bound) << tier;
  }
}

// An atlas left at its clear depth (never drawn, or drawn where the receivers do not look)
// shadows nothing: the ratio would be 1 everywhere. The shadowed ground must be as dark as the
// sun's absence makes it, the lit ground as bright as without the pass.
TEST(VulkanShadows, TheShadowedRegionIsDarkAndTheLitRegionIsNot) {
  const Measured m = measure(boxOverPlane("high"), "box-ratio", kFootprint);
  size_t occluded = 0, lit = 0;
  const double inShadow = meanVisibility(m, 0.0f, &occluded);
  const double inLight = meanVisibility(m, 1.0f, &lit);
  std::printf("mean visibility: %.4f over %zu occluded pixels, %.4f over %zu lit pixels\n", inShadow, occluded, inLight,
              lit);
  ASSERT_GT(occluded, 500u);  // 911 measured
  ASSERT_GT(lit, 10000u);
  EXPECT_LT(inShadow, 0.03);  // 0.0145 measured; 0.044 with the casters' back faces drawn
  EXPECT_GT(inLight, 0.98);
}

// A caster behind the camera (tests/data/scenes/shadows/behind_camera.json) still casts into the
// view: the cascades hold casters the camera cannot see.
TEST(VulkanShadows, ACasterBehindTheCameraCasts) {
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(
      test::readText(test::sourceDir() + "/tests/data/scenes/shadows/behind_camera.json"));
  scene["sky"]["luminance"] = 0;  // lit by the sun alone
  for (auto& object : scene["objects"]) {
    object["material"] = "plastic";
    object.erase("params");
  }
  const Measured m = measure(scene.dump(), "behind-camera", kFootprint);
  size_t occluded = 0;
  const double inShadow = meanVisibility(m, 0.0f, &occluded);
  std::printf("behind camera: %zu occluded pixels, mean visibility %.4f; wrong %.4f%% of %llu\n", occluded, inShadow,
              100 * m.score.wrongFraction(), static_cast<unsigned long long>(m.score.scored));
  ASSERT_GT(occluded, 500u);
  EXPECT_LT(inShadow, 0.05);
  EXPECT_LE(m.score.wrongFraction(), 0.005);  // none wrong measured
}

}  // namespace
}  // namespace facet::runtime
