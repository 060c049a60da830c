// ibl/sphere_quadrature.h
// A product quadrature over the unit sphere: Gauss–Legendre nodes in z = cos θ times equally
// spaced azimuths. With `order` = N it integrates every spherical polynomial of degree ≤ 2N − 1
// exactly, so projecting a band-limited radiance onto SH is exact (up to rounding) instead of
// converging like a grid; discontinuous radiance still converges, at O(1/N).
#pragma once

#include <vector>

#include "facet/ibl/vec3.h"

namespace facet::ibl {

struct SphereSample {
  Vec3 direction;
  double weight = 0;  // steradians; the weights sum to 4π
};

/// N Gauss–Legendre nodes in z (pole axis +z) × 2N azimuths: 2N² samples. N ≥ 1.
std::vector<SphereSample> sphereQuadrature(int order);

}  // namespace facet::ibl
