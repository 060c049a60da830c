#include "facet/ibl/sheen_lut.h"

#include <algorithm>
#include <cmath>

#include "facet/ibl/dfg_lut.h"

namespace facet::ibl {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

double integrateSheenAlbedo(double NoV, double perceptualRoughness, int steps) {
  NoV = std::clamp(NoV, 1e-4, 1.0);
  const double r = std::clamp(perceptualRoughness, 0.089, 1.0);
  const double alpha = r * r;
  const int muSteps = std::max(steps, 2), phiSteps = std::max(steps / 2, 1);
  const double sinV = std::sqrt(1.0 - NoV * NoV);
  double sum = 0;
  for (int i = 0; i < muSteps; ++i) {
    const double NoL = (i + 0.5) / muSteps;
    const double sinL = std::sqrt(1.0 - NoL * NoL);
    const double weight = NoL * neubeltVisibility(NoV, NoL);
    for (int j = 0; j < phiSteps; ++j) {
      const double phi = (j + 0.5) / phiSteps * kPi;
      // h = (v + l)/|v + l| with v = (sinV, 0, NoV), l = (sinL cos φ, sinL sin φ, NoL).
      const double hx = sinV + sinL * std::cos(phi), hy = sinL * std::sin(phi), hz = NoV + NoL;
      const double NoH = hz / std::sqrt(hx * hx + hy * hy + hz * hz);
      sum += charlieDistribution(alpha, NoH) * weight;
    }
  }
  // dω = d(cos θ_l) dφ over [0, 1] × [0, 2π]; the half azimuth range counted twice.
  return sum * (1.0 / muSteps) * (2.0 * kPi / phiSteps);
}

SheenLut generateSheenLut(int size, int steps) {
  SheenLut lut;
  lut.size = std::max(size, 1);
  lut.albedo.resize(size_t(lut.size) * size_t(lut.size));
  for (int row = 0; row < lut.size; ++row)
    for (int column = 0; column < lut.size; ++column)
      lut.albedo[size_t(row) * size_t(lut.size) + size_t(column)] =
          static_cast<float>(integrateSheenAlbedo(dfgLutNoV(column, lut.size), dfgLutRoughness(row, lut.size), steps));
  return lut;
}

}  // namespace facet::ibl
