#pragma once

#include "facet/render_backend.h"

namespace facet::runtime {

// A unit sphere centred at the origin, latitude/longitude tessellated, outward normals, uv0 =
// (longitude, latitude) in [0, 1]. With 64 × 128 segments the flat facets sit at most
// 1 − cos(π/128) ≈ 3e-4 of the radius inside the true sphere.
Mesh makeSphere(int rings = 64, int segments = 128);

}  // namespace facet::runtime
