// The hard cases of a shadow map (docs/shadows.md, "Hard cases"), drawn by the Vulkan and GL shadow
// passes per tier and scored against the ray-cast reference: acne under a grazing sun, peter-panning at
// a contact, a step at a cascade boundary, a thin caster's shadow broken. The scenes are
// tests/data/scenes/shadows/, lit by the sun alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "facet/scene/scene.h"
#include "shadow_frames.h"

namespace facet::runtime {
namespace {

using shadow_frames::Api;
using shadow_frames::Measured;
using shadow_reference::PixelKind;

const char* const kTiers[] = {"reference", "high", "mid", "low"};

struct Bias {
  double depth, slope, normal;
  bool vertex = false;  // the slope bias in the depth-only programs' vertex stage ("slopeStage": "vertex")
};

// The scene in `tier`, with the shadows block's biases and slope stage set when `bias` is given.
std::string inTier(const std::string& json, const std::string& tier, const Bias* bias = nullptr) {
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(json);
  scene["tier"] = tier;
  if (bias) {
    scene["shadows"]["depthBias"] = bias->depth;
    scene["shadows"]["slopeBias"] = bias->slope;
    scene["shadows"]["normalBias"] = bias->normal;
    scene["shadows"]["slopeStage"] = bias->vertex ? "vertex" : "raster";
  }
  return scene.dump();
}

bool isSurface(const Measured& m, size_t i) { return m.reference.pixels[i].kind == PixelKind::Surface; }

// The footprints (docs/shadows.md, "The metric"): the 3×3 tent's reach (1.5 texels) and the normal
// offset (1 texel), 2.5 texels of the coarsest cascade the scored pixels use, rounded up.
// grazing_sun's ground reaches the 60 m shadow distance (cascade 3, 83 mm texels at 2048²);
// contact's ground near the box is in cascade 0 (6 mm); cascade_boundary's strip runs through all
// four.
constexpr double kGrazingFootprint = 0.25;
constexpr double kContactFootprint = 0.02;
constexpr double kBoundaryFootprint = 0.25;
constexpr double kPoleFootprint = 0.02;

// Acne: the lit ground under a sun 3° above the horizon. Every lit pixel the reference scores
// must be lit.
uint64_t grazingAcne(const std::string& tier, const Bias* bias, uint64_t* scored, Api api = Api::Vulkan) {
  const Measured m = shadow_frames::measure(inTier(shadow_frames::sunOnlyScene("grazing_sun.json"), tier, bias),
                                            "grazing-" + tier, kGrazingFootprint, api);
  *scored = m.score.scored;
  return m.score.acne;
}

struct ContactFigures {
  double gap = 0;        // the widest lit gap at the box's foot, in texels
  double nearest = 1e9;  // the scored shadowed pixel nearest the box, in texels: the gap's resolution
  uint64_t leaks = 0;    // every leak of the image, near the box or not
};

// Peter-panning: the widest lit gap between the box's foot and its shadow, in texels of the cascade
// the gap's pixels read: the distance from the box of the farthest pixel rendered lit where the
// reference is in shadow (a leak), among those within kContactReach texels of the box. A gap wider
// than that reach shows as leaks all the way out to it; leaks farther out are not peter-panning
// (they count in `leaks`).
constexpr double kContactReach = 16;
ContactFigures contactGap(const std::string& tier, const Bias* bias, Api api = Api::Vulkan) {
  const std::string json = inTier(shadow_frames::sunOnlyScene("contact.json"), tier, bias);
  const Measured m = shadow_frames::measure(json, "contact-" + tier, kContactFootprint, api);
  ContactFigures out;
  out.leaks = m.score.leaks;
  std::string error;
  const auto scene = parseScene("contact.json", json, &error);
  EXPECT_TRUE(scene) << error;
  if (!scene) return out;
  const SceneObject& box = scene->objects[1];
  const glm::dvec3 half = 0.5 * box.scale * box.radius;
  for (size_t i = 0; i < m.points.size(); ++i) {
    const auto& pixel = m.reference.pixels[i];
    if (pixel.kind != PixelKind::Surface || pixel.object != 0 || pixel.footprint != 0 ||
        std::isnan(m.rendered.values[i]))
      continue;
    const glm::dvec3 local = glm::conjugate(box.rotation) * (m.points[i] - box.position);
    const double texels =
        glm::length(glm::max(glm::abs(local) - half, glm::dvec3(0))) / shadow_frames::texelSizeAt(m, m.points[i]);
    out.nearest = std::min(out.nearest, texels);
    if (texels <= kContactReach && m.rendered.values[i] >= shadow_reference::kLitThreshold)
      out.gap = std::max(out.gap, texels);
  }
  return out;
}

struct BoundaryFigures {
  double worstCascade = 0;  // the largest wrong fraction of one cascade's pixels
  double worstBand = 0;     // the largest wrong fraction of the pixels within 3 % of a split's depth
  uint64_t bandScored = 0, wrong = 0, scored = 0;
  int cascadesSeen = 0;  // cascades with scored pixels (the ground starts 8 m away: past cascade 0)
};

// A cascade boundary: the wrong fraction of each cascade's pixels, and of the band along each split
// (a step shows as wrong pixels gathered at the split). Pixels past 0.9 of the shadow distance are
// left out: the shadow fades there by design, which the reference does not model.
BoundaryFigures cascadeBoundary(const std::string& tier, const Bias* bias, Api api = Api::Vulkan) {
  const std::string json = inTier(shadow_frames::sunOnlyScene("cascade_boundary.json"), tier, bias);
  const Measured m = shadow_frames::measure(json, "boundary-" + tier, kBoundaryFootprint, api);
  const double fadeStart = 0.9 * 60;  // the scene's shadow distance is the default 60 m
  BoundaryFigures out;
  const auto inShadowRange = [&](size_t i) {
    return isSurface(m, i) && shadow_frames::viewDepth(m, m.points[i]) < fadeStart;
  };
  const auto all = shadow_frames::scoreWhere(m, inShadowRange);
  out.wrong = all.wrong;
  out.scored = all.scored;
  for (int c = 0; c < 4; ++c) {
    const auto s = shadow_frames::scoreWhere(
        m, [&](size_t i) { return inShadowRange(i) && shadow_frames::cascadeAt(m, m.points[i]) == c; });
    if (s.scored > 0) ++out.cascadesSeen;
    out.worstCascade = std::max(out.worstCascade, s.wrongFraction());
  }
  for (int split = 0; split < 3; ++split) {
    const double at = m.shadow.splits[split];
    const auto s = shadow_frames::scoreWhere(m, [&](size_t i) {
      return inShadowRange(i) && std::abs(shadow_frames::viewDepth(m, m.points[i]) - at) < 0.03 * at;
    });
    out.bandScored += s.scored;
    out.worstBand = std::max(out.worstBand, s.wrongFraction());
  }
  return out;
}

struct PoleFigures {
  size_t shadowPixels = 0;  // the ground pixels the reference shadows (at the point)
  size_t uncovered = 0;     // of those, with no rendered shadow within one pixel
  size_t pieces = 0;        // 8-connected pieces of the rendered shadow along them
};

// A thin pole's shadow stays connected: each ground pixel the reference shadows has a pixel
// rendered in shadow within one pixel, and the rendered shadow pixels near the reference's form one
// 8-connected piece.
PoleFigures thinPole(const std::string& tier, const Bias* bias, Api api = Api::Vulkan) {
  const Measured m = shadow_frames::measure(inTier(shadow_frames::sunOnlyScene("thin_pole.json"), tier, bias),
                                            "pole-" + tier, kPoleFootprint, api);
  const int w = int(m.reference.width), h = int(m.reference.height);
  const auto at = [&](int x, int y) { return size_t(y) * size_t(w) + size_t(x); };
  const auto shadowedInReference = [&](int x, int y) {
    const auto& p = m.reference.pixels[at(x, y)];
    return p.kind == PixelKind::Surface && p.object == 0 && p.visibility == 0;
  };
  const auto shadowedInRendering = [&](int x, int y) {
    const float v = m.rendered.values[at(x, y)];
    return !std::isnan(v) && v < shadow_reference::kLitThreshold;
  };
  PoleFigures out;
  std::vector<uint8_t> near(m.points.size(), 0);  // rendered shadow pixels within one pixel of the reference's
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!shadowedInReference(x, y)) continue;
      ++out.shadowPixels;
      bool covered = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h || !shadowedInRendering(nx, ny)) continue;
          covered = true;
          near[at(nx, ny)] = 1;
        }
      if (!covered) ++out.uncovered;
    }
  std::vector<size_t> stack;
  for (size_t start = 0; start < near.size(); ++start) {
    if (near[start] != 1) continue;
    ++out.pieces;
    near[start] = 2;
    stack.push_back(start);
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      const int x = int(i % size_t(w)), y = int(i / size_t(w));
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h || near[at(nx, ny)] != 1) continue;
          near[at(nx, ny)] = 2;
          stack.push_back(at(nx, ny));
        }
    }
  }
  return out;
}

