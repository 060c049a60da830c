#pragma once

#include <algorithm>

namespace facet::ibl {

/// One axis of a bilinear, clamp-to-edge read of a table whose `size` texel centres sit at
/// (i + 0.5) / size, as a GPU sampler reads it: the two texels blended at u ∈ [0, 1] and the
/// second one's weight. Below the first centre and above the last the edge texel is held (the
/// weight is 0), which is what the table builders' edge handling must account for.
struct BilinearAxis {
  int i0 = 0, i1 = 0;
  double t = 0.0;
};

inline BilinearAxis bilinearAxis(double u, int size) {
  const double x = std::clamp(u * size - 0.5, 0.0, double(size - 1));
  BilinearAxis axis;
  axis.i0 = int(x);
  axis.i1 = std::min(axis.i0 + 1, size - 1);
  axis.t = x - axis.i0;
  return axis;
}

}  // namespace facet::ibl
