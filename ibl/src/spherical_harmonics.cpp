#include "facet/ibl/spherical_harmonics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "facet/ibl/sphere_quadrature.h"

namespace facet::ibl {
namespace {

// Basis constants K_k (header table), from K_lm = √((2l + 1)/4π · (l − |m|)!/(l + |m|)!) with the
// √2 of real m ≠ 0 terms and the polynomial factors of p_k absorbed.
const double kBasisConstants[kMaxShCoefficients] = {
    0.5 / std::sqrt(kPi),                                                                      // 1
    std::sqrt(3.0 / (4.0 * kPi)), std::sqrt(3.0 / (4.0 * kPi)), std::sqrt(3.0 / (4.0 * kPi)),  // y z x
    std::sqrt(15.0 / (4.0 * kPi)), std::sqrt(15.0 / (4.0 * kPi)),                              // xy yz
    std::sqrt(5.0 / (16.0 * kPi)),                                                             // 3z² − 1
    std::sqrt(15.0 / (4.0 * kPi)), std::sqrt(15.0 / (16.0 * kPi)),                             // xz x² − y²
    // band 3
    0.25 * std::sqrt(35.0 / (2.0 * kPi)), 0.5 * std::sqrt(105.0 / kPi), 0.25 * std::sqrt(21.0 / (2.0 * kPi)),
    0.25 * std::sqrt(7.0 / kPi), 0.25 * std::sqrt(21.0 / (2.0 * kPi)), 0.25 * std::sqrt(105.0 / kPi),
    0.25 * std::sqrt(35.0 / (2.0 * kPi)),
    // band 4
    0.75 * std::sqrt(35.0 / kPi), 0.75 * std::sqrt(35.0 / (2.0 * kPi)), 0.75 * std::sqrt(5.0 / kPi),
    0.75 * std::sqrt(5.0 / (2.0 * kPi)), 3.0 / 16.0 * std::sqrt(1.0 / kPi), 0.75 * std::sqrt(5.0 / (2.0 * kPi)),
    0.375 * std::sqrt(5.0 / kPi), 0.75 * std::sqrt(35.0 / (2.0 * kPi)), 3.0 / 16.0 * std::sqrt(35.0 / kPi)};

// Clamped-cosine convolution factors Â_l (Ramamoorthi & Hanrahan 2001, eq. 8): the cosine lobe's
// own zonal coefficients times √(4π/(2l + 1)); Â_l = 0 for odd l > 1, and
// Â_l = 2π (−1)^(l/2 − 1) / ((l + 2)(l − 1)) · l! / (2^l ((l/2)!)²) for even l ≥ 2 (Â_4 = −π/24).
const double kBandFactors[kMaxShBands] = {kPi, 2.0 * kPi / 3.0, kPi / 4.0, 0.0, -kPi / 24.0};

int bandOf(int k) {
  int l = 0;
  while ((l + 1) * (l + 1) <= k) ++l;
  return l;
}

void checkBands(int bands) {
  if (bands < 1 || bands > kMaxShBands)
    throw std::invalid_argument("spherical harmonics: bands must be 1, 2, 3, 4 or 5");
}

// p_k(d): the polynomial part of Y_k, the same list the shader evaluates (band 3's and 4's in
// their unit-vector forms: x² + y² + z² = 1 folded in).
std::vector<double> basisPolynomials(int bands, Vec3 d) {
  const double x = d.x, y = d.y, z = d.z;
  const double xx = x * x, yy = y * y, zz = z * z;
  const double all[kMaxShCoefficients] = {1.0, y, z, x, x * y, y * z, 3.0 * zz - 1.0, x * z, xx - yy,
                                          // band 3
                                          y * (3.0 * xx - yy), x * y * z, y * (5.0 * zz - 1.0), z * (5.0 * zz - 3.0),
                                          x * (5.0 * zz - 1.0), z * (xx - yy), x * (xx - 3.0 * yy),
                                          // band 4
                                          x * y * (xx - yy), y * z * (3.0 * xx - yy), x * y * (7.0 * zz - 1.0),
                                          y * z * (7.0 * zz - 3.0), 35.0 * zz * zz - 30.0 * zz + 3.0,
                                          x * z * (7.0 * zz - 3.0), (xx - yy) * (7.0 * zz - 1.0),
                                          x * z * (xx - 3.0 * yy), xx * (xx - 3.0 * yy) - yy * (3.0 * xx - yy)};
  return std::vector<double>(all, all + bands * bands);
}

}  // namespace

std::vector<double> shBasis(int bands, Vec3 d) {
  checkBands(bands);
  std::vector<double> y = basisPolynomials(bands, d);
  for (size_t k = 0; k < y.size(); ++k) y[k] *= kBasisConstants[k];
  return y;
}

SphericalHarmonics projectRadiance(const std::function<Vec3(Vec3)>& radiance, int bands, int quadratureOrder) {
  checkBands(bands);
  SphericalHarmonics sh{bands, std::vector<Vec3>(size_t(bands * bands))};
  for (const SphereSample& s : sphereQuadrature(quadratureOrder)) {
    Vec3 L = radiance(s.direction) * s.weight;
    std::vector<double> y = shBasis(bands, s.direction);
    for (size_t k = 0; k < y.size(); ++k) sh.coefficients[k] += L * y[k];
  }
  return sh;
}

SphericalHarmonics projectRadiance(const EquirectImage& image, int bands) {
  checkBands(bands);
  SphericalHarmonics sh{bands, std::vector<Vec3>(size_t(bands * bands))};
  for (int row = 0; row < image.height; ++row) {
    double solidAngle = equirectTexelSolidAngle(image, row);
    for (int column = 0; column < image.width; ++column) {
      Vec3 d = equirectDirection(image, column, row);
      Vec3 L = image.texel(column, row) * solidAngle;
      std::vector<double> y = shBasis(bands, d);
      for (size_t k = 0; k < y.size(); ++k) sh.coefficients[k] += L * y[k];
    }
  }
  return sh;
}

SphericalHarmonics radianceToIrradiance(const SphericalHarmonics& radiance) {
  checkBands(radiance.bands);
  SphericalHarmonics irradiance = radiance;
  for (size_t k = 0; k < irradiance.coefficients.size(); ++k)
    irradiance.coefficients[k] = irradiance.coefficients[k] * kBandFactors[bandOf(int(k))];
  return irradiance;
}

Vec3 evaluateSh(const SphericalHarmonics& sh, Vec3 d) {
  std::vector<double> y = shBasis(sh.bands, d);
  Vec3 sum;
  for (size_t k = 0; k < y.size(); ++k) sum += sh.coefficients[k] * y[k];
  return sum;
}

std::vector<Vec3> shaderIrradianceCoefficients(const SphericalHarmonics& radiance) {
  checkBands(radiance.bands);
  std::vector<Vec3> c(radiance.coefficients.size());
  for (size_t k = 0; k < c.size(); ++k)
    c[k] = radiance.coefficients[k] * (kBandFactors[bandOf(int(k))] * kBasisConstants[k] / kPi);
  return c;
}

Vec3 evaluateShaderIrradiance(const std::vector<Vec3>& coefficients, Vec3 n) {
  int bands = 1;
  while (bands < kMaxShBands && size_t((bands + 1) * (bands + 1)) <= coefficients.size()) ++bands;
  std::vector<double> p = basisPolynomials(bands, n);
  Vec3 sum;
  for (size_t k = 0; k < p.size(); ++k) sum += coefficients[k] * p[k];
  return {std::max(sum.x, 0.0), std::max(sum.y, 0.0), std::max(sum.z, 0.0)};
}

}  // namespace facet::ibl
