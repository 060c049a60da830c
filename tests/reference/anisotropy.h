// Directional albedo of the anisotropic GGX/Smith lobe (chunks/anisotropy_ggx_smith.glsl), in double,
// by deterministic quadrature: its white furnace (docs/material-models.md, "Anisotropy").
#pragma once

#include <cmath>

#include "facet/eval/standard_model.h"

namespace facet::reference {

// ∫ D_aniso V_aniso n·l dω_l (F = 1) for a view at n·v and azimuth phiV from the tangent, frame
// t = +x, b = +y, n = +z. h is sampled ∝ D(h) n·h on an n × n grid by stretching the slopes of the
// α = 1 GGX (Heitz 2014, §5.3: the slope distribution of the anisotropic GGX is the isotropic one
// scaled by α_t, α_b), so the estimator is f n·l / (D n·h / (4 v·h)) = 4 V n·l v·h / n·h, exact for
// the narrowest lobe (α_b = α_min).
inline double anisotropicAlbedo(glm::dvec2 alpha, double NoV, double phiV, int n = 512) {
  const double sinV = std::sqrt(1.0 - NoV * NoV);
  const glm::dvec3 v(sinV * std::cos(phiV), sinV * std::sin(phiV), NoV);
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    double u = (i + 0.5) / n, r = std::sqrt(u / (1.0 - u));
    for (int j = 0; j < n; ++j) {
      double phi = 2.0 * kPi * (j + 0.5) / n;
      glm::dvec3 h = glm::normalize(glm::dvec3(-alpha.x * r * std::cos(phi), -alpha.y * r * std::sin(phi), 1.0));
      double VoH = glm::dot(v, h);
      if (VoH <= 0) continue;
      glm::dvec3 l = 2.0 * VoH * h - v;
      if (l.z <= 0) continue;
      double V = visibilitySmithGgxCorrelatedAnisotropic(alpha.x, alpha.y, v.x, v.y, NoV, l.x, l.y, l.z);
      sum += 4.0 * V * l.z * VoH / h.z;
    }
  }
  return sum / (double(n) * n);
}

}  // namespace facet::reference
