// ibl/equirect_image.h
// A float RGB environment in the equirectangular (latitude–longitude) layout, and the mapping
// between its texels and directions. World space is right-handed with +y up (as the renderer's).
//
// Mapping (texture coordinates s, t in [0, 1], texel (column, row) centred at ((c + 0.5)/W, (r + 0.5)/H)):
//   θ = π t        polar angle from +y: row 0 is the zenith, the last row the nadir
//   φ = 2π s       azimuth, from +x towards +z
//   d = (sin θ cos φ, cos θ, sin θ sin φ)
// Inverse, as a shader writes it:  s = fract(atan(d.z, d.x) / 2π),  t = acos(d.y) / π.
// A texel spans Δφ = 2π/W by Δθ = π/H, so its solid angle is Δφ (cos θ₀ − cos θ₁): equal along a
// row, shrinking towards the poles.
#pragma once

#include <vector>

#include "facet/ibl/vec3.h"

namespace facet::ibl {

struct EquirectImage {
  int width = 0;  // 2 × height for the environments Facet builds
  int height = 0;
  std::vector<float> rgb;  // width × height × 3, row-major, row 0 = zenith

  EquirectImage() = default;
  EquirectImage(int w, int h) : width(w), height(h), rgb(size_t(w) * size_t(h) * 3, 0.0f) {}

  Vec3 texel(int column, int row) const;
  void setTexel(int column, int row, Vec3 value);
};

/// The direction through the centre of texel (column, row).
Vec3 equirectDirection(const EquirectImage& image, int column, int row);

/// Texture coordinates (s, t) of a unit direction, by the inverse mapping above.
void equirectCoordinates(Vec3 direction, double* s, double* t);

/// Solid angle of a texel of `row` (steradians); the sum over the image is 4π.
double equirectTexelSolidAngle(const EquirectImage& image, int row);

/// Bilinear sample at texture coordinates (s, t): wraps in s (the seam at φ = 0 is continuous),
/// clamps in t (the poles), as a GPU sampler set to REPEAT × CLAMP_TO_EDGE does.
Vec3 sampleBilinear(const EquirectImage& image, double s, double t);

/// The image rendered from a radiance function, one sample per texel centre.
template <class Radiance>
EquirectImage renderEquirect(int width, int height, const Radiance& radiance) {
  EquirectImage image(width, height);
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column)
      image.setTexel(column, row, radiance(equirectDirection(image, column, row)));
  return image;
}

/// Half the resolution in both axes; each output texel is the solid-angle-weighted mean of its
/// 2 × 2 children, so the solid-angle-weighted mean of the image (its mean radiance) is kept.
/// width and height must be even.
EquirectImage downsampleEquirect(const EquirectImage& image);

/// Solid-angle-weighted mean radiance.
Vec3 meanRadiance(const EquirectImage& image);

}  // namespace facet::ibl
