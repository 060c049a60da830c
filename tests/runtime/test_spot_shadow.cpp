// Spot lights' shadow views (runtime/spot_shadow.h) without a GPU: the atlas's cells for cascades
// and spots together, the perspective view fitted to the cone (its edge inside the cell by the
// guard band, near and far from the range, the light's handedness), the receivers' atlasFromWorld
// agreeing with the pass's matrix and viewport in float, the casters the cone keeps, and the
// constant depth bias.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "facet/runtime/shadow_pass.h"
#include "facet/runtime/spot_shadow.h"
#include "facet/runtime/sun_shadow.h"
#include "facet/scene/scene.h"

namespace {

using namespace facet::runtime;

Scene spotScene(const glm::dvec3& direction = {0.3, -1, 0.2}, double outer = 30) {
  Scene s;
  PunctualLight l;
  l.spot = true;
  l.castShadows = true;
  l.position = {1, 4, -2};
  l.direction = glm::normalize(direction);
  l.range = 15;
  l.innerAngleDegrees = outer / 2;
  l.outerAngleDegrees = outer;
  s.lights = {PunctualLight{}, l};  // a point light in slot 0: the spot is light 1
  return s;
}

// Where the shadow pass writes a world point: atlas texel coordinates (x, y) and window depth.
glm::dvec3 passAtlas(const SpotShadow& s, const glm::dvec3& p) {
  const glm::dvec4 clip = s.viewProjection * glm::dvec4(p, 1);
  return {s.viewport[0] + (clip.x / clip.w + 1) / 2 * s.viewport[2],
          s.viewport[1] + (clip.y / clip.w + 1) / 2 * s.viewport[3], (clip.z / clip.w + 1) / 2};
}

// A world point at distance `along` on the spot's axis and angle `angle` (radians) from it, turned
// by `turn` about the axis.
glm::dvec3 conePoint(const SpotShadow& s, double along, double angle, double turn) {
  const glm::dvec3 a = s.axis;
  const glm::dvec3 u = glm::normalize(glm::cross(a, std::abs(a.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)));
  const glm::dvec3 v = glm::cross(a, u);
  return s.position + along * (a + std::tan(angle) * (std::cos(turn) * u + std::sin(turn) * v));
}

}  // namespace

TEST(SpotShadow, AtlasCellsKeepTheSunsLayoutAndAddTheSpots) {
  // The sun alone: one cascade the whole atlas, two to four a 2×2 grid (sun_shadow.h).
  EXPECT_EQ(shadowAtlasCell(2048, 1, 0), (std::array<uint32_t, 4>{0, 0, 2048, 2048}));
  EXPECT_EQ(shadowAtlasCell(2048, 3, 2), (std::array<uint32_t, 4>{0, 1024, 1024, 1024}));
  EXPECT_EQ(shadowAtlasCell(2048, 4, 3), (std::array<uint32_t, 4>{1024, 1024, 1024, 1024}));
  // Four cascades and a spot: a 3×3 grid, the spot in the fifth cell.
  EXPECT_EQ(shadowAtlasCell(2048, 5, 4), (std::array<uint32_t, 4>{682, 682, 682, 682}));
  // Every view inside the atlas, none overlapping another, for 1..4 cascades and a spot.
  for (uint32_t cascades = 0; cascades <= 4; ++cascades) {
    Scene s = spotScene();
    s.shadows.atlasSize = 1024;
    if (cascades > 0) {
      s.sun = Sun{};
      s.sun->castShadows = true;
      s.shadows.cascades = cascades;
    }
    std::vector<std::array<uint32_t, 4>> cells;
    for (const SunCascade& c : fitSunShadow(s, {}).cascades) cells.push_back(c.viewport);
    cells.push_back(shadowAtlasCell(1024, cascades + 1, cascades));
    for (size_t i = 0; i < cells.size(); ++i) {
      EXPECT_LE(cells[i][0] + cells[i][2], 1024u);
      EXPECT_LE(cells[i][1] + cells[i][3], 1024u);
      for (size_t j = 0; j < i; ++j) {
        const bool apart = cells[i][0] >= cells[j][0] + cells[j][2] || cells[j][0] >= cells[i][0] + cells[i][2] ||
                           cells[i][1] >= cells[j][1] + cells[j][3] || cells[j][1] >= cells[i][1] + cells[i][3];
        EXPECT_TRUE(apart) << cascades << " cascades: views " << j << " and " << i << " overlap";
      }
    }
  }
}

