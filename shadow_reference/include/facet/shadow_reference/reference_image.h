// The reference visibility of every pixel of a scene's image: the camera ray's nearest hit, and
// the sun's visibility there, at the point and over a filter's footprint.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/shadow_reference/shadow_scene.h"
#include "facet/shadow_reference/sun_visibility.h"

namespace facet::shadow_reference {

enum class PixelKind : uint8_t {
  Sky,        // the camera ray meets nothing
  FacesAway,  // the surface's side the camera sees faces away from the light, or a spot light does not
              // reach it (outside its cone or range): unlit, shadow or not
  Surface,    // a surface the sun may light
};

struct ReferencePixel {
  PixelKind kind = PixelKind::Sky;
  uint32_t object = 0;   // the object hit (Surface and FacesAway)
  float visibility = 0;  // at the hit point: 0 or 1 (1 on an object that does not receive shadows)
  float footprint = 0;   // over the footprint disc: the fraction of its points that see the sun
};

struct ReferenceOptions {
  double footprintRadius = 0;  // metres; 0: the footprint is the hit point alone
  int footprintSamples = 16;
};

struct ReferenceImage {
  uint32_t width = 0, height = 0;
  std::vector<ReferencePixel> pixels;  // rows top to bottom
};

ReferenceImage renderReference(const ShadowScene& scene, const SunVisibility& sun, const ReferenceOptions& options);

// RGBA8 pixels for a PNG: a surface's footprint visibility as grey (white lit, black in shadow,
// grey between), surfaces facing away from the sun black, sky mid-blue.
std::vector<uint8_t> referencePixelsRgba(const ReferenceImage& image);

}  // namespace facet::shadow_reference
