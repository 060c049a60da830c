// Ray-casts the first object (a sphere) of a scene through a grid of pixel centres, for tests
// that compare rendered pixels with a CPU evaluation at the same surface point.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "facet/scene/scene.h"

namespace facet::test {

// Calls visit(x, y, p, n, v) for every `step`-th pixel whose centre sees the sphere with
// n·v ≥ minNoV (grazing pixels mix the silhouette with the background): p the surface point,
// n its normal, v the unit vector to the eye, all world space, in double precision.
template <typename Visit>
void forEachSpherePixel(const runtime::Scene& scene, uint32_t step, double minNoV, Visit visit) {
  const auto& cam = scene.camera;
  glm::dmat4 viewProjection =
      glm::perspective(glm::radians(cam.fovYDegrees), double(scene.width) / scene.height, cam.nearPlane, cam.farPlane) *
      glm::lookAt(cam.position, cam.target, cam.up);
  glm::dmat4 inverse = glm::inverse(viewProjection);
  const glm::dvec3 centre = scene.objects.at(0).position;
  const double radius = scene.objects.at(0).radius;
  for (uint32_t y = step; y < scene.height; y += step) {
    for (uint32_t x = step; x < scene.width; x += step) {
      glm::dvec4 ndcNear((x + 0.5) / scene.width * 2 - 1, 1 - (y + 0.5) / scene.height * 2, -1, 1);
      glm::dvec4 ndcFar = ndcNear;
      ndcFar.z = 1;
      glm::dvec4 a = inverse * ndcNear, b = inverse * ndcFar;
      glm::dvec3 origin = glm::dvec3(a) / a.w;
      glm::dvec3 dir = glm::normalize(glm::dvec3(b) / b.w - origin);
      glm::dvec3 oc = origin - centre;
      double half = glm::dot(oc, dir), c = glm::dot(oc, oc) - radius * radius, disc = half * half - c;
      if (disc <= 0) continue;
      glm::dvec3 p = origin + (-half - std::sqrt(disc)) * dir;
      glm::dvec3 n = glm::normalize(p - centre);
      glm::dvec3 v = glm::normalize(cam.position - p);
      if (glm::dot(n, v) < minNoV) continue;
      visit(x, y, p, n, v);
    }
  }
}

}  // namespace facet::test
