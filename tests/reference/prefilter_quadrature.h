// What a prefiltered environment level should hold, by brute force (tests/ibl/test_ibl.cpp,
// tools/measure_ibl.cpp), sharing no code with facet_ibl.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "facet/eval/standard_model.h"

namespace facet::reference {

// The limit of Karis's estimator Σ L(l) n·l / Σ n·l with l drawn from pdf(l) = D/4 (n = v = r):
//   ∫ L(l) D(h) n·l dl / ∫ D(h) n·l dl   over the hemisphere of n, h = normalize(n + l).
// Midpoint grid uniform in θ (from n) and φ.
template <class Radiance>
glm::dvec3 ggxLobeAverageByGrid(const Radiance& radiance, glm::dvec3 n, double alpha, int thetaSteps = 512) {
  glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  glm::dvec3 t = glm::normalize(glm::cross(helper, n)), b = glm::cross(n, t);
  int phiSteps = 2 * thetaSteps;
  double dTheta = 0.5 * kPi / thetaSteps, dPhi = 2.0 * kPi / phiSteps;
  glm::dvec3 sum(0.0);
  double weight = 0;
  for (int i = 0; i < thetaSteps; ++i) {
    double theta = (i + 0.5) * dTheta, c = std::cos(theta), s = std::sin(theta);
    double NoH = std::sqrt(0.5 * (1.0 + c));  // h halfway between n and l: cos(θ/2)
    double w = distributionGgx(alpha, NoH) * c * s;
    for (int j = 0; j < phiSteps; ++j) {
      double phi = (j + 0.5) * dPhi;
      sum += radiance(s * std::cos(phi) * t + s * std::sin(phi) * b + c * n) * w;
      weight += w;
    }
  }
  return sum / weight;
}

}  // namespace facet::reference