// The cone's edge lies the guard band inside the cell's edge, its axis at the cell's centre, the
// near plane at depth 0 and the range at depth 1; and the receivers' matrix, as float, reaches the
// texel and depth the pass writes.
TEST(SpotShadow, TheViewIsFittedToTheCone) {
  for (const glm::dvec3& direction :
       {glm::dvec3(0.3, -1, 0.2), glm::dvec3(0, -1, 0), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1)})
    for (double outer : {5.0, 30.0, 60.0}) {
      const Scene s = spotScene(direction, outer);
      const std::array<uint32_t, 4> cell{512, 0, 512, 512};
      const SpotShadow spot = fitSpotShadow(s, 1, cell);
      EXPECT_EQ(spot.light, 1u);
      EXPECT_EQ(spot.farPlane, 15);
      EXPECT_NEAR(spot.nearPlane, 0.15, 1e-12);
      const double guard = shadowGuardTexels(s.shadows.normalBias, 512);  // 3 texels
      EXPECT_EQ(guard, 3);
      const glm::dvec3 centre = passAtlas(spot, conePoint(spot, 7, 0, 0));
      EXPECT_NEAR(centre.x, 768, 1e-6);
      EXPECT_NEAR(centre.y, 256, 1e-6);
      for (double turn = 0; turn < 6.28; turn += 0.5) {
        // A point on the cone's edge: at most guard texels from the cell's edge, never outside.
        const glm::dvec3 edge = passAtlas(spot, conePoint(spot, 7, glm::radians(outer), turn));
        const double reach = std::max(std::abs(edge.x - 768), std::abs(edge.y - 256));
        EXPECT_LE(reach, 256 - guard + 1e-6) << "outer " << outer << " turn " << turn;
        EXPECT_GE(reach, (256 - guard) * std::sqrt(0.5) - 1e-6);
      }
      EXPECT_NEAR(passAtlas(spot, spot.position + spot.nearPlane * spot.axis).z, 0, 1e-9);
      EXPECT_NEAR(passAtlas(spot, spot.position + spot.farPlane * spot.axis).z, 1, 1e-9);
      EXPECT_NEAR(spot.texelPerMetre, 2 * std::tan(spot.halfAngle) / 512, 1e-15);

      // The receiver: atlasFromWorld as float, the product in float, divided by w (highp).
      const glm::mat4 m(spot.atlasFromWorld);
      std::mt19937 random(7);
      std::uniform_real_distribution<double> unit(0, 1);
      for (int i = 0; i < 200; ++i) {
        const glm::dvec3 p =
            conePoint(spot, 0.5 + 14 * unit(random), glm::radians(outer) * unit(random), 6.283 * unit(random));
        const glm::vec4 h = m * glm::vec4(glm::vec3(p), 1);
        const glm::dvec3 pass = passAtlas(spot, p);
        EXPECT_NEAR(h.x / h.w * 2048, pass.x, 0.02) << i;  // u, v of the default 2048² atlas
        EXPECT_NEAR(h.y / h.w * 2048, pass.y, 0.02) << i;
        EXPECT_NEAR(h.z / h.w, pass.z, 2e-5) << i;  // a D16 step is 1.5e-5
      }
    }
}

// A triangle counter-clockwise seen from the light is counter-clockwise in the atlas's window, as
// one facing the camera is in the frame: the pass culls with the material's faces.
TEST(SpotShadow, TheViewHasTheCamerasHandedness) {
  const SpotShadow spot = fitSpotShadow(spotScene({0, -1, 0}), 1, {0, 0, 256, 256});
  // Seen from above (the light looks down −y), counter-clockwise about +y: a triangle facing up.
  const glm::dvec3 a = passAtlas(spot, {1, 0, -2}), b = passAtlas(spot, {2, 0, -1}), c = passAtlas(spot, {2, 0, -3});
  const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  EXPECT_GT(area, 0);
}

// Every caster whose sphere holds a point of the cone is kept (checked on random spheres against
// random points of the view's cone), and those wholly beside, behind or beyond it are dropped.
TEST(SpotShadow, CastersOutsideTheConeAreCulled) {
  const SpotShadow spot = fitSpotShadow(spotScene({0, -1, 0}, 30), 1, {0, 0, 1024, 1024});
  const glm::dvec3 l = spot.position;
  EXPECT_TRUE(casterInSpotCone(spot, {l + glm::dvec3(0, -3, 0), 0.5}));
  EXPECT_TRUE(casterInSpotCone(spot, {l, 0.1}));                             // around the light
  EXPECT_FALSE(casterInSpotCone(spot, {l + glm::dvec3(0, 2, 0), 1.0}));      // behind it
  EXPECT_FALSE(casterInSpotCone(spot, {l + glm::dvec3(0, -16.5, 0), 1.0}));  // past the range
  EXPECT_TRUE(casterInSpotCone(spot, {l + glm::dvec3(0, -15.5, 0), 1.0}));   // reaching into it
  EXPECT_FALSE(casterInSpotCone(spot, {l + glm::dvec3(3, -3, 0), 0.5}));     // beside (45° off a 30° cone)
  EXPECT_TRUE(casterInSpotCone(spot, {l + glm::dvec3(3, -3, 0), 1.2}));      // beside, reaching its side (1.1 m off)

  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0, 1);
  int kept = 0, dropped = 0;
  for (int i = 0; i < 4000; ++i) {
    const CasterBounds caster{l + glm::dvec3(24 * unit(random) - 12, 24 * unit(random) - 18, 24 * unit(random) - 12),
                              0.1 + 2 * unit(random)};
    const bool in = casterInSpotCone(spot, caster);
    (in ? kept : dropped)++;
    if (in) continue;
    for (int j = 0; j < 200; ++j) {
      const glm::dvec3 p =
          conePoint(spot, spot.farPlane * unit(random), spot.halfAngle * unit(random), 6.283 * unit(random));
      ASSERT_GT(glm::length(p - caster.center), caster.radius) << "a dropped caster holds a point of the cone";
    }
  }
  EXPECT_GT(kept, 200);
  EXPECT_GT(dropped, 200);
}

