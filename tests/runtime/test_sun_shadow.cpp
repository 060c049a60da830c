// The sun's cascade fitting (runtime/sun_shadow.h) without a GPU: the shadow pass's matrices and
// the receivers' uniforms agree texel for texel (the receiver shaders' arithmetic replayed here in
// double), the splits follow the practical scheme, the cascades do not shimmer as the camera moves
// or change size as it turns, casters behind the camera still cast, and degenerate suns, cameras
// and settings give finite numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "facet/runtime/sun_shadow.h"
#include "facet/scene/scene.h"

namespace {

using namespace facet::runtime;

Scene sunScene(uint32_t cascades = 4) {
  Scene s;
  s.width = 640;
  s.height = 360;
  s.camera.position = {3, 2, 10};
  s.camera.target = {0, 0.5, 0};
  s.sun = Sun{};
  s.sun->direction = glm::normalize(glm::dvec3(-0.4, -0.7, -0.6));
  s.sun->castShadows = true;
  s.shadows.cascades = cascades;
  return s;
}

// A world point at view depth `depth`, (sx, sy) in [−1, 1] across the view (the frustum's edges at ±1).
glm::dvec3 viewPoint(const Scene& s, double depth, double sx, double sy) {
  const glm::dmat4 view = glm::lookAt(s.camera.position, s.camera.target, s.camera.up);
  const double t = std::tan(glm::radians(s.camera.fovYDegrees) / 2);
  const double aspect = double(s.width) / s.height;
  return glm::dvec3(glm::inverse(view) * glm::dvec4(sx * depth * t * aspect, sy * depth * t, -depth, 1));
}

// Where the shadow pass writes a world point: atlas texel coordinates (x, y) and window depth.
glm::dvec3 passAtlas(const SunCascade& c, const glm::dvec3& p) {
  const glm::dvec4 clip = c.viewProjection * glm::dvec4(p, 1);
  return {c.viewport[0] + (clip.x / clip.w + 1) / 2 * c.viewport[2],
          c.viewport[1] + (clip.y / clip.w + 1) / 2 * c.viewport[3], (clip.z / clip.w + 1) / 2};
}

glm::dvec4 vec(const float v[4]) { return {v[0], v[1], v[2], v[3]}; }

// chunks/shadow_cascade.glsl's shadow_select: a chain of mix over step(splits, d); receivers of 3
// cascades are the 4-cascade variant.
glm::dvec4 shadowSelect(const facet::abi::ShadowUniforms& u, uint32_t cascades, double d, const float (*c)[4]) {
  if (cascades == 1) return vec(c[0]);
  const glm::dvec4 passed = glm::step(vec(u.splits), glm::dvec4(d));
  glm::dvec4 value = glm::mix(vec(c[0]), vec(c[1]), passed.x);
  if (cascades > 2) {
    value = glm::mix(value, vec(c[2]), passed.y);
    value = glm::mix(value, vec(c[3]), passed.z);
  }
  return value;
}

// The receiver's lookup (templates/forward.vert.glsl, chunks/shadow_sun.glsl) for a world point
// whose normal offset is 0: the atlas coordinate in texels and the compare depth, from the
// uniforms' float values.
glm::dvec3 shaderAtlas(const facet::abi::ShadowUniforms& u, uint32_t cascades, const glm::dvec3& cameraPosition,
                       const glm::dvec3& p) {
  const float* m = u.lightView;
  const glm::dvec3 light(m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12], m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
                         m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]);
  const double d = glm::dot(p - cameraPosition, glm::dvec3(vec(u.cameraForward)));
  const glm::dvec4 scale = shadowSelect(u, cascades, d, u.cascadeScale);
  const glm::dvec4 offset = shadowSelect(u, cascades, d, u.cascadeOffset);
  const glm::dvec3 atlas = light * glm::dvec3(scale) + glm::dvec3(offset);
  return {atlas.x * u.fadeAtlas[2], atlas.y * u.fadeAtlas[2], atlas.z};
}

bool finite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