// Each case runs on both backends.
class ShadowCases : public testing::TestWithParam<Api> {};

INSTANTIATE_TEST_SUITE_P(Backends, ShadowCases, testing::Values(Api::Vulkan, Api::Gl),
                         [](const testing::TestParamInfo<Api>& param) {
                           return std::string(shadow_frames::apiName(param.param));
                         });

TEST_P(ShadowCases, AGrazingSunLeavesNoAcneOnTheLitGround) {
  for (const char* tier : kTiers) {
    uint64_t scored = 0;
    const uint64_t acne = grazingAcne(tier, nullptr, &scored, GetParam());
    std::printf("%s grazing_sun %-9s scored %llu acne %llu\n", shadow_frames::apiName(GetParam()), tier,
                static_cast<unsigned long long>(scored), static_cast<unsigned long long>(acne));
    ASSERT_GT(scored, 20000u) << tier;
    EXPECT_EQ(acne, 0u) << tier;
  }
}

TEST_P(ShadowCases, AContactShadowStartsWithinTwoTexelsOfItsCaster) {
  for (const char* tier : kTiers) {
    const ContactFigures f = contactGap(tier, nullptr, GetParam());
    std::printf("%s contact %-9s leaks %llu, widest gap %.2f texels, nearest shadowed pixel %.2f texels\n",
                shadow_frames::apiName(GetParam()), tier, static_cast<unsigned long long>(f.leaks), f.gap, f.nearest);
    EXPECT_LT(f.nearest, 1.0) << tier;  // the test sees a gap of a texel
    EXPECT_LE(f.gap, 2.0) << tier;
  }
}

