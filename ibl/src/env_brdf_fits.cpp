#include "facet/ibl/env_brdf_fits.h"

#include <algorithm>
#include <cmath>

namespace facet::ibl {

EnvBrdfTerms envBrdfKaris(double NoV, double perceptualRoughness) {
  double r = perceptualRoughness;
  double kx = -1.0 * r + 1.0;
  double ky = -0.0275 * r + 0.0425;
  double kz = -0.572 * r + 1.04;
  double kw = 0.022 * r - 0.04;
  double s = std::min(kx * kx, std::exp2(-9.28 * NoV)) * kx + ky;
  return {-1.04 * s + kz, 1.04 * s + kw};
}

EnvBrdfTerms envBrdfZioma(double NoV, double perceptualRoughness) {
  double m = 1.0 - std::max(perceptualRoughness, NoV);
  return {1.0, m * m * m};
}

double envBrdfZiomaSaturated(double f0, double NoV, double perceptualRoughness) {
  return std::min(envBrdfZioma(NoV, perceptualRoughness).apply(f0), 1.0);
}

}  // namespace facet::ibl
