// Brute-force references for the IBL integrals of facet_ibl (ibl/), sharing no code with it:
// deterministic midpoint grids over the hemisphere in double, no importance sampling. Slow, and
// exact to ~1e-5 for α ≥ 0.06 (r ≥ 0.25) at the default resolution — the ground truth the
// sampled generators are checked against (tests/ibl/test_ibl.cpp, tools/measure_env_brdf.cpp).
#pragma once

#include <cmath>

#include "facet/eval/standard_model.h"

namespace facet::reference {

struct DfgByGrid {
  double fresnelWeighted = 0;  // ∫ D V (1 − v·h)⁵ n·l dl
  double albedo = 0;           // ∫ D V n·l dl
};

// l = (sin θ cos φ, sin θ sin φ, cos θ) on a thetaSteps × 2·thetaSteps grid over θ ∈ [0, π/2],
// φ ∈ [0, π] (the integrand is even in φ with v in the xz plane, so the other half doubles it).
// Uniform in θ rather than cos θ keeps the cells small both at the pole (lobe at n·v = 1) and at
// the horizon (lobe at grazing view).
inline DfgByGrid integrateDfgByGrid(double NoV, double perceptualRoughness, int thetaSteps = 1024) {
  double alpha = perceptualRoughness * perceptualRoughness;
  double vx = std::sqrt(1.0 - NoV * NoV), vz = NoV;
  int phiSteps = 2 * thetaSteps;
  double dTheta = 0.5 * kPi / thetaSteps, dPhi = kPi / phiSteps;
  DfgByGrid sum;
  for (int i = 0; i < thetaSteps; ++i) {
    double theta = (i + 0.5) * dTheta;
    double NoL = std::cos(theta), sinTheta = std::sin(theta);
    double V = visibilitySmithGgxCorrelated(alpha, NoV, NoL);
    double cell = 2.0 * sinTheta * dTheta * dPhi;  // dω, doubled for φ ∈ [π, 2π]
    for (int j = 0; j < phiSteps; ++j) {
      double phi = (j + 0.5) * dPhi;
      double lx = sinTheta * std::cos(phi), ly = sinTheta * std::sin(phi);
      double hx = lx + vx, hy = ly, hz = NoL + vz;
      double hl = std::sqrt(hx * hx + hy * hy + hz * hz);
      double NoH = hz / hl, VoH = (vx * hx + vz * hz) / hl;
      double f = distributionGgx(alpha, NoH) * V * NoL * cell;
      double m = 1.0 - VoH, Fc = m * m * m * m * m;
      sum.albedo += f;
      sum.fresnelWeighted += f * Fc;
    }
  }
  return sum;
}

}  // namespace facet::reference
