#include "facet/shadow_reference/reference_image.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "facet/shadow_reference/camera_rays.h"

namespace facet::shadow_reference {

ReferenceImage renderReference(const ShadowScene& scene, const SunVisibility& sun, const ReferenceOptions& options) {
  ReferenceImage out;
  out.width = scene.scene.width;
  out.height = scene.scene.height;
  out.pixels.resize(size_t(out.width) * out.height);
  const CameraRays camera(scene.scene);
  for (uint32_t y = 0; y < out.height; ++y)
    for (uint32_t x = 0; x < out.width; ++x) {
      ReferencePixel& pixel = out.pixels[size_t(y) * out.width + x];
      const Ray ray = camera.ray(x, y);
      const std::optional<Hit> hit = sun.bvh().closestHit(ray);
      if (!hit) continue;
      const WorldTriangle& t = sun.triangles()[hit->triangle];
      pixel.object = t.object;
      glm::dvec3 normal = glm::cross(t.b - t.a, t.c - t.a);
      if (glm::dot(normal, ray.direction) > 0) normal = -normal;  // the side the camera sees
      const glm::dvec3 point = ray.origin + hit->t * ray.direction;
      if (!(glm::dot(normal, sun.towardsLight(point)) > 0) || !sun.reaches(point)) {
        pixel.kind = PixelKind::FacesAway;
        continue;
      }
      pixel.kind = PixelKind::Surface;
      if (!scene.scene.objects[t.object].receiveShadows) {
        pixel.visibility = pixel.footprint = 1;
        continue;
      }
      pixel.visibility = sun.visible(point, hit->triangle) ? 1 : 0;
      pixel.footprint = options.footprintRadius > 0
                            ? float(sun.footprintVisibility(point, normal, options.footprintRadius,
                                                            options.footprintSamples, hit->triangle))
                            : pixel.visibility;
    }
  return out;
}

std::vector<uint8_t> referencePixelsRgba(const ReferenceImage& image) {
  std::vector<uint8_t> rgba;
  rgba.reserve(image.pixels.size() * 4);
  for (const ReferencePixel& p : image.pixels) {
    if (p.kind == PixelKind::Sky) {
      rgba.insert(rgba.end(), {40, 60, 140, 255});
      continue;
    }
    const uint8_t v = p.kind == PixelKind::Surface ? uint8_t(std::lround(p.footprint * 255)) : 0;
    rgba.insert(rgba.end(), {v, v, v, 255});
  }
  return rgba;
}

}  // namespace facet::shadow_reference
