// The sphere test of docs/specular-tiers.md, in double on the CPU: a unit sphere seen by an
// orthographic camera, one directional light, the standard model's diffuse + ambient, and a
// pluggable specular term; tone-mapped (ACES fitted, as chunks/tonemap_aces.glsl), sRGB-encoded
// and quantised to 8 bits. PSNR of a specular form = the same image with the exact
// GGX · Smith (height-correlated) · Schlick specular as the reference, over the sphere's pixels.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "facet/eval/standard_model.h"

namespace facet::reference {

struct ShadingPoint {
  double alpha, perceptualRoughness, f0;
  double NoV, NoL, NoH, LoH, RoL;
};

// Returns the specular BRDF value (f0 and Fresnel included, n·l not included).
using SpecularForm = std::function<double(const ShadingPoint&)>;

inline double specularExactForm(const ShadingPoint& p) {
  double F = p.f0 + (1.0 - p.f0) * std::pow(1.0 - p.LoH, 5.0);
  return distributionGgx(p.alpha, p.NoH) * visibilitySmithGgxCorrelated(p.alpha, p.NoV, p.NoL) * F;
}

struct SphereScene {
  int size = 128;                                                    // pixels per side
  glm::dvec3 light = glm::normalize(glm::dvec3(-0.45, 0.55, 0.70));  // towards the light
  double illuminance = 2.5;  // pre-exposed E (white diffuse at n·l = 1 → 0.4)
  double ambient = 0.05;     // constant ambient radiance, diffuse only
};

struct SphereMaterial {
  double f0;  // 0.04: dielectric with diffuse albedo 0.5; 1.0: metal, no diffuse
  double perceptualRoughness;
  double diffuseAlbedo() const { return f0 >= 1.0 ? 0.0 : 0.5; }
};

inline double tonemapAcesFitted(double x) {
  x = std::clamp(x, 0.0, 160.0);
  return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
inline double srgbFromLinear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c < 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// Display value in [0, 1] per sphere pixel (pixels off the sphere are skipped), unquantised.
inline std::vector<double> renderSphere(const SphereScene& scene, const SphereMaterial& m, const SpecularForm& spec) {
  std::vector<double> out;
  out.reserve(size_t(scene.size) * scene.size);
  glm::dvec3 v(0.0, 0.0, 1.0);
  double r = std::clamp(m.perceptualRoughness, 0.089, 1.0);
  for (int y = 0; y < scene.size; ++y) {
    for (int x = 0; x < scene.size; ++x) {
      double px = (x + 0.5) / scene.size * 2.0 - 1.0, py = 1.0 - (y + 0.5) / scene.size * 2.0;
      double z2 = 1.0 - px * px - py * py;
      if (z2 <= 0.0) continue;
      glm::dvec3 n(px, py, std::sqrt(z2));
      glm::dvec3 l = scene.light;
      glm::dvec3 h = glm::normalize(v + l);
      glm::dvec3 R = 2.0 * glm::dot(n, v) * n - v;
      ShadingPoint p{r * r,
                     r,
                     m.f0,
                     std::max(glm::dot(n, v), 1e-4),
                     std::clamp(glm::dot(n, l), 0.0, 1.0),
                     std::clamp(glm::dot(n, h), 0.0, 1.0),
                     std::clamp(glm::dot(l, h), 0.0, 1.0),
                     glm::dot(R, l)};
      double diffuse = m.diffuseAlbedo();
      double radiance = diffuse * scene.ambient;
      if (p.NoL > 0.0) radiance += (diffuse / kPi + spec(p)) * scene.illuminance * p.NoL;
      out.push_back(srgbFromLinear(tonemapAcesFitted(radiance)));
    }
  }
  return out;
}

inline double quantize8(double c) { return std::round(std::clamp(c, 0.0, 1.0) * 255.0); }

// Sum of squared 8-bit differences and pixel count, to pool several images into one PSNR.
struct SquaredError {
  double sum = 0;
  size_t count = 0;
  void add(const std::vector<double>& a, const std::vector<double>& b, bool quantized = true) {
    for (size_t i = 0; i < a.size(); ++i) {
      double d = quantized ? quantize8(a[i]) - quantize8(b[i]) : 255.0 * (a[i] - b[i]);
      sum += d * d;
    }
    count += a.size();
  }
  double psnr() const {
    double mse = sum / double(count);
    return mse <= 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / mse);
  }
};

}  // namespace facet::reference
