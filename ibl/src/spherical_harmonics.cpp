#include "facet/ibl/spherical_harmonics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "facet/ibl/sphere_quadrature.h"

namespace facet::ibl {
namespace {

// Basis constants K_k (header table), from K_lm = √((2l + 1)/4π · (l − |m|)!/(l + |m|)!) with the
// √2 of real m ≠ 0 terms and the polynomial factors of p_k absorbed.
const double kBasisConstants[9] = {
    0.5 / std::sqrt(kPi),                                                                         // 1
    std::sqrt(3.0 / (4.0 * kPi)),  std::sqrt(3.0 / (4.0 * kPi)),   std::sqrt(3.0 / (4.0 * kPi)),  // y z x
    std::sqrt(15.0 / (4.0 * kPi)), std::sqrt(15.0 / (4.0 * kPi)),                                 // xy yz
    std::sqrt(5.0 / (16.0 * kPi)),                                                                // 3z² − 1
    std::sqrt(15.0 / (4.0 * kPi)), std::sqrt(15.0 / (16.0 * kPi)),                                // xz x² − y²
};

// Clamped-cosine convolution factors Â_l (Ramamoorthi & Hanrahan 2001, eq. 8): the cosine lobe's
// own zonal coefficients times √(4π/(2l + 1)).
const double kBandFactors[3] = {kPi, 2.0 * kPi / 3.0, kPi / 4.0};

int bandOf(int k) { return k == 0 ? 0 : k < 4 ? 1 : 2; }

void checkBands(int bands) {
  if (bands < 1 || bands > 3) throw std::invalid_argument("spherical harmonics: bands must be 1, 2 or 3");
}

// p_k(d): the polynomial part of Y_k, the same list the shader evaluates.
std::vector<double> basisPolynomials(int bands, Vec3 d) {
  const double all[9] = {
      1.0, d.y, d.z, d.x, d.x * d.y, d.y * d.z, 3.0 * d.z * d.z - 1.0, d.x * d.z, d.x * d.x - d.y * d.y};
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
  int bands = coefficients.size() >= 9 ? 3 : coefficients.size() >= 4 ? 2 : 1;
  std::vector<double> p = basisPolynomials(bands, n);
  Vec3 sum;
  for (size_t k = 0; k < p.size(); ++k) sum += coefficients[k] * p[k];
  return {std::max(sum.x, 0.0), std::max(sum.y, 0.0), std::max(sum.z, 0.0)};
}

}  // namespace facet::ibl
