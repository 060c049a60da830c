#include "facet/runtime/color_grading.h"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

#include "facet/runtime/environment.h"

namespace facet::runtime {
namespace {

// Row-major literals as glm's column-major matrices.
glm::dmat3 rows(double a, double b, double c, double d, double e, double f, double g, double h, double i) {
  return glm::transpose(glm::dmat3(a, b, c, d, e, f, g, h, i));
}

// Linear sRGB (Rec.709 primaries, D65) to CIE XYZ: IEC 61966-2-1.
const glm::dmat3 kRgbToXyz =
    rows(0.4124564, 0.3575761, 0.1804375, 0.2126729, 0.7151522, 0.0721750, 0.0193339, 0.1191920, 0.9503041);
// XYZ to the Bradford "cone" space (Lam 1985).
const glm::dmat3 kBradford = rows(0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296);
constexpr double kD65x = 0.31271, kD65y = 0.32902;

// CIE daylight locus, y as a function of x (CIE 15:2004, eq. 3.3), used for its slope only: the
// shifted white stays as far off the locus as D65 is.
double daylightLocusY(double x) { return -3.0 * x * x + 2.87 * x - 0.275; }

glm::dvec3 whiteXyz(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// The linear-RGB matrix adapting colours seen under the white (temperature, tint) to D65.
glm::dmat3 whiteBalance(double temperature, double tint) {
  const double x = kD65x - temperature * (temperature < 0 ? 0.1 : 0.05);
  const double y = kD65y + (daylightLocusY(x) - daylightLocusY(kD65x)) + tint * 0.05;
  const glm::dvec3 source = kBradford * whiteXyz(x, y);
  const glm::dvec3 target = kBradford * whiteXyz(kD65x, kD65y);
  glm::dmat3 scale(1.0);
  for (int i = 0; i < 3; ++i) scale[i][i] = target[i] / source[i];
  return glm::inverse(kRgbToXyz) * glm::inverse(kBradford) * scale * kBradford * kRgbToXyz;
}

double decodeSrgb(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double encodeSrgb(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

}  // namespace

ColorLut buildColorLut(const ColorGradingSettings& s, uint32_t size) {
  size = std::clamp<uint32_t>(size, 2, kMaxCubeLutSize);
  const glm::dmat3 balance = whiteBalance(s.temperature, s.tint);
  const bool balanced = s.temperature != 0 || s.tint != 0;
  ColorLut lut;
  lut.size = size;
  lut.rgb.resize(size_t(size) * size * size * 3);
  float* out = lut.rgb.data();
  for (uint32_t b = 0; b < size; ++b)
    for (uint32_t g = 0; g < size; ++g)
      for (uint32_t r = 0; r < size; ++r) {
        const double step = 1.0 / double(size - 1);
        glm::dvec3 c(decodeSrgb(r * step), decodeSrgb(g * step), decodeSrgb(b * step));
        if (balanced) c = balance * c;
        for (int i = 0; i < 3; ++i) {
          double v = s.gain[i] * (c[i] + s.lift[i] * (1.0 - c[i]));
          if (s.gamma[i] != 1) v = std::pow(std::max(v, 0.0), 1.0 / s.gamma[i]);
          if (s.contrast != 1) v = 0.18 * std::pow(std::max(v, 0.0) / 0.18, s.contrast);
          c[i] = v;
        }
        const double luminance = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
        if (s.saturation != 1) c = glm::dvec3(luminance) + s.saturation * (c - glm::dvec3(luminance));
        for (int i = 0; i < 3; ++i) *out++ = float(encodeSrgb(c[i]));
      }
  return lut;
}

std::array<float, 3> sampleColorLut(const ColorLut& lut, const std::array<float, 3>& rgb) {
  const uint32_t n = lut.size;
  uint32_t i0[3];
  double f[3];
  for (int c = 0; c < 3; ++c) {
    const double range = double(lut.domainMax[c]) - double(lut.domainMin[c]);
    const double u = std::clamp((double(rgb[c]) - lut.domainMin[c]) / range, 0.0, 1.0) * double(n - 1);
    i0[c] = std::min(uint32_t(u), n - 2);
    f[c] = u - double(i0[c]);
  }
  std::array<double, 3> sum{0, 0, 0};
  for (uint32_t corner = 0; corner < 8; ++corner) {
    double weight = 1;
    size_t index = 0;
    for (int c = 2; c >= 0; --c) {
      const uint32_t up = (corner >> c) & 1u;
      weight *= up ? f[c] : 1.0 - f[c];
      index = index * n + i0[c] + up;
    }
    if (weight == 0) continue;
    for (int c = 0; c < 3; ++c) sum[c] += weight * lut.rgb[index * 3 + size_t(c)];
  }
  return {float(sum[0]), float(sum[1]), float(sum[2])};
}

ColorLut resampleColorLut(const ColorLut& lut, uint32_t size) {
  const bool unitDomain =
      lut.domainMin == std::array<float, 3>{0, 0, 0} && lut.domainMax == std::array<float, 3>{1, 1, 1};
  if (lut.size == size && unitDomain) return lut;
  ColorLut out;
  out.size = size;
  out.title = lut.title;
  out.rgb.reserve(size_t(size) * size * size * 3);
  for (uint32_t b = 0; b < size; ++b)
    for (uint32_t g = 0; g < size; ++g)
      for (uint32_t r = 0; r < size; ++r) {
        const float step = 1.0f / float(size - 1);
        const std::array<float, 3> v = sampleColorLut(lut, {float(r) * step, float(g) * step, float(b) * step});
        out.rgb.insert(out.rgb.end(), v.begin(), v.end());
      }
  return out;
}

ColorLutTexels colorLutTexels(const ColorLut& lut) {
  const ColorLut sized = resampleColorLut(lut, abi::kColorLutSize);
  ColorLutTexels texels;
  const size_t entries = sized.rgb.size() / 3;
  texels.rgba.resize(entries * 4);
  for (size_t i = 0; i < entries; ++i) {
    for (size_t c = 0; c < 3; ++c) texels.rgba[i * 4 + c] = floatToHalf(sized.rgb[i * 3 + c]);
    texels.rgba[i * 4 + 3] = floatToHalf(1.0f);
  }
  return texels;
}

}  // namespace facet::runtime
