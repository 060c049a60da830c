// The sun's visibility against answers worked out by hand: a sphere's shadow on a plane (an
// ellipse: a ground point is shadowed exactly when its ray towards the sun passes within the
// radius of the centre), a box's shadow edge, a caster behind the camera, the castShadows and
// receiveShadows flags, a scene with nothing that casts; and the camera against the renderer's. A
// spot light's likewise: a sphere's shadow on a plane (a ground point is shadowed exactly when the
// segment to the light passes within the radius of the centre), a caster beyond the light casting
// nothing, the cone and range the light reaches, and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "facet/runtime/scene_frame.h"
#include "facet/shadow_reference/camera_rays.h"
#include "facet/shadow_reference/reference_image.h"
#include "facet/shadow_reference/shadow_score.h"
#include "test_support.h"

namespace facet::shadow_reference {
namespace {

runtime::SceneObject object(const std::string& mesh, const glm::dvec3& position, const glm::dvec3& scale) {
  runtime::SceneObject o;
  o.mesh = mesh;
  o.material = "red_plastic";
  o.position = position;
  o.scale = scale;
  return o;
}

ShadowScene sceneOf(const glm::dvec3& sunDirection, std::vector<runtime::SceneObject> objects) {
  ShadowScene s;
  s.scene.width = 160;
  s.scene.height = 120;
  s.scene.sun = runtime::Sun{};
  s.scene.sun->direction = sunDirection;
  s.scene.objects = std::move(objects);
  return s;
}

SunVisibility build(const ShadowScene& s) {
  std::string error;
  std::optional<SunVisibility> sun = SunVisibility::build(s, &error);
  EXPECT_TRUE(sun) << error;
  return std::move(*sun);
}

// Renders the scene's reference and checks every pixel that sees the ground (y = 0, found by
// intersecting the camera ray with the plane itself, not through the BVH) against the sphere's
// analytic shadow. Tessellation puts the mesh's silhouette up to 1 - cos(pi/128) = 3e-4 of the
// radius inside the sphere, so points within 1e-3 of the radius of the edge are not judged.
// Returns the shadowed and lit pixels judged. `light` is the sun's or a spot light's (whose segment
// to the ground point is the line's part that a sphere below the light can cross).
std::pair<int, int> checkSphereShadow(const ShadowScene& s, const SunVisibility& light, const glm::dvec3& centre,
                                      double radius) {
  const ReferenceImage image = renderReference(s, light, {});
  const CameraRays camera(s.scene);
  int shadowed = 0, lit = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const ReferencePixel& p = image.pixels[size_t(y) * image.width + x];
      if (p.kind != PixelKind::Surface || p.object != 0) continue;
      const Ray ray = camera.ray(x, y);
      const glm::dvec3 ground = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
      const glm::dvec3 toCentre = centre - ground;
      const glm::dvec3 L = light.towardsLight(ground);
      const double distance = glm::length(toCentre - glm::dot(toCentre, L) * L);
      if (distance < radius * (1 - 1e-3)) {
        EXPECT_EQ(p.visibility, 0) << "pixel " << x << "," << y << " lies in the shadow";
        ++shadowed;
      } else if (distance > radius * (1 + 1e-3)) {
        EXPECT_EQ(p.visibility, 1) << "pixel " << x << "," << y << " lies outside the shadow";
        ++lit;
      }
    }
  return {shadowed, lit};
}

TEST(SunVisibility, SphereOverAPlaneCastsItsAnalyticEllipse) {
  const glm::dvec3 centre(0.2, 1.5, -0.3);
  ShadowScene s =
      sceneOf({0.4, -1, 0.25}, {object("plane", {0, 0, 0}, {20, 1, 20}), object("sphere", centre, {1, 1, 1})});
  s.scene.objects[1].scale = {0.8, 0.8, 0.8};
  s.scene.camera.position = {1, 6, 7};
  s.scene.camera.target = {0.5, 0, -0.5};
  auto [shadowed, lit] = checkSphereShadow(s, build(s), centre, 0.8);
  EXPECT_GT(shadowed, 300);
  EXPECT_GT(lit, 5000);
}

// A caster the camera cannot see still casts: the sphere is behind the camera.
TEST(SunVisibility, CasterBehindTheCameraStillCasts) {
  const glm::dvec3 centre(0, 2, 6);
  ShadowScene s = sceneOf({0, -1, -3}, {object("plane", {0, 0, 0}, {40, 1, 40}), object("sphere", centre, {1, 1, 1})});
  s.scene.camera.position = {0, 3, 4};
  s.scene.camera.target = {0, 0, -4};
  auto [shadowed, lit] = checkSphereShadow(s, build(s), centre, 1);
  EXPECT_GT(shadowed, 200);
  EXPECT_GT(lit, 3000);
  const SunVisibility sun = build(s);
  for (const ReferencePixel& p : renderReference(s, sun, {}).pixels) ASSERT_NE(p.object, 1u) << "the sphere is seen";
}

// A 2 m box on the ground under a sun at 45° towards +x: its shadow ends at x = 0.5 + 2.
TEST(SunVisibility, BoxShadowEdgeLiesWhereTheTopEdgeProjects) {
  const ShadowScene s =
      sceneOf({1, -1, 0}, {object("plane", {0, 0, 0}, {20, 1, 20}), object("box", {0, 1, 0}, {1, 2, 1})});
  const SunVisibility sun = build(s);
  for (double x = 0.55; x < 2.5; x += 0.05) EXPECT_FALSE(sun.visible({x, 0, 0.2})) << x;
  for (double x = 2.55; x < 6; x += 0.05) EXPECT_TRUE(sun.visible({x, 0, 0.2})) << x;
  double lo = 2.0, hi = 3.0;  // occluded at lo, visible at hi
  for (int i = 0; i < 40; ++i) {
    const double mid = (lo + hi) / 2;
    (sun.visible({mid, 0, -0.3}) ? hi : lo) = mid;
  }
  EXPECT_NEAR(lo, 2.5, 1e-9);
  // Beside the box (|z| > 0.5) the ground is lit.
  EXPECT_TRUE(sun.visible({1.5, 0, 0.55}));
  EXPECT_FALSE(sun.visible({1.5, 0, 0.45}));
}

// Over a footprint disc of radius 0.1: exactly 0 or 1 farther than 0.1 from the edge, between on it.
TEST(SunVisibility, FootprintIsExactAwayFromTheEdgeAndPartialOnIt) {
  const ShadowScene s =
      sceneOf({1, -1, 0}, {object("plane", {0, 0, 0}, {20, 1, 20}), object("box", {0, 1, 0}, {1, 2, 1})});
  const SunVisibility sun = build(s);
  const glm::dvec3 up(0, 1, 0);
  EXPECT_EQ(sun.footprintVisibility({2.35, 0, 0}, up, 0.1, 32), 0);
  EXPECT_EQ(sun.footprintVisibility({2.65, 0, 0}, up, 0.1, 32), 1);
  const double onEdge = sun.footprintVisibility({2.5, 0, 0}, up, 0.1, 32);
  EXPECT_GT(onEdge, 0.3);
  EXPECT_LT(onEdge, 0.7);
  EXPECT_EQ(sun.footprintVisibility({2.5, 0, 0}, up, 0.1, 32), onEdge);  // the same points every time
}

// The torus (examples/scenes/meshes/torus.gltf: R 1, r 0.4, in the xz plane) shadows itself: from
// the hole, the ray towards a low sun meets the far side of the ring. Only when it casts.
TEST(SunVisibility, SelfShadowingFollowsCastShadows) {
  ShadowScene s = sceneOf({1, -0.2, 0}, {object(test::examplePath("scenes/meshes/torus.gltf"), {0, 0, 0}, {1, 1, 1})});
  s.scene.assetRoot = test::examplePath("scenes");
  EXPECT_FALSE(build(s).visible({0.55, 0, 0}));
  EXPECT_TRUE(build(s).visible({0, 0.5, 0}));
  s.scene.objects[0].castShadows = false;
  EXPECT_TRUE(build(s).visible({0.55, 0, 0}));
}

TEST(SunVisibility, CastAndReceiveFlags) {
  ShadowScene s =
      sceneOf({0.3, -1, 0.2}, {object("plane", {0, 0, 0}, {20, 1, 20}), object("sphere", {0, 1.5, 0}, {1, 1, 1})});
  s.scene.camera.position = {0, 6, 6};
  s.scene.camera.target = {0, 0, 0};
  const ReferenceCounts casting = countReference(renderReference(s, build(s), {}));
  EXPECT_GT(casting.occluded, 500u);
  s.scene.objects[1].castShadows = false;  // the sphere no longer casts
  const ReferenceCounts notCasting = countReference(renderReference(s, build(s), {}));
  EXPECT_EQ(notCasting.occluded, 0u);
  EXPECT_EQ(notCasting.lit, casting.lit + casting.occluded);
  s.scene.objects[1].castShadows = true;
  s.scene.objects[0].receiveShadows = false;  // the ground no longer receives
  EXPECT_EQ(countReference(renderReference(s, build(s), {})).occluded, 0u);
}

TEST(SunVisibility, NothingThatCastsLeavesEverythingLit) {
  ShadowScene s = sceneOf({0.3, -1, 0.2}, {object("plane", {0, 0, 0}, {20, 1, 20})});
  s.scene.camera.position = {0, 6, 6};
  const ReferenceCounts counts = countReference(renderReference(s, build(s), {0.2, 16}));
  EXPECT_EQ(counts.occluded + counts.partial + counts.facesAway, 0u);
  EXPECT_GT(counts.lit, 5000u);
}

TEST(SunVisibility, SceneWithoutSunIsAnError) {
  ShadowScene s = sceneOf({0, -1, 0}, {});
  s.scene.sun.reset();
  std::string error;
  EXPECT_FALSE(SunVisibility::build(s, &error));
  EXPECT_EQ(error, "the scene has no sun to cast shadows");
}

// The reference's camera is the renderer's: the matrix SceneFrame uploads (in float) is the
// reference's, and each pixel's ray projects back to that pixel's centre.
TEST(SunVisibility, CameraMatchesTheRenderers) {
  ShadowScene s = sceneOf({0, -1, 0}, {});
  s.scene.width = 300;
  s.scene.height = 170;
  s.scene.camera.position = {1.5, 2.4, 9};
  s.scene.camera.target = {0, 0.7, 0};
  s.scene.camera.fovYDegrees = 38;
  s.scene.camera.nearPlane = 0.3;
  std::string error;
  auto frame = runtime::SceneFrame::prepare(s.scene, "", &error);
  ASSERT_TRUE(frame) << error;
  const glm::mat4 reference(facet::runtime::viewProjection(s.scene));
  const float* uploaded = frame->frame().frame.viewProjection;
  for (int i = 0; i < 16; ++i) EXPECT_EQ(uploaded[i], glm::value_ptr(reference)[i]) << i;
  const CameraRays camera(s.scene);
  for (uint32_t y : {0u, 57u, 169u})
    for (uint32_t x : {0u, 123u, 299u}) {
      const Ray ray = camera.ray(x, y);
      const glm::dvec4 clip = facet::runtime::viewProjection(s.scene) * glm::dvec4(ray.origin + 5.0 * ray.direction, 1);
      EXPECT_NEAR((clip.x / clip.w + 1) / 2 * 300, x + 0.5, 1e-9);
      EXPECT_NEAR((1 - clip.y / clip.w) / 2 * 170, y + 0.5, 1e-9);
      EXPECT_NEAR(glm::length(ray.direction), 1, 1e-12);
    }
}

// A spot light in the sun's place (SunVisibility::buildSpot).

// A spot 5 m above the ground at (0.5, 5, 0), pointing down a little towards −x, 40° cone, 20 m
// range, over a 20 m plane; the camera above and beside it.
ShadowScene spotScene(std::vector<runtime::SceneObject> objects) {
  ShadowScene s;
  s.scene.width = 160;
  s.scene.height = 120;
  s.scene.camera.position = {0, 9, 7};
  s.scene.camera.target = {0, 0, 0};
  runtime::PunctualLight spot;
  spot.spot = true;
  spot.castShadows = true;
  spot.position = {0.5, 5, 0};
  spot.direction = glm::normalize(glm::dvec3(-0.1, -1, 0));
  spot.range = 20;
  spot.innerAngleDegrees = 30;
  spot.outerAngleDegrees = 40;
  s.scene.lights = {runtime::PunctualLight{}, spot};
  s.scene.objects = {object("plane", {0, 0, 0}, {20, 1, 20})};
  for (runtime::SceneObject& o : objects) s.scene.objects.push_back(std::move(o));
  return s;
}

SunVisibility buildSpot(const ShadowScene& s) {
  std::string error;
  std::optional<SunVisibility> spot = SunVisibility::buildSpot(s, 1, &error);
  EXPECT_TRUE(spot) << error;
  return std::move(*spot);
}

// Every pixel that sees the ground (found by intersecting the camera ray with the plane itself):
// outside the cone unreached, inside it shadowed exactly where the segment to the light passes
// within the sphere's radius (1e-3 of the radius either side not judged, as for the sun:
// tessellation).
TEST(SpotVisibility, SphereUnderASpotCastsItsAnalyticShadow) {
  const glm::dvec3 centre(0, 2, 0.3);
  const double radius = 0.6;
  const ShadowScene s = spotScene({object("sphere", centre, {radius, radius, radius})});
  const SunVisibility spot = buildSpot(s);
  auto [shadowed, lit] = checkSphereShadow(s, spot, centre, radius);
  EXPECT_GT(shadowed, 300);
  EXPECT_GT(lit, 1000);
  // The ground outside the cone is unreached (the ground never faces away from a light above it).
  const ReferenceImage image = renderReference(s, spot, {});
  const CameraRays camera(s.scene);
  const runtime::PunctualLight& light = s.scene.lights[1];
  int outside = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const ReferencePixel& p = image.pixels[size_t(y) * image.width + x];
      if (p.kind == PixelKind::Sky || p.object != 0) continue;
      const Ray ray = camera.ray(x, y);
      const glm::dvec3 ground = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
      const double angle = std::acos(glm::dot(glm::normalize(ground - light.position), light.direction));
      if (std::abs(angle - glm::radians(40.0)) < 1e-3) continue;
      EXPECT_EQ(p.kind == PixelKind::FacesAway, angle > glm::radians(40.0)) << "pixel " << x << "," << y;
      outside += angle > glm::radians(40.0) ? 1 : 0;
    }
  EXPECT_GT(outside, 1000);
}

