#include "facet/shadow_reference/sun_visibility.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace facet::shadow_reference {

SunVisibility::SunVisibility(std::vector<WorldTriangle> triangles, std::vector<bool> casts,
                             const glm::dvec3& towardsSun)
    : triangles_(std::move(triangles)), casts_(std::move(casts)), bvh_(triangles_), towardsSun_(towardsSun) {
  double size = 1;
  for (const WorldTriangle& t : triangles_)
    for (const glm::dvec3& p : {t.a, t.b, t.c}) size = std::max({size, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  rayEpsilon_ = kRayEpsilon * size;
}

SunVisibility::SunVisibility(std::vector<WorldTriangle> triangles, std::vector<bool> casts,
                             const runtime::PunctualLight& spot)
    : SunVisibility(std::move(triangles), std::move(casts), glm::dvec3(0, 1, 0)) {
  spot_ = spot;
  spot_->direction = glm::normalize(spot.direction);
  // The light's position is a point of the scene too: the epsilon covers its coordinates.
  rayEpsilon_ = std::max(rayEpsilon_, kRayEpsilon * std::max({std::abs(spot.position.x), std::abs(spot.position.y),
                                                              std::abs(spot.position.z)}));
}

std::optional<SunVisibility> SunVisibility::buildSpot(const ShadowScene& scene, size_t light, std::string* error) {
  if (light >= scene.scene.lights.size() || !scene.scene.lights[light].spot) {
    *error = "the scene has no spot light " + std::to_string(light) + " to cast shadows";
    return std::nullopt;
  }
  auto triangles = buildWorldTriangles(scene.scene, error);
  if (!triangles) return std::nullopt;
  std::vector<bool> casts;
  for (const runtime::SceneObject& o : scene.scene.objects) casts.push_back(o.castShadows);
  return SunVisibility(std::move(*triangles), std::move(casts), scene.scene.lights[light]);
}

std::optional<SunVisibility> SunVisibility::build(const ShadowScene& scene, std::string* error) {
  if (!scene.scene.sun) {
    *error = "the scene has no sun to cast shadows";
    return std::nullopt;
  }
  auto triangles = buildWorldTriangles(scene.scene, error);
  if (!triangles) return std::nullopt;
  std::vector<bool> casts;
  for (const runtime::SceneObject& o : scene.scene.objects) casts.push_back(o.castShadows);
  return SunVisibility(std::move(*triangles), std::move(casts), -glm::normalize(scene.scene.sun->direction));
}

bool SunVisibility::visible(const glm::dvec3& point, uint32_t receiver) const {
  if (!spot_) return !bvh_.occluded({point, towardsSun_, rayEpsilon_, 1e300}, casts_, receiver);
  // The segment to the light, in metres along the unit direction, short of the light by the same
  // epsilon it starts with (a triangle through the light's position does not hide it).
  const glm::dvec3 toLight = spot_->position - point;
  const double distance = glm::length(toLight);
  if (!(distance > 2 * rayEpsilon_)) return true;
  return !bvh_.occluded({point, toLight / distance, rayEpsilon_, distance - rayEpsilon_}, casts_, receiver);
}

glm::dvec3 SunVisibility::towardsLight(const glm::dvec3& point) const {
  return spot_ ? glm::normalize(spot_->position - point) : towardsSun_;
}

bool SunVisibility::reaches(const glm::dvec3& point) const {
  if (!spot_) return true;
  // chunks/light_punctual.glsl: the cone's falloff is 0 from the outer angle out, the range's at
  // the range.
  const glm::dvec3 fromLight = point - spot_->position;
  const double distance = glm::length(fromLight);
  return distance > 0 && distance < spot_->range &&
         glm::dot(fromLight, spot_->direction) > distance * std::cos(glm::radians(spot_->outerAngleDegrees));
}

double SunVisibility::footprintVisibility(const glm::dvec3& centre, const glm::dvec3& normal, double radius,
                                          int samples, uint32_t receiver) const {
  if (radius <= 0 || samples <= 0) return visible(centre, receiver) ? 1 : 0;
  // An orthonormal basis of the disc's plane (Duff et al., "Building an Orthonormal Basis,
  // Revisited", 2017).
  const glm::dvec3 n = glm::normalize(normal);
  const double sign = std::copysign(1.0, n.z);
  const double a = -1 / (sign + n.z), b = n.x * n.y * a;
  const glm::dvec3 tangent(1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  const glm::dvec3 bitangent(b, sign + n.y * n.y * a, -n.y);
  const double goldenAngle = M_PI * (3 - std::sqrt(5.0));
  int lit = 0;
  for (int i = 0; i < samples; ++i) {
    const double r = radius * std::sqrt((i + 0.5) / samples), phi = i * goldenAngle;
    // Off the receiving triangle the points may lie on others: none is skipped.
    lit += visible(centre + r * (std::cos(phi) * tangent + std::sin(phi) * bitangent)) ? 1 : 0;
  }
  return double(lit) / samples;
}

}  // namespace facet::shadow_reference