void expectFinite(const SunShadowFit& fit) {
  const auto* floats = reinterpret_cast<const float*>(&fit.uniforms);
  for (size_t i = 0; i < sizeof(fit.uniforms) / sizeof(float); ++i) EXPECT_TRUE(std::isfinite(floats[i])) << i;
  for (const SunCascade& c : fit.cascades) {
    EXPECT_TRUE(finite(c.viewProjection));
    EXPECT_TRUE(std::isfinite(c.radius) && c.radius > 0);
    EXPECT_TRUE(std::isfinite(c.texelSize) && c.texelSize > 0);
    EXPECT_TRUE(std::isfinite(c.depthRange) && c.depthRange > 0);
    EXPECT_TRUE(std::isfinite(c.center.x) && std::isfinite(c.center.y) && std::isfinite(c.center.z));
  }
}

// Every cascade's slice, sampled: points the pass writes and the receivers read at the same texel
// and depth, inside the cascade's viewport and depth range.
void expectPassAndReceiversAgree(const Scene& s) {
  const SunShadowFit fit = fitSunShadow(s, {});
  ASSERT_EQ(fit.cascades.size(), s.shadows.cascades);
  expectFinite(fit);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> across(-1, 1), along(0.02, 0.98);
  for (size_t i = 0; i < fit.cascades.size(); ++i) {
    const SunCascade& c = fit.cascades[i];
    for (int k = 0; k < 200; ++k) {
      const double depth = c.splitNear + (c.splitFar - c.splitNear) * along(random);
      const glm::dvec3 p = viewPoint(s, depth, across(random), across(random));
      const glm::dvec3 pass = passAtlas(c, p);
      const glm::dvec3 shader = shaderAtlas(fit.uniforms, s.shadows.cascades, s.camera.position, p);
      EXPECT_NEAR(pass.x, shader.x, 0.01) << "cascade " << i;
      EXPECT_NEAR(pass.y, shader.y, 0.01) << "cascade " << i;
      EXPECT_NEAR(pass.z, shader.z, 1e-5) << "cascade " << i;
      EXPECT_GE(pass.x, c.viewport[0]);
      EXPECT_LE(pass.x, c.viewport[0] + c.viewport[2]);
      EXPECT_GE(pass.y, c.viewport[1]);
      EXPECT_LE(pass.y, c.viewport[1] + c.viewport[3]);
      EXPECT_GE(pass.z, 0);
      EXPECT_LE(pass.z, 1);
    }
  }
}

TEST(SunShadow, PassAndReceiversMapAWorldPointToTheSameTexelAndDepth) {
  for (uint32_t cascades = 1; cascades <= 4; ++cascades) {
    SCOPED_TRACE(cascades);
    expectPassAndReceiversAgree(sunScene(cascades));
  }
}

TEST(SunShadow, AtlasLayoutIsTheWholeAtlasOrAGridOfHalfSizeSquares) {
  const SunShadowFit one = fitSunShadow(sunScene(1), {});
  EXPECT_EQ(one.cascades[0].viewport, (std::array<uint32_t, 4>{0, 0, 2048, 2048}));
  const SunShadowFit four = fitSunShadow(sunScene(4), {});
  EXPECT_EQ(four.cascades[0].viewport, (std::array<uint32_t, 4>{0, 0, 1024, 1024}));
  EXPECT_EQ(four.cascades[1].viewport, (std::array<uint32_t, 4>{1024, 0, 1024, 1024}));
  EXPECT_EQ(four.cascades[2].viewport, (std::array<uint32_t, 4>{0, 1024, 1024, 1024}));
  EXPECT_EQ(four.cascades[3].viewport, (std::array<uint32_t, 4>{1024, 1024, 1024, 1024}));
  EXPECT_EQ(four.uniforms.fadeAtlas[2], 2048.0f);
  EXPECT_EQ(four.uniforms.fadeAtlas[3], 1.0f / 2048);
}

