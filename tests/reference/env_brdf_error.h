// The error of an analytic environment BRDF against a DFG table, over the table's texel centres
// (tests/ibl/test_ibl.cpp and tools/measure_ibl.cpp report the same numbers).
#pragma once

#include <cmath>
#include <functional>

#include "facet/ibl/dfg_lut.h"

namespace facet::reference {

struct EnvBrdfError {
  double max = 0, mean = 0;
  double atNoV = 0, atRoughness = 0;  // where the max is
};

// fit(n·v, r) against f0 · A + B of the table (f90 = 1), at every texel centre.
inline EnvBrdfError envBrdfError(const ibl::DfgLut& lut, double f0,
                                 const std::function<double(double NoV, double r)>& fit) {
  EnvBrdfError e;
  for (int row = 0; row < lut.size; ++row) {
    double r = ibl::dfgLutRoughness(row, lut.size);
    for (int column = 0; column < lut.size; ++column) {
      double NoV = ibl::dfgLutNoV(column, lut.size);
      double d = std::abs(fit(NoV, r) - ibl::specularEnvironmentBrdf(lut.at(column, row), f0));
      e.mean += d;
      if (d > e.max) e.max = d, e.atNoV = NoV, e.atRoughness = r;
    }
  }
  e.mean /= double(lut.size) * lut.size;
  return e;
}

}  // namespace facet::reference
