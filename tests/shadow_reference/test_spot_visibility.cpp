// A spot light's visibility in the ray-cast reference (SunVisibility::buildSpot) against answers
// worked out by hand: a sphere's shadow on a plane (a ground point is shadowed exactly when the
// segment to the light passes within the radius of the centre), a caster beyond the light casting
// nothing, the cone and range the light reaches, and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "facet/shadow_reference/camera_rays.h"
#include "facet/shadow_reference/reference_image.h"
#include "facet/shadow_reference/shadow_score.h"

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

SunVisibility build(const ShadowScene& s) {
  std::string error;
  std::optional<SunVisibility> spot = SunVisibility::buildSpot(s, 1, &error);
  EXPECT_TRUE(spot) << error;
  return std::move(*spot);
}

}  // namespace

// Every pixel that sees the ground (found by intersecting the camera ray with the plane itself):
// outside the cone unreached, inside it shadowed exactly where the segment to the light passes
// within the sphere's radius (1e-3 of the radius either side not judged, as for the sun:
// tessellation).
TEST(SpotVisibility, SphereUnderASpotCastsItsAnalyticShadow) {
  const glm::dvec3 centre(0, 2, 0.3);
  const double radius = 0.6;
  const ShadowScene s = spotScene({object("sphere", centre, {radius, radius, radius})});
  const SunVisibility spot = build(s);
  const ReferenceImage image = renderReference(s, spot, {});
  const CameraRays camera(s.scene);
  const runtime::PunctualLight& light = s.scene.lights[1];
  int shadowed = 0, lit = 0, outside = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const ReferencePixel& p = image.pixels[size_t(y) * image.width + x];
      if (p.kind == PixelKind::Sky || p.object != 0) continue;
      const Ray ray = camera.ray(x, y);
      const glm::dvec3 ground = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
      const glm::dvec3 fromLight = ground - light.position;
      const double angle = std::acos(glm::dot(glm::normalize(fromLight), light.direction));
      if (std::abs(angle - glm::radians(40.0)) < 1e-3) continue;
      if (angle > glm::radians(40.0)) {
        EXPECT_EQ(p.kind, PixelKind::FacesAway) << "pixel " << x << "," << y << " lies outside the cone";
        ++outside;
        continue;
      }
      ASSERT_EQ(p.kind, PixelKind::Surface) << "pixel " << x << "," << y;
      // The distance from the sphere's centre to the segment from the ground point to the light.
      const glm::dvec3 d = glm::normalize(light.position - ground);
      const glm::dvec3 toCentre = centre - ground;
      const double distance = glm::length(toCentre - glm::dot(toCentre, d) * d);
      if (distance < radius * (1 - 1e-3)) {
        EXPECT_EQ(p.visibility, 0) << "pixel " << x << "," << y << " lies in the shadow";
        ++shadowed;
      } else if (distance > radius * (1 + 1e-3)) {
        EXPECT_EQ(p.visibility, 1) << "pixel " << x << "," << y << " lies outside the shadow";
        ++lit;
      }
    }
  EXPECT_GT(shadowed, 300);
  EXPECT_GT(lit, 1000);
  EXPECT_GT(outside, 1000);
}

// Rays end at the light: a caster above it, on the line from a ground point through the light,
// hides nothing; the same caster between them does.
TEST(SpotVisibility, ACasterBeyondTheLightCastsNothing) {
  const glm::dvec3 ground(0, 0, 0);
  const ShadowScene above = spotScene({object("sphere", {0.5, 7, 0}, {0.5, 0.5, 0.5})});
  EXPECT_TRUE(build(above).visible(ground));
  const ShadowScene between = spotScene({object("sphere", {0.25, 2.5, 0}, {0.5, 0.5, 0.5})});
  EXPECT_FALSE(build(between).visible(ground));
  // The sun's reference, with the same caster above, would hide it: the segment is what differs.
  ShadowScene sun = above;
  sun.scene.sun = runtime::Sun{};
  sun.scene.sun->direction = glm::normalize(ground - glm::dvec3(0.5, 7, 0));
  std::string error;
  EXPECT_FALSE(SunVisibility::build(sun, &error)->visible(ground));
}

TEST(SpotVisibility, TheLightReachesItsConeWithinItsRange) {
  const SunVisibility spot = build(spotScene({}));
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

}  // namespace facet::shadow_reference