TEST_P(ShadowCases, ACascadeBoundaryShowsNoStep) {
  for (const char* tier : kTiers) {
    const BoundaryFigures f = cascadeBoundary(tier, nullptr, GetParam());
    std::printf(
        "%s cascade_boundary %-9s wrong %llu of %llu, worst cascade %.3f%%, worst split band %.3f%% (%llu scored)\n",
        shadow_frames::apiName(GetParam()), tier, static_cast<unsigned long long>(f.wrong),
        static_cast<unsigned long long>(f.scored), 100 * f.worstCascade, 100 * f.worstBand,
        static_cast<unsigned long long>(f.bandScored));
    EXPECT_GE(f.cascadesSeen, 3) << tier;
    EXPECT_GT(f.bandScored, 1000u) << tier;
    EXPECT_LE(f.worstCascade, 0.005) << tier;
    EXPECT_LE(f.worstBand, 0.005) << tier;
  }
}

TEST_P(ShadowCases, AThinPoleCastsOneUnbrokenShadow) {
  for (const char* tier : kTiers) {
    const PoleFigures f = thinPole(tier, nullptr, GetParam());
    std::printf("%s thin_pole %-9s %zu shadow pixels, %zu uncovered, %zu pieces\n", shadow_frames::apiName(GetParam()),
                tier, f.shadowPixels, f.uncovered, f.pieces);
    ASSERT_GT(f.shadowPixels, 150u) << tier;
    EXPECT_EQ(f.uncovered, 0u) << tier;
    EXPECT_EQ(f.pieces, 1u) << tier;
  }
}

// The slope bias in the depth-only programs' vertex stage ("slopeStage": "vertex", the
// `.depth.slope` programs; docs/shadows.md "Bias") at the default biases: the bounds the raster
// stage meets above, in every case and tier.
TEST_P(ShadowCases, TheVertexStageSlopeBiasMeetsTheSameBoundsAtTheDefaults) {
  const Bias defaults{1, 2, 1, true};
  for (const char* tier : kTiers) {
    uint64_t scored = 0;
    const uint64_t acne = grazingAcne(tier, &defaults, &scored, GetParam());
    const ContactFigures contact = contactGap(tier, &defaults, GetParam());
    const PoleFigures pole = thinPole(tier, &defaults, GetParam());
    std::printf(
        "%s vertex slope bias %-9s acne %llu of %llu, contact gap %.2f texels, pole %zu uncovered, %zu pieces\n",
        shadow_frames::apiName(GetParam()), tier, static_cast<unsigned long long>(acne),
        static_cast<unsigned long long>(scored), contact.gap, pole.uncovered, pole.pieces);
    ASSERT_GT(scored, 20000u) << tier;
    EXPECT_EQ(acne, 0u) << tier;
    EXPECT_LT(contact.nearest, 1.0) << tier;
    EXPECT_LE(contact.gap, 2.0) << tier;
    EXPECT_EQ(pole.uncovered, 0u) << tier;
    EXPECT_EQ(pole.pieces, 1u) << tier;
  }
}

