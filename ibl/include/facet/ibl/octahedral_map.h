// ibl/octahedral_map.h
// A float RGB environment in the octahedral layout (Praun & Hoppe 2003; Cigolle et al. 2014,
// "A Survey of Efficient Representations for Independent Unit Vectors"), the layout the shaders
// sample: its lookup is an L1 normalisation and a fold, with no atan/acos (the equirect lookup's
// two highp transcendentals cost 0.34 Mali cycles, 14 % of the high tier: issue 10).
//
// Mapping, +y up at the centre of the square (texture coordinates u, v in [0, 1], p = 2 (u, v) − 1):
//   encode: q = d / (|d.x| + |d.y| + |d.z|), p = q.xz; if q.y < 0, p = (1 − |p.yx|) · sgn(p)
//   decode: y = 1 − |p.x| − |p.y|; if y < 0, p = (1 − |p.yx|) · sgn(p); d = normalize(p.x, y, p.y)
// with sgn(0) = +1. The inner diamond |p.x| + |p.y| ≤ 1 is the upper hemisphere, the four corner
// triangles the lower one; every edge point (u, 1) is the same direction as its mirror (1 − u, 1)
// (likewise on the other edges), and the four corners are all −y.
//
// Seams without a gutter: a sampler clamped to the edge cannot blend a border texel with its
// mirror across the fold. So the texels of the outer ring do not hold their centre's direction
// but the direction of the nearest edge point (their centre pushed onto the edge): a texel and
// its mirror then hold the same value, and the bilinear clamp-to-edge reconstruction is continuous
// across every edge, at every level with one and the same (u, v) (trilinear filtering stays
// valid). The price is a half-texel band along each edge where the map holds still.
#pragma once

#include <vector>

#include "facet/ibl/vec3.h"

namespace facet::ibl {

struct OctahedralImage {
  int size = 0;            // size × size texels
  std::vector<float> rgb;  // size × size × 3, row-major, row 0 at v = 0

  OctahedralImage() = default;
  explicit OctahedralImage(int n) : size(n), rgb(size_t(n) * size_t(n) * 3, 0.0f) {}

  Vec3 texel(int column, int row) const;
  void setTexel(int column, int row, Vec3 value);
};

/// Texture coordinates (u, v) of a direction (need not be unit length, must not be 0).
void octahedralCoordinates(Vec3 direction, double* u, double* v);

/// The unit direction at texture coordinates (u, v) ∈ [0, 1]².
Vec3 octahedralDirection(double u, double v);

/// The direction a texel holds: its centre's, or for the outer ring the nearest edge point's
/// (see the header comment). size ≥ 2.
Vec3 octahedralTexelDirection(int size, int column, int row);

/// Bilinear sample with clamp to edge, as the GPU sampler of the environment does.
Vec3 sampleBilinear(const OctahedralImage& image, double u, double v);

}  // namespace facet::ibl
