#include "facet/shadow_reference/camera_rays.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace facet::shadow_reference {

CameraRays::CameraRays(const runtime::Scene& scene)
    : inverseViewProjection_(glm::inverse(runtime::viewProjection(scene))),
      position_(scene.camera.position),
      forward_(glm::normalize(scene.camera.target - scene.camera.position)),
      near_(scene.camera.nearPlane),
      far_(scene.camera.farPlane),
      width_(scene.width),
      height_(scene.height) {}

Ray CameraRays::ray(uint32_t x, uint32_t y) const {
  // Normalised device coordinates of the pixel's centre, +y up (row 0 is the top). The point at
  // clip depth 1 lies on the far plane whether depth runs from -1 or 0.
  const double ndcX = 2 * (x + 0.5) / width_ - 1, ndcY = 1 - 2 * (y + 0.5) / height_;
  const glm::dvec4 far = inverseViewProjection_ * glm::dvec4(ndcX, ndcY, 1, 1);
  const glm::dvec3 direction = glm::normalize(glm::dvec3(far) / far.w - position_);
  // The planes are perpendicular to the view direction: the ray crosses them at depth / cos.
  const double cosine = glm::dot(direction, forward_);
  return {position_, direction, near_ / cosine, far_ / cosine};
}

}  // namespace facet::shadow_reference
