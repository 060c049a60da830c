// The split-sum DFG table as the shaders read it, for tests that predict rendered pixels: bilinear
// between texel centres at (i + 0.5)/size, clamped at the edges (docs/ibl.md), from the float table
// the runtime uploads as RG16F (runtime::dfgTable).
#pragma once

#include <utility>

#include "facet/runtime/environment.h"

namespace facet::test {

// (B, A + B) at (n·v, perceptual roughness): the f90 term and the directional albedo.
inline std::pair<double, double> dfgBilinear(double NoV, double roughness) {
  ibl::DfgTerms d = runtime::dfgTable().sampleBilinear(NoV, roughness);
  return {d.fresnelWeighted, d.albedo};
}

}  // namespace facet::test
