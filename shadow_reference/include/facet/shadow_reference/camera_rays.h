// The camera rays of a scene's pixels, with the renderer's camera: its view and projection are
// SceneFrame's (runtime/scene_frame.cpp; test_shadow_reference checks that the matrices agree
// with what SceneFrame uploads), and a pixel's ray passes through its centre, where the
// rasteriser samples it without MSAA. Rows run top to bottom, as in the renderer's images.
#pragma once

#include <cstdint>

#include <glm/mat4x4.hpp>

#include "facet/scene/scene.h"
#include "facet/shadow_reference/bvh.h"

namespace facet::shadow_reference {

class CameraRays {
 public:
  explicit CameraRays(const runtime::Scene& scene);
  // The ray through pixel (x, y)'s centre from the camera, unit direction, t in metres between
  // the near and far planes.
  Ray ray(uint32_t x, uint32_t y) const;

 private:
  glm::dmat4 inverseViewProjection_;
  glm::dvec3 position_, forward_;
  double near_, far_;
  uint32_t width_, height_;
};

}  // namespace facet::shadow_reference