// The shadow pass culls and biases faces by their winding as the forward pass does: a triangle
// facing the sun is counter-clockwise in the atlas, as one facing the camera is in the frame.
TEST(SunShadow, CascadesHaveTheCamerasHandedness) {
  const Scene s = sunScene();
  auto windowArea = [](const glm::dmat4& viewProjection, const glm::dvec3& p0, const glm::dvec3& p1,
                       const glm::dvec3& p2) {
    glm::dvec2 w[3];
    const glm::dvec3 p[3] = {p0, p1, p2};
    for (int k = 0; k < 3; ++k) {
      const glm::dvec4 clip = viewProjection * glm::dvec4(p[k], 1);
      w[k] = glm::dvec2(clip) / clip.w;
    }
    return (w[1].x - w[0].x) * (w[2].y - w[0].y) - (w[2].x - w[0].x) * (w[1].y - w[0].y);
  };
  // (a, b, towards the viewer) right-handed: the triangle p, p + a, p + b faces the viewer.
  auto facing = [](const glm::dvec3& towardsViewer) {
    const glm::dvec3 a = glm::normalize(glm::cross(towardsViewer, glm::dvec3(0.3, 1, 0.2)));
    return std::pair{a, glm::cross(towardsViewer, a)};
  };
  const glm::dmat4 camera = glm::perspective(glm::radians(s.camera.fovYDegrees), double(s.width) / s.height,
                                             s.camera.nearPlane, s.camera.farPlane) *
                            glm::lookAt(s.camera.position, s.camera.target, s.camera.up);
  const glm::dvec3 target = s.camera.target;
  const auto [ca, cb] = facing(glm::normalize(s.camera.position - target));
  EXPECT_GT(windowArea(camera, target, target + ca, target + cb), 0);
  const auto [sa, sb] = facing(-s.sun->direction);
  for (const SunCascade& c : fitSunShadow(s, {}).cascades)
    EXPECT_GT(windowArea(c.viewProjection, c.center, c.center + sa, c.center + sb), 0);
}

TEST(SunShadow, SplitsFollowThePracticalSchemeAndEndAtTheDistance) {
  for (double lambda : {0.0, 0.5, 0.75, 1.0}) {
    for (uint32_t cascades = 1; cascades <= 4; ++cascades) {
      Scene s = sunScene(cascades);
      s.shadows.splitLambda = lambda;
      const SunShadowFit fit = fitSunShadow(s, {});
      ASSERT_EQ(fit.cascades.size(), cascades);
      EXPECT_DOUBLE_EQ(fit.cascades.front().splitNear, s.camera.nearPlane);
      EXPECT_DOUBLE_EQ(fit.cascades.back().splitFar, s.shadows.distance);
      for (uint32_t i = 0; i < cascades; ++i) {
        const SunCascade& c = fit.cascades[i];
        EXPECT_LT(c.splitNear, c.splitFar);
        if (i > 0) {
          EXPECT_DOUBLE_EQ(c.splitNear, fit.cascades[i - 1].splitFar);
        }
        // Zhang et al.'s practical split, λ between logarithmic and uniform.
        const double n = s.camera.nearPlane, f = s.shadows.distance, x = double(i + 1) / cascades;
        EXPECT_NEAR(c.splitFar, lambda * n * std::pow(f / n, x) + (1 - lambda) * (n + (f - n) * x), 1e-9);
        EXPECT_FLOAT_EQ(fit.uniforms.splits[i], float(c.splitFar));
      }
      for (uint32_t i = cascades; i < 4; ++i) {
        EXPECT_EQ(fit.uniforms.splits[i], fit.uniforms.splits[cascades - 1]);
        for (int k = 0; k < 4; ++k) {
          EXPECT_EQ(fit.uniforms.cascadeScale[i][k], fit.uniforms.cascadeScale[cascades - 1][k]);
          EXPECT_EQ(fit.uniforms.cascadeOffset[i][k], fit.uniforms.cascadeOffset[cascades - 1][k]);
        }
      }
    }
  }
  // Past the far plane nothing is drawn: the cascades end there.
  Scene s = sunScene();
  s.camera.farPlane = 40;
  EXPECT_DOUBLE_EQ(fitSunShadow(s, {}).cascades.back().splitFar, 40);
}

TEST(SunShadow, UniformsCarryTheNormalOffsetForwardAndFade) {
  Scene s = sunScene();
  s.shadows.normalBias = 1.5;
  const SunShadowFit fit = fitSunShadow(s, {});
  for (size_t i = 0; i < 4; ++i)
    EXPECT_FLOAT_EQ(fit.uniforms.cascadeScale[i][3], float(1.5 * fit.cascades[i].texelSize));
  const glm::dvec3 forward = glm::normalize(s.camera.target - s.camera.position);
  EXPECT_FLOAT_EQ(fit.uniforms.cameraForward[0], float(forward.x));
  EXPECT_FLOAT_EQ(fit.uniforms.cameraForward[1], float(forward.y));
  EXPECT_FLOAT_EQ(fit.uniforms.cameraForward[2], float(forward.z));
  // The shader's fade, clamp(d·x + y, 0, 1): 0 (full shadow) up to 90 % of the distance, 1 at it.
  auto fade = [&](double d) { return std::clamp(d * fit.uniforms.fadeAtlas[0] + fit.uniforms.fadeAtlas[1], 0.0, 1.0); };
  EXPECT_EQ(fade(0.5 * s.shadows.distance), 0.0);
  EXPECT_NEAR(fade(0.9 * s.shadows.distance), 0.0, 1e-6);
  EXPECT_NEAR(fade(0.95 * s.shadows.distance), 0.5, 1e-6);
  EXPECT_NEAR(fade(s.shadows.distance), 1.0, 1e-6);
}

