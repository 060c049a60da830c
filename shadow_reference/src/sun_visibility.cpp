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
  return !bvh_.occluded({point, towardsSun_, rayEpsilon_, 1e300}, casts_, receiver);
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
