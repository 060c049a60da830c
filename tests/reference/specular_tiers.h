// Double-precision CPU evaluation of the specular forms of the GPU tiers (chunks/brdf_ggx_fastv.glsl,
// chunks/specular_fused_hammon.glsl, chunks/specular_zioma.glsl, chunks/specular_lut.glsl), from the same formulas (not
// the same code), plus the directional albedo (white furnace) integral used to check energy. The exact model they are
// measured against is in standard_model.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "facet/eval/standard_model.h"

namespace facet::reference {

// Hammon 2017 (GDC, "PBR Diffuse Lighting for GGX+Smith Microsurfaces"), the square-root-free
// height-correlated Smith V used on Filament's mobile path: V = 0.5 / lerp(2 n·l n·v, n·l + n·v, α).
inline double visibilityHammon(double alpha, double NoV, double NoL) {
  double a = 2.0 * NoL * NoV;
  double b = NoL + NoV;
  return 0.5 / (a + (b - a) * alpha);
}

// Zioma's fused form, GGX D × V·F with f0 applied by the caller:
//   spec = α² / (4π d² · max(LoH², loH2Min) · (roughScale · ρ + roughBias)),  d = NoH²(α² − 1) + 1
// where ρ = α (Unity URP / BRDF2 as shipped) or ρ = perceptual r (the talk's slide).
struct ZiomaCoefficients {
  double loH2Min;
  double roughScale;
  double roughBias;
  bool perceptualInFactor = false;  // ρ = r instead of α
};
// As published and shipped (URP "minimalist Cook-Torrance"): max(LoH², 0.1) · (α + 0.5).
inline constexpr ZiomaCoefficients kZiomaPublished{0.1, 1.0, 0.5, false};
// The talk's slide: (r + 0.5) with perceptual r, no LoH² floor (kept here only to measure it).
inline constexpr ZiomaCoefficients kZiomaTalk{0.0, 1.0, 0.5, true};
// Facet's refit (tools/fit_zioma.cpp; procedure and numbers in docs/specular-tiers.md).
inline constexpr ZiomaCoefficients kZiomaFacet{0.15, -0.3125, 1.0082, false};

inline double specularZioma(const ZiomaCoefficients& k, double alpha, double NoH, double LoH) {
  double a2 = alpha * alpha;
  double d = NoH * NoH * (a2 - 1.0) + 1.0;
  double rho = k.perceptualInFactor ? std::sqrt(alpha) : alpha;
  double vf = std::max(LoH * LoH, k.loH2Min) * (k.roughScale * rho + k.roughBias);
  return a2 / (4.0 * kPi * d * d * vf);
}

// The mid tier's fused lobe (chunks/specular_fused_hammon.glsl) without f0: GGX D × Hammon's V,
// with the chunk's floor of 2^-12 on lerp(2 n·l n·v, n·l + n·v, α).
inline double specularFusedHammon(double alpha, double NoV, double NoL, double NoH) {
  double a = 2.0 * NoL * NoV;
  double m = std::max(a + (NoL + NoV - a) * alpha, 1.0 / 4096.0);
  return distributionGgx(alpha, NoH) * 0.5 / m;
}

// The exact single-scattering specular the tiers approximate, without f0 split out.
inline double specularExact(double alpha, double NoV, double NoL, double NoH, double LoH, double f0) {
  double F = f0 + (1.0 - f0) * std::pow(1.0 - LoH, 5.0);
  return distributionGgx(alpha, NoH) * visibilitySmithGgxCorrelated(alpha, NoV, NoL) * F;
}

// Directional albedo ∫ f(v, l) n·l dω_l of a specular BRDF over the hemisphere, for a BRDF of
// the form f = D_GGX(α, n·h) · g(n·v, n·l, n·h, l·h). Quadrature: h importance-sampled from
// D(h) n·h on a Hammersley set (deterministic), l = reflect(−v, h), pdf(l) = D n·h / (4 v·h), so
// each sample weighs g · n·l · 4 v·h / n·h — bounded and smooth even for α = 0.089²,
// where uniform sampling would miss the lobe. `gOverD` returns f / D.
template <class GOverD>
double directionalAlbedo(double alpha, double NoV, GOverD gOverD, int samples = 2048) {
  double sinV = std::sqrt(std::max(0.0, 1.0 - NoV * NoV));
  double vx = sinV, vz = NoV;  // v in the xz plane, n = +z
  double a2 = alpha * alpha;
  double sum = 0.0;
  for (int i = 0; i < samples; ++i) {
    double xi1 = (i + 0.5) / samples;
    // Radical inverse in base 2 (Van der Corput), the second Hammersley coordinate.
    uint32_t bits = static_cast<uint32_t>(i);
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    double xi2 = double(bits) * 2.3283064365386963e-10;
    double cosH = std::sqrt((1.0 - xi1) / (1.0 + (a2 - 1.0) * xi1));
    double sinH = std::sqrt(std::max(0.0, 1.0 - cosH * cosH));
    double phi = 2.0 * kPi * xi2;
    double hx = sinH * std::cos(phi), hz = cosH;  // h_y does not enter v·h, n·l, n·h (v, n in xz)
    double VoH = vx * hx + vz * hz;
    if (VoH <= 0.0) continue;
    double lz = 2.0 * VoH * hz - vz;  // l = 2 (v·h) h − v
    if (lz <= 0.0) continue;
    double NoL = lz, NoH = hz, LoH = VoH;
    sum += gOverD(NoV, NoL, NoH, LoH) * NoL * 4.0 * VoH / NoH;
  }
  return sum / samples;
}

inline double albedoExact(double alpha, double NoV, double f0, int samples = 2048) {
  return directionalAlbedo(
      alpha, NoV,
      [&](double nv, double nl, double, double lh) {
        double F = f0 + (1.0 - f0) * std::pow(1.0 - lh, 5.0);
        return visibilitySmithGgxCorrelated(alpha, nv, nl) * F;
      },
      samples);
}

inline double albedoHammon(double alpha, double NoV, double f0, int samples = 2048) {
  return directionalAlbedo(
      alpha, NoV,
      [&](double nv, double nl, double, double lh) {
        double F = f0 + (1.0 - f0) * std::pow(1.0 - lh, 5.0);
        return visibilityHammon(alpha, nv, nl) * F;
      },
      samples);
}

// Zioma's spec / D = 1 / (4 · max(LoH², m) · (s ρ + b)), times f0.
inline double albedoZioma(const ZiomaCoefficients& k, double alpha, double NoV, double f0, int samples = 2048) {
  double rho = k.perceptualInFactor ? std::sqrt(alpha) : alpha;
  double factor = k.roughScale * rho + k.roughBias;
  return directionalAlbedo(
      alpha, NoV, [&](double, double, double, double lh) { return f0 / (4.0 * std::max(lh * lh, k.loH2Min) * factor); },
      samples);
}

// The fused lobe's spec / D = 0.5 / max(lerp(2 n·l n·v, n·l + n·v, α), 2^-12), times f0.
inline double albedoFusedHammon(double alpha, double NoV, double f0, int samples = 2048) {
  return directionalAlbedo(
      alpha, NoV,
      [&](double nv, double nl, double, double) {
        double a = 2.0 * nl * nv;
        return f0 * 0.5 / std::max(a + (nl + nv - a) * alpha, 1.0 / 4096.0);
      },
      samples);
}

// Bilinear sample of an R8 table as the GPU does it (clamp to edge, texel centres at
// (i + 0.5)/W), in double: the CPU twin of textureLod(lut, uv, 0.0).r.
inline double sampleR8Bilinear(const std::vector<uint8_t>& texels, uint32_t width, uint32_t height, double u,
                               double v) {
  auto texel = [&](int i, int j) {
    i = std::clamp(i, 0, int(width) - 1);
    j = std::clamp(j, 0, int(height) - 1);
    return texels[size_t(j) * width + size_t(i)] / 255.0;
  };
  double x = u * width - 0.5, y = v * height - 0.5;
  double x0 = std::floor(x), y0 = std::floor(y);
  double fx = x - x0, fy = y - y0;
  int i0 = int(x0), j0 = int(y0);
  double top = texel(i0, j0) * (1 - fx) + texel(i0 + 1, j0) * fx;
  double bottom = texel(i0, j0 + 1) * (1 - fx) + texel(i0 + 1, j0 + 1) * fx;
  return top * (1 - fy) + bottom * fy;
}

// The coordinate chunks/specular_lut.glsl samples for a table coordinate t ∈ [0, 1] on an axis
// of n texels: t·(n − 1)/n + 0.5/n, so t = 0 and t = 1 land on the first and last texel centres.
inline double lutTexelCoordinate(double t, uint32_t n) { return t * (n - 1.0) / n + 0.5 / n; }

}  // namespace facet::reference