// Moving the camera by a tenth of a cascade's texel, again and again, moves that cascade's image
// of a fixed world point by whole texels: its texel grid is fixed in the world.
TEST(SunShadow, CameraMovesShiftEveryCascadeByWholeTexels) {
  const Scene start = sunScene();
  const SunShadowFit first = fitSunShadow(start, {});
  for (size_t i = 0; i < first.cascades.size(); ++i) {
    const SunCascade& c0 = first.cascades[i];
    const glm::dvec3 fixedPoint = viewPoint(start, 0.5 * (c0.splitNear + c0.splitFar), 0.3, -0.2);
    const glm::dvec3 at0 = passAtlas(c0, fixedPoint);
    for (int axis = 0; axis < 3; ++axis) {
      glm::dvec3 step(0);
      step[axis] = c0.texelSize / 10;
      for (int k = 1; k <= 30; ++k) {
        Scene moved = start;
        moved.camera.position += double(k) * step;
        moved.camera.target += double(k) * step;
        const SunCascade c = fitSunShadow(moved, {}).cascades[i];
        EXPECT_DOUBLE_EQ(c.radius, c0.radius);
        const glm::dvec3 at = passAtlas(c, fixedPoint);
        for (int a = 0; a < 2; ++a) {
          const double shift = at[a] - at0[a];
          EXPECT_NEAR(shift, std::round(shift), 1e-6) << "cascade " << i << " axis " << axis << " move " << k;
          EXPECT_LE(std::abs(std::round(shift)), 4.0);
        }
      }
    }
  }
}

TEST(SunShadow, TurningTheCameraKeepsEveryCascadesSize) {
  const Scene start = sunScene();
  const SunShadowFit first = fitSunShadow(start, {});
  for (double yaw : {0.3, 1.2, 2.5, -2.0})
    for (double pitch : {-1.2, -0.4, 0.0, 0.7}) {
      Scene turned = start;
      const glm::dvec3 direction(std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw));
      turned.camera.target = turned.camera.position + 7.0 * direction;
      const SunShadowFit fit = fitSunShadow(turned, {});
      for (size_t i = 0; i < fit.cascades.size(); ++i) {
        EXPECT_NEAR(fit.cascades[i].radius, first.cascades[i].radius, 1e-12 * first.cascades[i].radius);
        EXPECT_NEAR(fit.cascades[i].texelSize, first.cascades[i].texelSize, 1e-12 * first.cascades[i].texelSize);
      }
    }
}

// tests/data/scenes/shadows/behind_camera.json: a 3 m box 2 m behind the camera whose shadow
// reaches into the view. Its sphere lies inside the first cascade's depth range, where the fit
// without it does not reach.
TEST(SunShadow, ACasterBehindTheCameraStillCasts) {
  Scene s = sunScene();
  s.width = s.height = 256;
  s.camera.position = {0, 2, 4};
  s.camera.target = {0, 0, -4};
  s.sun->direction = glm::normalize(glm::dvec3(0.1, -0.3, -0.9));
  const CasterBounds box{{0, 1.5, 6}, glm::length(glm::dvec3(1.5, 3, 0.5))};
  const CasterBounds ground{{0, 0, 0}, 40 * std::sqrt(2.0)};
  const std::vector<CasterBounds> casters{ground, box};
  const SunShadowFit fit = fitSunShadow(s, casters);
  const SunShadowFit without = fitSunShadow(s, {});
  const SunCascade& c = fit.cascades[0];
  ASSERT_TRUE(casterInCascade(c, box, s.sun->direction));
  const glm::dvec3 sunward = box.center - box.radius * s.sun->direction;
  EXPECT_GE(passAtlas(c, sunward).z, 0.0);
  EXPECT_LE(passAtlas(c, box.center).z, 1.0);
  EXPECT_LT(passAtlas(without.cascades[0], sunward).z, 0.0);
  // Every cascade that the box can shadow holds it.
  for (const SunCascade& cascade : fit.cascades)
    if (casterInCascade(cascade, box, s.sun->direction)) {
      EXPECT_GE(passAtlas(cascade, sunward).z, 0.0);
    }
}

