#include "facet/compiler/specular_lut.h"

#include <algorithm>
#include <cmath>

namespace facet::compiler {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Same floor as chunks/precision.glsl: r⁴ ≥ 2^-14 (smallest normal fp16) → r ≥ 0.089.
constexpr double kMinPerceptualRoughness = 0.089;

}  // namespace

double specularLutIntensity(SpecularLutAxis axis, double cosine, double perceptualRoughness) {
  double c = std::clamp(cosine, 0.0, 1.0);
  double r = std::clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0);
  double alpha = r * r;
  double a2 = alpha * alpha;
  // n·h'² from R·L by the half-angle identity cos²(θ/2) = (1 + cos θ)/2, or n·h itself.
  double NoH2 = axis == SpecularLutAxis::kReflectedCosine4 ? 0.5 * (1.0 + c) : c * c;
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
      double c = options.axis == SpecularLutAxis::kReflectedCosine4 ? std::sqrt(std::sqrt(u)) : u;
      double s = specularLutIntensity(options.axis, c, r) / options.scale;
      s = std::clamp(s, 0.0, 1.0);
      double q = std::round(255.0 * (options.encoding == SpecularLutEncoding::kSqrt ? std::sqrt(s) : s));
      lut.texels[size_t{j} * lut.width + i] = static_cast<uint8_t>(q);
    }
  }
  return lut;
}

}  // namespace facet::compiler
