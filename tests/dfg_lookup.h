// The split-sum DFG table as the shaders read it, for tests that predict rendered pixels: bilinear
// between texel centres at (i + 0.5)/size, clamped at the edges (docs/ibl.md), from the float table
// the runtime uploads as RG16F (runtime::dfgTable).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "facet/runtime/environment.h"

namespace facet::test {

// (B, A + B) at (n·v, perceptual roughness): the f90 term and the directional albedo.
inline std::pair<double, double> dfgBilinear(double NoV, double roughness) {
  const auto& t = runtime::dfgTable();
  auto coordinate = [&](double u, int* i0, int* i1, double* w) {
    double x = std::clamp(u * t.size - 0.5, 0.0, double(t.size - 1));
    *i0 = int(std::floor(x));
    *i1 = std::min(*i0 + 1, t.size - 1);
    *w = x - *i0;
  };
  int c0, c1, r0, r1;
  double wc, wr;
  coordinate(NoV, &c0, &c1, &wc);
  coordinate(roughness, &r0, &r1, &wr);
  auto at = [&](int c, int r, int ch) { return double(t.texels[(size_t(r) * size_t(t.size) + size_t(c)) * 2 + size_t(ch)]); };
  auto lerp2 = [&](int ch) {
    return (at(c0, r0, ch) * (1 - wc) + at(c1, r0, ch) * wc) * (1 - wr) +
           (at(c0, r1, ch) * (1 - wc) + at(c1, r1, ch) * wc) * wr;
  };
  return {lerp2(0), lerp2(1)};
}

}  // namespace facet::test