// Rays end at the light: a caster above it, on the line from a ground point through the light,
// hides nothing; the same caster between them does.
TEST(SpotVisibility, ACasterBeyondTheLightCastsNothing) {
  const glm::dvec3 ground(0, 0, 0);
  const ShadowScene above = spotScene({object("sphere", {0.5, 7, 0}, {0.5, 0.5, 0.5})});
  EXPECT_TRUE(buildSpot(above).visible(ground));
  const ShadowScene between = spotScene({object("sphere", {0.25, 2.5, 0}, {0.5, 0.5, 0.5})});
  EXPECT_FALSE(buildSpot(between).visible(ground));
  // The sun's reference, with the same caster above, would hide it: the segment is what differs.
  ShadowScene sun = above;
  sun.scene.sun = runtime::Sun{};
  sun.scene.sun->direction = glm::normalize(ground - glm::dvec3(0.5, 7, 0));
  std::string error;
  EXPECT_FALSE(SunVisibility::build(sun, &error)->visible(ground));
}

TEST(SpotVisibility, TheLightReachesItsConeWithinItsRange) {
  const SunVisibility spot = buildSpot(spotScene({}));
  const glm::dvec3 position(0.5, 5, 0), axis = glm::normalize(glm::dvec3(-0.1, -1, 0));
  EXPECT_TRUE(spot.reaches(position + 3.0 * axis));
  EXPECT_TRUE(spot.reaches(position + 19.9 * axis));
  EXPECT_FALSE(spot.reaches(position + 20.1 * axis));  // past the range
  EXPECT_FALSE(spot.reaches(position - 3.0 * axis));   // behind the light
  const glm::dvec3 across = glm::normalize(glm::cross(axis, glm::dvec3(0, 0, 1)));
  for (double degrees : {39.5, 40.5}) {
    const double t = std::tan(glm::radians(degrees));
    EXPECT_EQ(spot.reaches(position + 3.0 * (axis + t * across)), degrees < 40) << degrees;
  }
  EXPECT_NEAR(glm::dot(spot.towardsLight({0.5, 0, 0}), glm::dvec3(0, 1, 0)), 1, 1e-15);
}

TEST(SpotVisibility, OnlyASpotLightCanBeTheLight) {
  const ShadowScene s = spotScene({});
  std::string error;
  EXPECT_FALSE(SunVisibility::buildSpot(s, 0, &error));  // slot 0 is a point light
  EXPECT_EQ(error, "the scene has no spot light 0 to cast shadows");
  EXPECT_FALSE(SunVisibility::buildSpot(s, 2, &error));
  EXPECT_EQ(error, "the scene has no spot light 2 to cast shadows");
}

}  // namespace
}  // namespace facet::shadow_reference