// The defaults pass with a slope bias of 0 too (the normal offset alone removes the acne, "Bias"),
// so the vertex stage's own work shows with the depth bias and normal offset at 0: its slope bias
// alone must remove the acne as the rasteriser's does (low: none of the thousands left unbiased;
// high keeps the 5 pixels the rasteriser's leaves too).
TEST_P(ShadowCases, TheVertexStageSlopeBiasAloneRemovesTheAcneAsTheRasterisersDoes) {
  const Bias raster{0, 2, 0, false};
  const Bias vertex{0, 2, 0, true};
  for (const char* tier : {"high", "low"}) {
    uint64_t scored = 0;
    const uint64_t rasterAcne = grazingAcne(tier, &raster, &scored, GetParam());
    const uint64_t vertexAcne = grazingAcne(tier, &vertex, &scored, GetParam());
    std::printf("%s grazing_sun %-9s at 0, 2, 0: acne %llu raster, %llu vertex\n", shadow_frames::apiName(GetParam()),
                tier, static_cast<unsigned long long>(rasterAcne), static_cast<unsigned long long>(vertexAcne));
    ASSERT_GT(scored, 20000u) << tier;
    EXPECT_LE(vertexAcne, rasterAcne + 5) << tier;
    EXPECT_LE(vertexAcne, 10u) << tier;
  }
}

// The bias sweep of docs/shadows.md, "Bias": every hard case per setting, in high (the 3×3 tent)
// and low (one compare tap), printed as the doc's table, with the slope bias at the rasteriser and,
// from the same build, in the vertex stage. Disabled (a table, not a check): run with
// --gtest_also_run_disabled_tests --gtest_filter='*BiasSweep*' (FACET_SWEEP_API=gl for GL).
TEST(VulkanShadowCases, DISABLED_BiasSweep) {
  const char* apiName = std::getenv("FACET_SWEEP_API");
  const Api api = apiName && std::string(apiName) == "gl" ? Api::Gl : Api::Vulkan;
  const Bias settings[] = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 1}, {0.5, 1, 0.5}, {1, 1, 0.5}, {1, 2, 0},
                           {0, 2, 1}, {1, 0, 1}, {1, 1, 1}, {1, 2, 1}, {2, 2, 1},     {1, 4, 1},   {1, 2, 2},
                           {2, 4, 2}, {4, 4, 2}, {4, 8, 4}, {8, 8, 4}, {16, 16, 8},   {0, 8, 0},   {0, 4, 0}};
  std::printf(
      "| depth, slope, normal | tier | stage | grazing_sun acne | contact leaks, widest gap (texels) | "
      "cascade_boundary wrong, worst band | thin_pole uncovered, pieces |\n|---|---|---|---:|---:|---:|---:|\n");
  for (Bias bias : settings)
    for (const char* tier : {"high", "low"})
      for (bool vertex : {false, true}) {
        bias.vertex = vertex;
        uint64_t scored = 0;
        const uint64_t acne = grazingAcne(tier, &bias, &scored, api);
        const ContactFigures contact = contactGap(tier, &bias, api);
        const BoundaryFigures boundary = cascadeBoundary(tier, &bias, api);
        const PoleFigures pole = thinPole(tier, &bias, api);
        std::printf("| %g, %g, %g | %s | %s | %llu | %llu, %.1f | %llu, %.2f %% | %zu, %zu |\n", bias.depth, bias.slope,
                    bias.normal, tier, vertex ? "vertex" : "raster", static_cast<unsigned long long>(acne),
                    static_cast<unsigned long long>(contact.leaks), contact.gap,
                    static_cast<unsigned long long>(boundary.wrong), 100 * boundary.worstBand, pole.uncovered,
                    pole.pieces);
        std::fflush(stdout);
      }
}

}  // namespace
}  // namespace facet::runtime
