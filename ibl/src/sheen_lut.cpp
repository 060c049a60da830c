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

double sheenLutNoV(int column, int size) {
  if (column < 0) return 1e-4;  // MIN_N_DOT_V: the shaders floor n·v there
  if (column >= size) return 1.0;
  return dfgLutNoV(column, size);
}

double sheenLutRoughness(int row, int size) {
  if (row < 0) return 0.0;  // integrateSheenAlbedo clamps it to 0.089, as the shaders do
  if (row >= size) return 1.0;
  return dfgLutRoughness(row, size);
}

SheenLut generateSheenLut(int size, int steps) {
  SheenLut lut;
  lut.size = std::max(size, 1);
  const int nodes = lut.size + 2;
  lut.albedo.resize(size_t(nodes) * size_t(nodes));
  for (int row = -1; row <= lut.size; ++row)
    for (int column = -1; column <= lut.size; ++column)
      lut.albedo[size_t(row + 1) * size_t(nodes) + size_t(column + 1)] = static_cast<float>(
          integrateSheenAlbedo(sheenLutNoV(column, lut.size), sheenLutRoughness(row, lut.size), steps));
  return lut;
}

SheenTerms sheenTexelTerms(const SheenLut& lut, int column, int row) {
  // s: the largest E over the 3 × 3 nodes around the texel (its footprint's corners).
  double footprint = 0;
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc) footprint = std::max(footprint, lut.at(column + dc, row + dr));
  // min(E, 1): the texel's own E, or on an edge the largest over the strip clamp-to-edge gives it
  // alone (column 0 down to MIN_N_DOT_V, the last column to n·v = 1, the last row to r = 1).
  const int c0 = column == 0 ? -1 : column, c1 = column == lut.size - 1 ? lut.size : column;
  const int r0 = row == 0 ? -1 : row, r1 = row == lut.size - 1 ? lut.size : row;
  double held = 0;
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) held = std::max(held, lut.at(c, r));
  return {correctedSheen(held).albedo, correctedSheen(footprint).scale};
}

}  // namespace facet::ibl
