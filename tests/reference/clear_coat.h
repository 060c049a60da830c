// Directional albedo of the clear coat layered over a white base, in double, by deterministic
// quadrature: the white furnace of chunks/clear_coat_ggx_kelemen.glsl's form and of Filament's
// per-light attenuation it replaced (docs/material-models.md, "Energy").
#pragma once

#include <cmath>

#include "facet/eval/standard_model.h"

namespace facet::reference {

// How the base under the coat is attenuated for a light: by the view's Fresnel, 1 − Fc(n·v)
// (Facet's), or by the light's half vector, 1 − Fc(l·h) (Filament's mobile form).
enum class CoatAttenuation { View, HalfVector };

// ∫ (f_c + f_base · (1 − Fc)) n·l dω over the hemisphere of l, for a coat of perceptual roughness
// r (strength 1) over a Lambertian white base (albedo exactly 1: the most a base can reflect).
// The coat's part samples h ∝ D(h) n·h on an n × n grid (cos²θ_h by GGX's inverse CDF), where
// f_c n·l / (D n·h) · dω_l/dω_h = Fc(v·h) n·l / (v·h n·h) (Kelemen's V cancels 4 v·h); the base's
// part samples l ∝ n·l / π, where it is the mean of 1 − Fc.
inline double clearCoatLayeredAlbedo(double r, double NoV, CoatAttenuation attenuation, int n = 512) {
  const double alpha = std::clamp(r, 0.089, 1.0) * std::clamp(r, 0.089, 1.0);
  const double vx = std::sqrt(1.0 - NoV * NoV), vz = NoV;
  double coat = 0, base = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      double u = (i + 0.5) / n, phi = 2.0 * kPi * (j + 0.5) / n;
      double cos2 = (1.0 - u) / (1.0 + (alpha * alpha - 1.0) * u), ct = std::sqrt(cos2), st = std::sqrt(1.0 - cos2);
      double hx = st * std::cos(phi), hz = ct;
      double VoH = vx * hx + vz * hz;
      double lz = 2.0 * VoH * hz - vz;
      if (VoH > 0 && lz > 0) coat += fresnelClearCoat(VoH) * lz / (VoH * hz);
      // l cosine-distributed: cos θ_l = √u.
      double cl = std::sqrt(u), sl = std::sqrt(1.0 - u);
      glm::dvec3 l(sl * std::cos(phi), sl * std::sin(phi), cl), v(vx, 0.0, vz);
      double LoH = glm::dot(l, glm::normalize(l + v));
      base += 1.0 - (attenuation == CoatAttenuation::View ? fresnelClearCoat(NoV) : fresnelClearCoat(LoH));
    }
  }
  return (coat + base) / (double(n) * n);
}

}  // namespace facet::reference