TEST(SunShadow, CasterCullingKeepsCastersUpSunAndDropsFarOnes) {
  const Scene s = sunScene();
  const SunShadowFit fit = fitSunShadow(s, {});
  const glm::dvec3 sun = s.sun->direction;
  for (const SunCascade& c : fit.cascades) {
    const double reach = 0.5 * c.texelSize * c.viewport[2];
    // Up-sun of the slice, however far: it shadows it.
    EXPECT_TRUE(casterInCascade(c, {c.center - 500.0 * sun, 0.1}, sun));
    EXPECT_TRUE(casterInCascade(c, {c.center, 0.1}, sun));
    // Down-sun beyond the sphere: its shadow falls past the slice.
    EXPECT_FALSE(casterInCascade(c, {c.center + (reach + 2) * sun, 1.0}, sun));
    // Across the rays beyond the square's reach, on either side.
    const glm::dvec3 across = glm::normalize(glm::cross(sun, glm::dvec3(0, 1, 0)));
    EXPECT_FALSE(casterInCascade(c, {c.center - 50.0 * sun + (reach + 1.5) * across, 1.0}, sun));
    EXPECT_TRUE(casterInCascade(c, {c.center - 50.0 * sun + (reach + 0.5) * across, 1.0}, sun));
  }
}

TEST(SunShadow, DegenerateSunsCamerasAndSettingsStayFinite) {
  {
    SCOPED_TRACE("sun straight down");
    Scene s = sunScene();
    s.sun->direction = {0, -1, 0};
    expectPassAndReceiversAgree(s);
  }
  {
    SCOPED_TRACE("sun along the camera's forward axis");
    Scene s = sunScene();
    s.sun->direction = glm::normalize(s.camera.target - s.camera.position);
    expectPassAndReceiversAgree(s);
    s.sun->direction = -s.sun->direction;
    expectPassAndReceiversAgree(s);
  }
  {
    SCOPED_TRACE("camera looking straight down with the sun");
    Scene s = sunScene();
    s.camera.position = {0, 20, 0};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 0, -1};
    s.sun->direction = {0, -1, 0};
    expectPassAndReceiversAgree(s);
  }
  {
    SCOPED_TRACE("one cascade, the smallest atlas, the largest normal bias");
    Scene s = sunScene(1);
    s.shadows.atlasSize = 256;
    s.shadows.normalBias = 64;
    expectPassAndReceiversAgree(s);
  }
  {
    SCOPED_TRACE("four cascades in the smallest atlas");
    Scene s = sunScene(4);
    s.shadows.atlasSize = 256;
    s.shadows.normalBias = 64;
    expectPassAndReceiversAgree(s);
  }
  {
    SCOPED_TRACE("shadow distance short of the near plane");
    Scene s = sunScene();
    s.camera.nearPlane = 0.5;
    s.shadows.distance = 0.01;
    const SunShadowFit fit = fitSunShadow(s, {});
    expectFinite(fit);
    // Every pixel the camera draws lies past the distance: fully faded, lit.
    EXPECT_EQ(std::clamp(s.camera.nearPlane * fit.uniforms.fadeAtlas[0] + fit.uniforms.fadeAtlas[1], 0.0, 1.0), 1.0);
  }
  {
    SCOPED_TRACE("no sun");
    Scene s = sunScene();
    s.sun.reset();
    EXPECT_TRUE(fitSunShadow(s, {}).cascades.empty());
  }
}

