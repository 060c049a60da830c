#include "facet/compiler/specular_lut.h"

#include <algorithm>
#include <cmath>

namespace facet::compiler {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Same floor as chunks/precision.glsl: r⁴ ≥ 2^-14 (smallest normal fp16) → r ≥ 0.089.
constexpr double kMinPerceptualRoughness = 0.089;

// ln x for x in (0, 1], from correctly rounded operations only (generateSpecularLut's promise of
// the same bytes everywhere): x^(2^-24) by 24 square roots lies within 6e-7 of 1, where
// ln y = 2 atanh z, z = (y − 1)/(y + 1), is z's series to z³ (the next term is below 1e-32).
// The roots' roundings (1.1e-16 each, near 1) bound the relative error by about 1e-7 for the
// table's x ≥ 1.2e-4: far below a table step.
double logOfUnitInterval(double x) {
  constexpr int kRoots = 24;
  for (int i = 0; i < kRoots; ++i) x = std::sqrt(x);
  const double z = (x - 1.0) / (x + 1.0);
  return 2.0 * (z + z * z * z / 3.0) * double(1 << kRoots);
}

}  // namespace

double specularLutAlbedo(double perceptualRoughness) {
  double r = std::clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0);
  double a2 = r * r * r * r;
  // A = 2π ∫₀¹ S(μ) μ dμ with μ = R·L = n·l (v = n), in t = n·h'² = (1 + μ)/2:
  //   A = ∫_{1/2}^{1} a² (2t − 1) / (k t + 1)² dt,   k = α² − 1,
  //     = a²/k² [2 ln(w₁/w₀) + (2 + k)(1/w₁ − 1/w₀)],   w₀ = 1 + k/2, w₁ = 1 + k = α².
  // At r = 1 (k = 0) D is the constant 1/π and A = ∫ (2t − 1) dt = 1/4; the closed form loses
  // about 2 log10(1/|k|) digits to cancellation as k → 0, a few at the table's last rows.
  double k = a2 - 1.0;
  if (std::abs(k) < 1e-6) return 0.25;
  double w0 = 1.0 + 0.5 * k, w1 = a2;
  return a2 / (k * k) * (2.0 * logOfUnitInterval(w1 / w0) + (2.0 + k) * (1.0 / w1 - 1.0 / w0));
}

double specularLutIntensity(SpecularLutAxis axis, double cosine, double perceptualRoughness) {
  double c = std::clamp(cosine, 0.0, 1.0);
  double r = std::clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0);
  double alpha = r * r;
  double a2 = alpha * alpha;
  // n·h'² from R·L by the half-angle identity cos²(θ/2) = (1 + cos θ)/2, or n·h itself.
  double NoH2 = axis == SpecularLutAxis::ReflectedCosine4 ? 0.5 * (1.0 + c) : c * c;
  double d = NoH2 * (a2 - 1.0) + 1.0;
  double D = a2 / (kPi * d * d);
  return 0.25 * D;  // implicit geometric term: V = G / (4 n·l n·v) with G = n·l n·v
}

SpecularLut generateSpecularLut(const SpecularLutOptions& options) {
  SpecularLut lut;
  lut.width = std::max<uint32_t>(options.width, 2);
  lut.height = std::max<uint32_t>(options.height, 2);
  lut.scale = options.scale;
  lut.encoding = options.encoding;
  lut.texels.resize(size_t{lut.width} * lut.height);
  for (uint32_t j = 0; j < lut.height; ++j) {
    double r = double(j) / double(lut.height - 1);
    for (uint32_t i = 0; i < lut.width; ++i) {
      double u = double(i) / double(lut.width - 1);
      double c = options.axis == SpecularLutAxis::ReflectedCosine4 ? std::sqrt(std::sqrt(u)) : u;
      double s = specularLutIntensity(options.axis, c, r) / options.scale;
      if (options.normalized) s /= specularLutAlbedo(r);
      s = std::clamp(s, 0.0, 1.0);
      double q = std::round(255.0 * (options.encoding == SpecularLutEncoding::Sqrt ? std::sqrt(s) : s));
      lut.texels[size_t{j} * lut.width + i] = static_cast<uint8_t>(q);
    }
  }
  return lut;
}

}  // namespace facet::compiler
