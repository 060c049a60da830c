// Brute-force irradiance and the test sky of the SH checks (tests/ibl/test_ibl.cpp,
// tools/measure_ibl.cpp): E(n) = ∫ L(d) max(0, n·d) dω on a midpoint grid over the hemisphere
// around n, in double, sharing no code with facet_ibl.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "facet/eval/standard_model.h"

namespace facet::reference {

// θ from n uniform on thetaSteps rows, φ on 2·thetaSteps columns.
template <class Radiance>
glm::dvec3 irradianceByGrid(const Radiance& radiance, glm::dvec3 n, int thetaSteps = 512) {
  glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  glm::dvec3 t = glm::normalize(glm::cross(helper, n));
  glm::dvec3 b = glm::cross(n, t);
  int phiSteps = 2 * thetaSteps;
  double dTheta = 0.5 * kPi / thetaSteps, dPhi = 2.0 * kPi / phiSteps;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < thetaSteps; ++i) {
    double theta = (i + 0.5) * dTheta;
    double c = std::cos(theta), s = std::sin(theta);
    for (int j = 0; j < phiSteps; ++j) {
      double phi = (j + 0.5) * dPhi;
      glm::dvec3 d = s * std::cos(phi) * t + s * std::sin(phi) * b + c * n;
      sum += radiance(d) * (c * s * dTheta * dPhi);
    }
  }
  return sum;
}

// Point i of `count` spread evenly over the sphere (Fibonacci spiral): the normals the SH checks
// are evaluated at.
inline glm::dvec3 fibonacciSphere(int i, int count) {
  double z = 1.0 - 2.0 * (i + 0.5) / count, s = std::sqrt(1.0 - z * z);
  double phi = i * kPi * (3.0 - std::sqrt(5.0));  // the golden angle
  return {s * std::cos(phi), s * std::sin(phi), z};
}

// A dim sky with a sun-sized bright cap: radiance 1 (blue-ish) everywhere, plus 100 inside 10°
// of `kCapAxis`. A hard edge, and 43 % of the energy in 0.76 % of the sphere: the case SH handles
// worst (Filament's talk shows SH ringing with a bright sun).
inline const glm::dvec3 kCapAxis = glm::normalize(glm::dvec3(0.3, 0.8, 0.5));
inline glm::dvec3 capSkyRadiance(glm::dvec3 d) {
  glm::dvec3 sky(0.6, 0.8, 1.0);
  return glm::dot(d, kCapAxis) > std::cos(10.0 * kPi / 180.0) ? sky + glm::dvec3(100.0, 95.0, 90.0) : sky;
}

}  // namespace facet::reference
