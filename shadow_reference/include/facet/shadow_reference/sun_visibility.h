// The sun's visibility from world points, ray-cast against a scene's casting triangles: the
// ground truth shadow maps are measured against (docs/shadows.md, "Accuracy: the ray-cast
// reference"). The same for a spot light (buildSpot): rays towards its position, and only points
// within its cone and range are reached by it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "facet/shadow_reference/bvh.h"
#include "facet/shadow_reference/shadow_scene.h"
#include "facet/shadow_reference/world_triangles.h"

namespace facet::shadow_reference {

// Shadow rays start kRayEpsilon × the scene's size (its largest absolute coordinate, at least 1
// m) from their point. A point computed on a triangle in double lies within about 1e-15 of that
// size of the triangle's plane, and a ray leaving a surface at angle θ crosses it again within
// that error / sin θ: 1e-9 clears every sun above 1e-6 rad of grazing. It is 40 nm on a 40 m
// scene, while the renderer's fp32 positions resolve 2.4 µm there, so no gap the renderer can
// draw is stepped over. The receiving triangle itself is skipped outright.
inline constexpr double kRayEpsilon = 1e-9;

class SunVisibility {
 public:
  // The scene's triangles (buildWorldTriangles) and its BVH; nullopt with *error when a mesh
  // cannot be built or the scene has no sun.
  static std::optional<SunVisibility> build(const ShadowScene& scene, std::string* error);
  // The spot light scene.lights[light] in place of the sun (whatever its castShadows); nullopt with
  // *error when a mesh cannot be built or that light is not a spot light.
  static std::optional<SunVisibility> buildSpot(const ShadowScene& scene, size_t light, std::string* error);

  // 1 when the ray from `point` towards the sun (the spot light's position: the segment up to it)
  // meets no triangle of a casting object (other than `receiver`, the triangle the point lies on),
  // else 0.
  bool visible(const glm::dvec3& point, uint32_t receiver = kNoTriangle) const;
  // The fraction of `samples` points of the disc of `radius` about `centre`, perpendicular to
  // `normal`, from which the sun is visible: a filter's footprint. The points follow Vogel's
  // spiral (the golden angle between consecutive points, radii ∝ √((i + 1/2) / samples)): evenly
  // spread for any count and the same on every run. Radius 0 is the point alone.
  double footprintVisibility(const glm::dvec3& centre, const glm::dvec3& normal, double radius, int samples,
                             uint32_t receiver = kNoTriangle) const;

  const glm::dvec3& towardsSun() const { return towardsSun_; }  // the sun's (unused with a spot light)
  // The unit direction from `point` towards the light.
  glm::dvec3 towardsLight(const glm::dvec3& point) const;
  // Whether the light reaches `point` at all, shadow or not: always for the sun; for a spot, a
  // point strictly inside its outer cone and its range (where its falloff is above 0).
  bool reaches(const glm::dvec3& point) const;
  double rayEpsilon() const { return rayEpsilon_; }
  const std::vector<WorldTriangle>& triangles() const { return triangles_; }
  const Bvh& bvh() const { return bvh_; }

 private:
  SunVisibility(std::vector<WorldTriangle> triangles, std::vector<bool> casts, const glm::dvec3& towardsSun);
  SunVisibility(std::vector<WorldTriangle> triangles, std::vector<bool> casts, const runtime::PunctualLight& spot);
  std::vector<WorldTriangle> triangles_;
  std::vector<bool> casts_;  // per object
  Bvh bvh_;
  glm::dvec3 towardsSun_;
  std::optional<runtime::PunctualLight> spot_;  // with a spot light: its position, axis, cone and range
  double rayEpsilon_ = kRayEpsilon;
};

}  // namespace facet::shadow_reference
