#include "cascade_overlay.h"

#include <glm/geometric.hpp>

#include "facet/shadow_reference/camera_rays.h"
#include "facet/shadow_reference/sun_visibility.h"

namespace facet::viewer {

bool tintShadowCascades(const runtime::Scene& scene, const abi::ShadowUniforms& shadow, std::vector<uint8_t>* rgba,
                        std::array<size_t, abi::kMaxShadowCascades>* pixels, std::string* error) {
  pixels->fill(0);
  if (rgba->size() != size_t(scene.width) * scene.height * 4) {
    *error = "--shadow-cascades: the image is not the scene's size";
    return false;
  }
  const shadow_reference::ShadowScene shadowScene{scene};
  auto sun = shadow_reference::SunVisibility::build(shadowScene, error);
  if (!sun) return false;
  const shadow_reference::CameraRays camera(scene);
  const glm::dvec3 forward(shadow.cameraForward[0], shadow.cameraForward[1], shadow.cameraForward[2]);
  const uint32_t cascades = runtime::sunShadowCascades(scene);
  constexpr uint8_t kTints[abi::kMaxShadowCascades][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}};
  for (uint32_t y = 0; y < scene.height; ++y)
    for (uint32_t x = 0; x < scene.width; ++x) {
      const shadow_reference::Ray ray = camera.ray(x, y);
      const auto hit = sun->bvh().closestHit(ray);
      if (!hit || !scene.objects[sun->triangles()[hit->triangle].object].receiveShadows) continue;
      const double depth = glm::dot(ray.origin + hit->t * ray.direction - scene.camera.position, forward);
      if (depth >= scene.shadows.distance) continue;
      // The receivers' choice: the first cascade whose split lies beyond the depth.
      uint32_t cascade = 0;
      while (cascade + 1 < cascades && depth >= shadow.splits[cascade]) ++cascade;
      ++(*pixels)[cascade];
      uint8_t* p = &(*rgba)[(size_t(y) * scene.width + x) * 4];
      for (int c = 0; c < 3; ++c) p[c] = uint8_t((p[c] + kTints[cascade][c] + 1) / 2);
    }
  return true;
}

}  // namespace facet::viewer
