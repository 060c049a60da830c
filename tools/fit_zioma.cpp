// tools/fit_zioma.cpp — offline fit of Facet's one-division Zioma specular (chunks/specular_zioma.glsl).
//
// Form (the shipped structure, coefficients free):
//   spec = α² / (4π d² · max(LoH², m) · (p α + q)) · f0,   d = NoH²(α² − 1) + 1
// Constraint: directional albedo ≤ 0.995 for f0 = 1, for every NoV and roughness of a grid (the
// 0.5 % margin covers the quadrature error and grid points in between; tests/compiler/test_chunks.cpp checks
// ≤ 1 on a finer grid). The albedo is A_m(α, NoV) / (p α + q), with A_m the integral of
// D n·l / (4 max(LoH², m)), so for a given m the constraint is linear: p αᵢ + q ≥ maxᵥ A_m(αᵢ, v) / 0.995.
// Objective: squared error of the tone-mapped sRGB value against the exact GGX · Smith-correlated ·
// Schlick model, pooled over sphere images (reference/specular_sphere.h) with 9 light directions
// (the view axis, a ring at 50° and a ring at 100° from it, 4 each), f0 ∈ {0.04, 1} and perceptual
// roughness 0.1 … 1.0. Search: for each m on a grid and each p on a grid, q = the smallest value
// the constraint allows and a golden-section search above it; then the same on a 4× finer grid
// around the best point. Deterministic; prints the best coefficients and their numbers.
//
// Usage: fit_zioma            (a few minutes)
#include <cstdio>
#include <vector>

#include "reference/specular_sphere.h"
#include "reference/specular_tiers.h"

using namespace facet::reference;