// The constant bias is depthBias texels' width along the ray at the middle of the range, in window
// depth: a surface moved that far back changes its window depth by the bias.
TEST(SpotShadow, TheDepthBiasIsTexelsAtTheRangesMiddle) {
  const SpotShadow spot = fitSpotShadow(spotScene(), 1, {0, 0, 1024, 1024});
  const double mid = (spot.nearPlane + spot.farPlane) / 2;
  const double width = 2 * spot.texelPerMetre * mid;
  const double moved =
      passAtlas(spot, spot.position + (mid + width) * spot.axis).z - passAtlas(spot, spot.position + mid * spot.axis).z;
  EXPECT_NEAR(spotDepthBias(spot, 2), moved, 0.01 * moved);
}

// The pass a backend draws: the sun's cascades, then the spot's view in the next cell with its
// matrix, its casters (those in its cone) and its biases; a spot alone takes the whole atlas.
TEST(SpotShadow, TheShadowPassHasTheSpotsViewAfterTheCascades) {
  Scene s = spotScene({0, -1, 0}, 30);
  s.shadows.atlasSize = 1024;
  const glm::dvec3 l = s.lights[1].position;
  const std::vector<CasterBounds> bounds{{l + glm::dvec3(0, -3, 0), 0.5}, {l + glm::dvec3(6, -3, 0), 0.5}};
  const ShadowPassDesc alone = shadowPassDesc(s, bounds, std::vector<DrawItem>(2));
  ASSERT_EQ(alone.cascades.size(), 1u);
  EXPECT_EQ(alone.spotViews, 1u);
  EXPECT_EQ(alone.casters.size(), 2u);
  const ShadowCascadeDesc& view = alone.cascades[0];
  EXPECT_EQ(std::vector<uint32_t>(view.viewport, view.viewport + 4), (std::vector<uint32_t>{0, 0, 1024, 1024}));
  EXPECT_EQ(view.casters, std::vector<uint32_t>{0});  // the second caster lies beside the cone
  const SpotShadow spot = fitSpotShadow(s, 1, {0, 0, 1024, 1024});
  for (int i = 0; i < 16; ++i) EXPECT_EQ(view.viewProjection[i], float(glm::value_ptr(spot.viewProjection)[i])) << i;
  EXPECT_FLOAT_EQ(view.depthBias, float(spotDepthBias(spot, s.shadows.depthBias)));
  EXPECT_FLOAT_EQ(view.slopeBias, float(s.shadows.slopeBias));

  s.sun = Sun{};
  s.sun->castShadows = true;
  s.shadows.cascades = 4;
  const ShadowPassDesc both = shadowPassDesc(s, bounds, std::vector<DrawItem>(2));
  ASSERT_EQ(both.cascades.size(), 5u);
  EXPECT_EQ(both.spotViews, 1u);
  EXPECT_EQ(std::vector<uint32_t>(both.cascades[4].viewport, both.cascades[4].viewport + 4),
            (std::vector<uint32_t>{341, 341, 341, 341}));
  EXPECT_EQ(std::vector<uint32_t>(both.cascades[3].viewport, both.cascades[3].viewport + 4),
            (std::vector<uint32_t>{0, 341, 341, 341}));
  EXPECT_EQ(both.cascades[4].casters, std::vector<uint32_t>{0});
  // No spot casting: the sun's pass as before, no spot view.
  s.lights[1].castShadows = false;
  const ShadowPassDesc sun = shadowPassDesc(s, bounds, std::vector<DrawItem>(2));
  EXPECT_EQ(sun.cascades.size(), 4u);
  EXPECT_EQ(sun.spotViews, 0u);
  EXPECT_EQ(sun.cascades[3].viewport[0], 512u);
}