// The figure of the request: of fixed world points the camera sees within the shadow distance,
// the fraction whose shadow lookup changes (another cascade, or another texel of the sun's frame)
// when the camera moves by a tenth of a texel. Goal: at most 0.1 %.
TEST(SunShadow, ShimmerFigure) {
  const Scene start = sunScene();
  const SunShadowFit first = fitSunShadow(start, {});
  std::printf("| cascade | view depths (m) | sphere radius (m) | texel (mm) | depth range (m) |\n");
  for (size_t i = 0; i < first.cascades.size(); ++i) {
    const SunCascade& c = first.cascades[i];
    std::printf("| %zu | %.2f – %.2f | %.2f | %.2f | %.2f |\n", i, c.splitNear, c.splitFar, c.radius,
                1000 * c.texelSize, c.depthRange);
  }
  const glm::dmat4 view = glm::lookAt(start.camera.position, start.camera.target, start.camera.up);
  const double near = start.camera.nearPlane, far = start.shadows.distance;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0, 1), across(-1, 1);
  std::vector<glm::dvec3> points;
  for (int k = 0; k < 20000; ++k) {
    // Uniform in the frustum's volume: depth³ uniform between near³ and far³.
    const double depth = std::cbrt(near * near * near + unit(random) * (far * far * far - near * near * near));
    points.push_back(viewPoint(start, depth, across(random), across(random)));
  }
  // The lookup: cascade, and the centre of the texel read, in world units across the sun's rays.
  struct Lookup {
    int cascade = -1;
    glm::dvec2 texel{0};
  };
  const glm::dvec3 sun = start.sun->direction;
  const glm::dvec3 right = glm::normalize(glm::cross(sun, glm::dvec3(0, 1, 0))), up = glm::cross(sun, right);
  auto lookup = [&](const SunShadowFit& fit, const glm::dvec3& cameraPosition, const glm::dvec3& p) {
    Lookup l;
    const double d = glm::dot(p - cameraPosition, glm::dvec3(vec(fit.uniforms.cameraForward)));
    for (size_t i = 0; i < fit.cascades.size() && l.cascade < 0; ++i)
      if (d < fit.cascades[i].splitFar) l.cascade = int(i);
    if (l.cascade < 0) return l;
    const SunCascade& c = fit.cascades[size_t(l.cascade)];
    const glm::dvec3 at = passAtlas(c, p);
    const glm::dvec4 centre((std::floor(at.x) + 0.5 - c.viewport[0]) / c.viewport[2] * 2 - 1,
                            (std::floor(at.y) + 0.5 - c.viewport[1]) / c.viewport[3] * 2 - 1, 0, 1);
    const glm::dvec3 world(glm::inverse(c.viewProjection) * centre);
    l.texel = {glm::dot(world, right), glm::dot(world, up)};
    return l;
  };
  std::vector<Lookup> before;
  for (const glm::dvec3& p : points) before.push_back(lookup(first, start.camera.position, p));
  double worst = 0;
  for (size_t i = 0; i < first.cascades.size(); ++i)
    for (int axis = 0; axis < 3; ++axis) {
      Scene moved = start;
      glm::dvec3 step(0);
      step[axis] = first.cascades[i].texelSize / 10;
      moved.camera.position += step;
      moved.camera.target += step;
      const SunShadowFit fit = fitSunShadow(moved, {});
      const glm::dmat4 movedView = glm::lookAt(moved.camera.position, moved.camera.target, moved.camera.up);
      size_t seen = 0, changed = 0;
      for (size_t k = 0; k < points.size(); ++k) {
        // Points the camera sees both times.
        const double depthBefore = -(view * glm::dvec4(points[k], 1)).z;
        const double depthAfter = -(movedView * glm::dvec4(points[k], 1)).z;
        if (depthBefore > far || depthAfter > far || depthAfter < near) continue;
        ++seen;
        const Lookup after = lookup(fit, moved.camera.position, points[k]);
        const double tolerance = 1e-3 * first.cascades[i].texelSize;
        if (after.cascade != before[k].cascade || glm::length(after.texel - before[k].texel) > tolerance) ++changed;
      }
      const double fraction = double(changed) / double(seen);
      std::printf(
          "shimmer: camera moved %.3g m (a tenth of cascade %zu's texel) along axis %d: %zu of %zu points "
          "(%.4f %%) read another cascade or texel\n",
          step[axis], i, axis, changed, seen, 100 * fraction);
      worst = std::max(worst, fraction);
    }
  std::printf("shimmer: worst %.4f %%\n", 100 * worst);
  EXPECT_LE(worst, 0.001);
}

}  // namespace