namespace {

const std::vector<double> kRoughness = [] {
  std::vector<double> r{0.089};
  for (int i = 2; i <= 20; ++i) r.push_back(0.05 * i);
  return r;
}();
const std::vector<double> kNoV{1e-4, 0.01, 0.03, 0.06, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
constexpr double kAlbedoBound = 0.995;

// maxᵥ A_m(α, NoV) per roughness of kRoughness.
std::vector<double> albedoNumerators(double m) {
  std::vector<double> out;
  for (double r : kRoughness) {
    double alpha = r * r, worst = 0.0;
    for (double NoV : kNoV) worst = std::max(worst, albedoZioma(ZiomaCoefficients{m, 0.0, 1.0}, alpha, NoV, 1.0, 1024));
    out.push_back(worst);
  }
  return out;
}

struct Scenes {
  std::vector<SphereScene> scenes;
  std::vector<SphereMaterial> materials;
  std::vector<std::vector<double>> reference;  // per (scene, material)
};

Scenes makeScenes() {
  Scenes s;
  // 9 light directions over the sphere of directions seen from the camera (+z): the view axis,
  // 4 at 50° from it and 4 at 100° (grazing and back-lit rims), azimuths 45° apart between rings.
  std::vector<glm::dvec3> lights{glm::dvec3(0, 0, 1)};
  for (int ring = 0; ring < 2; ++ring)
    for (int k = 0; k < 4; ++k) {
      double theta = (ring == 0 ? 50.0 : 100.0) * kPi / 180.0, phi = (90.0 * k + 45.0 * ring + 20.0) * kPi / 180.0;
      lights.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  for (glm::dvec3 l : lights) {
    SphereScene scene;
    scene.size = 48;
    scene.light = glm::normalize(l);
    s.scenes.push_back(scene);
  }
  for (double f0 : {0.04, 1.0})
    for (int i = 1; i <= 10; ++i) s.materials.push_back({f0, 0.1 * i});
  for (const auto& scene : s.scenes)
    for (const auto& m : s.materials) s.reference.push_back(renderSphere(scene, m, specularExactForm));
  return s;
}

double error(const Scenes& s, const ZiomaCoefficients& k) {
  SquaredError e;
  size_t idx = 0;
  for (const auto& scene : s.scenes)
    for (const auto& m : s.materials) {
      auto img =
          renderSphere(scene, m, [&](const ShadingPoint& p) { return specularZioma(k, p.alpha, p.NoH, p.LoH) * p.f0; });
      e.add(img, s.reference[idx++], false);
    }
  return e.sum / double(e.count);
}

struct Best {
  ZiomaCoefficients k{0, 0, 0};
  double mse = INFINITY;
};

void search(const Scenes& s, double m0, double m1, double dm, double p0, double p1, double dp, Best* best) {
  for (double m = m0; m <= m1 + 1e-12; m += dm) {
    if (m < 0) continue;
    std::vector<double> A = albedoNumerators(m);
    for (double p = p0; p <= p1 + 1e-12; p += dp) {
      double qMin = 0.0;
      for (size_t i = 0; i < kRoughness.size(); ++i) {
        double alpha = kRoughness[i] * kRoughness[i];
        qMin = std::max(qMin, A[i] / kAlbedoBound - p * alpha);
      }
      // Golden-section search of q in [qMin, qMin + 1.5].
      double a = qMin, b = qMin + 1.5;
      const double g = 0.5 * (std::sqrt(5.0) - 1.0);
      double c = b - g * (b - a), d = a + g * (b - a);
      double fc = error(s, {m, p, c}), fd = error(s, {m, p, d});
      for (int it = 0; it < 18; ++it) {
        if (fc < fd) {
          b = d;
          d = c;
          fd = fc;
          c = b - g * (b - a);
          fc = error(s, {m, p, c});
        } else {
          a = c;
          c = d;
          fc = fd;
          d = a + g * (b - a);
          fd = error(s, {m, p, d});
        }
      }
      double q = fc < fd ? c : d, f = std::min(fc, fd);
      if (f < best->mse) *best = {{m, p, q}, f};
    }
  }
}

double maxAlbedo(const ZiomaCoefficients& k, double* atR, double* atNoV) {
  double worst = 0.0;
  for (int i = 0; i <= 40; ++i) {
    double r = 0.089 + (1.0 - 0.089) * i / 40.0;
    for (int j = 0; j <= 40; ++j) {
      double NoV = j == 0 ? 1e-4 : j / 40.0;
      double a = albedoZioma(k, r * r, NoV, 1.0, 4096);
      if (a > worst) {
        worst = a;
        *atR = r;
        *atNoV = NoV;
      }
    }
  }
  return worst;
}

}  // namespace

int main() {
  Scenes s = makeScenes();
  Best best;
  search(s, 0.0, 1.0, 0.1, -1.0, 1.5, 0.25, &best);
  std::printf("coarse: m=%.4f p=%.4f q=%.4f mse=%.4f\n", best.k.loH2Min, best.k.roughScale, best.k.roughBias, best.mse);
  Best fine = best;
  search(s, best.k.loH2Min - 0.075, best.k.loH2Min + 0.075, 0.025, best.k.roughScale - 0.25, best.k.roughScale + 0.25,
         0.0625, &fine);
  std::printf("fine:   m=%.4f p=%.4f q=%.4f mse=%.4f\n", fine.k.loH2Min, fine.k.roughScale, fine.k.roughBias, fine.mse);

  for (auto [name, k] : {std::pair{"published (URP, a+0.5)", kZiomaPublished}, std::pair{"talk (r+0.5)", kZiomaTalk},
                         std::pair{"facet (fit)", fine.k}}) {
    double r = 0, v = 0;
    double a = maxAlbedo(k, &r, &v);
    double mse = error(s, k);
    std::printf("%-24s m=%.4f p=%.4f q=%.4f  fit-set PSNR %.2f dB  max albedo(f0=1) %.4f at r=%.3f NoV=%.4f\n", name,
                k.loH2Min, k.roughScale, k.roughBias, 10.0 * std::log10(255.0 * 255.0 / mse), a, r, v);
  }
  return 0;
}
