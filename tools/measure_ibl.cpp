// tools/measure_ibl.cpp — the measured numbers of docs/ibl.md.
//
// 1. The split-sum DFG terms at the hard point n·v = 1/64, r = 0.5: brute-force grid
//    (reference/dfg_quadrature.h) against VNDF and plain GGX importance sampling at several
//    sample counts.
// 2. The table facet_ibl ships (generateDfgLut() defaults): integration error against the grid
//    at every 5th texel with r ≥ 0.35 (where a 1024-row grid is exact to 3e-5), the error of bilinear
//    filtering halfway between texel centres, and the time to generate it.
// 3. Karis's and Zioma's analytic environment BRDFs against the table at its 64 × 64 texel
//    centres, for f0 = 0.04 and f0 = 1: max and mean absolute error; and Karis's fit against a
//    table of the model it was fitted to (UE4: separable Schlick–Smith, k = α/2), to tell fit error
//    from model difference.
// 4. SH2 and SH3 irradiance of reference/irradiance_quadrature.h's cap sky against brute force.
// 5. prefilterEnvironment() on the cap sky against the exact lobe average
//    (reference/prefilter_quadrature.h), for a few sample counts and lod biases; and its time
//    with the default options.
//
// Usage: measure_ibl    (prints Markdown; deterministic except the timing line)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "facet/ibl/dfg_lut.h"
#include "facet/ibl/env_brdf_fits.h"
#include "facet/ibl/ggx_microfacet.h"
#include "facet/ibl/hammersley.h"
#include "facet/ibl/prefilter_environment.h"
#include "facet/ibl/spherical_harmonics.h"
#include "reference/dfg_quadrature.h"
#include "reference/env_brdf_error.h"
#include "reference/irradiance_quadrature.h"
#include "reference/prefilter_quadrature.h"

using namespace facet::ibl;
namespace ref = facet::reference;

namespace {

void grazingPoint() {
  double NoV = 1.0 / 64.0, r = 0.5;
  ref::DfgByGrid truth = ref::integrateDfgByGrid(NoV, r, 4096);
  std::printf("## DFG at n·v = 1/64, r = 0.5\n\n");
  std::printf("| integrator | samples | A + B (albedo) | B (fresnelWeighted) |\n|---|---|---|---|\n");
  std::printf("| grid 4096 × 8192 (reference) | — | %.5f | %.5f |\n", truth.albedo, truth.fresnelWeighted);
  ref::DfgByGrid coarse = ref::integrateDfgByGrid(NoV, r, 1024);
  std::printf("| grid 1024 × 2048 (the test's) | — | %.5f | %.5f |\n", coarse.albedo, coarse.fresnelWeighted);
  for (int n : {256, 512, 1024, 2048, 4096}) {
    DfgTerms t = integrateDfg(NoV, r, n, DfgSampling::VisibleNormals);
    std::printf("| VNDF (Heitz 2018) | %d | %.5f | %.5f |\n", n, t.albedo, t.fresnelWeighted);
  }
  for (int n : {1024, 4096, 65536}) {
    DfgTerms t = integrateDfg(NoV, r, n, DfgSampling::GgxNormals);
    std::printf("| D n·h (Karis 2013) | %d | %.5f | %.5f |\n", n, t.albedo, t.fresnelWeighted);
  }
  std::printf("\n");
}

DfgLut table() {
  std::printf("## The shipped table: %d × %d, %d VNDF samples per texel\n\n", kDfgLutSize, kDfgLutSize, kDfgLutSamples);
  double best = 1e30;
  DfgLut lut;
  for (int run = 0; run < 3; ++run) {
    auto start = std::chrono::steady_clock::now();
    lut = generateDfgLut();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::printf("- generation time: %.3f s (best of 3, one thread)\n", best);

  double worst = 0, worstNoV = 0, worstR = 0;
  for (int row = 0; row < lut.size; row += 5) {
    double r = dfgLutRoughness(row, lut.size);
    if (r < 0.35) continue;
    for (int column = 0; column < lut.size; column += 5) {
      double NoV = dfgLutNoV(column, lut.size);
      ref::DfgByGrid g = ref::integrateDfgByGrid(NoV, r, 1024);
      DfgTerms t = lut.at(column, row);
      double e = std::max(std::abs(t.albedo - g.albedo), std::abs(t.fresnelWeighted - g.fresnelWeighted));
      if (e > worst) worst = e, worstNoV = NoV, worstR = r;
    }
  }
  std::printf("- integration error vs grid (every 5th texel, r ≥ 0.35, both terms): max %.2e at n·v = %.4f, r = %.4f\n",
              worst, worstNoV, worstR);

  // Filtering error: halfway between centres, against the integral there (VNDF, 16384 samples).
  double worstInterior = 0, worstEdge = 0, edgeR = 0;
  for (int row = 0; row + 1 < lut.size; row += 3) {
    double r = (row + 1.0) / lut.size;
    for (int column = 0; column + 1 < lut.size; column += 3) {
      double NoV = (column + 1.0) / lut.size;
      DfgTerms exact = integrateDfg(NoV, r, 16384);
      DfgTerms filtered = lut.sampleBilinear(NoV, r);
      double e = std::max(std::abs(filtered.albedo - exact.albedo),
                          std::abs(filtered.fresnelWeighted - exact.fresnelWeighted));
      if (column < 3) {
        if (e > worstEdge) worstEdge = e, edgeR = r;
      } else {
        worstInterior = std::max(worstInterior, e);
      }
    }
  }
  std::printf(
      "- bilinear filtering error halfway between texel centres (every 3rd, both terms): max %.2e for n·v ≥ 4/64;"
      " %.2e at n·v = 1/64 (worst at r = %.3f)\n",
      worstInterior, worstEdge, edgeR);

  double minAlbedo = 1e30, maxAlbedo = 0;
  for (int row = 0; row < lut.size; ++row)
    for (int column = 0; column < lut.size; ++column) {
      minAlbedo = std::min(minAlbedo, double(lut.at(column, row).albedo));
      maxAlbedo = std::max(maxAlbedo, double(lut.at(column, row).albedo));
    }
  std::printf("- albedo (G) over the table: min %.4f, max %.6f; largest energy-compensation factor (f0 = 1): %.3f\n\n",
              minAlbedo, maxAlbedo, 1.0 / minAlbedo);
  return lut;
}

void fits(const DfgLut& lut) {
  std::printf("## Analytic environment BRDFs against the table (64 × 64 texel centres)\n\n");
  std::printf("| fit | f0 | max abs error | at (n·v, r) | mean abs error |\n|---|---|---|---|---|\n");
  for (double f0 : {0.04, 1.0}) {
    struct Fit {
      const char* name;
      std::function<double(double, double)> eval;
    } list[] = {
        {"Karis 2014", [&](double NoV, double r) { return envBrdfKaris(NoV, r).apply(f0); }},
        {"Zioma 2015 (slide)", [&](double NoV, double r) { return envBrdfZioma(NoV, r).apply(f0); }},
        {"Zioma 2015, saturated", [&](double NoV, double r) { return envBrdfZiomaSaturated(f0, NoV, r); }},
    };
    for (const Fit& fit : list) {
      ref::EnvBrdfError e = ref::envBrdfError(lut, f0, fit.eval);
      std::printf("| %s | %g | %.4f | (%.3f, %.3f) | %.4f |\n", fit.name, f0, e.max, e.atNoV, e.atRoughness, e.mean);
    }
  }
  std::printf("\n");
}

// A 64 × 64 table of the UE4 model, same layout and sampler (VNDF, 2048 per texel); only the
// visibility differs: V = G1(v) G1(l) / (4 n·v n·l), G1(x) = x / (x (1 − k) + k), k = α/2.
DfgLut ue4ModelTable() {
  DfgLut lut;
  lut.size = kDfgLutSize;
  lut.texels.resize(size_t(lut.size) * lut.size * 2);
  const uint32_t samples = kDfgLutSamples;
  for (int row = 0; row < lut.size; ++row) {
    double r = dfgLutRoughness(row, lut.size), alpha = r * r, k = alpha / 2.0;
    for (int column = 0; column < lut.size; ++column) {
      double NoV = dfgLutNoV(column, lut.size);
      Vec3 v{std::sqrt(1.0 - NoV * NoV), 0.0, NoV};
      auto g1 = [k](double x) { return x / (x * (1.0 - k) + k); };
      double albedo = 0, fresnel = 0;
      for (uint32_t i = 0; i < samples; ++i) {
        Vec3 h = sampleGgxVisibleNormal(hammersley(i, samples), v, alpha);
        Vec3 l = reflectAbout(v, h);
        double VoH = dot(v, h);
        if (l.z <= 0.0 || VoH <= 0.0) continue;
        double V = g1(NoV) * g1(l.z) / (4.0 * NoV * l.z);
        double w = 4.0 * V * l.z * NoV / maskingSmithGgx(alpha, NoV);  // D V n·l / pdf, pdf of visible normals
        albedo += w;
        fresnel += w * std::pow(1.0 - VoH, 5.0);
      }
      size_t i = (size_t(row) * lut.size + column) * 2;
      lut.texels[i] = float(fresnel / samples);
      lut.texels[i + 1] = float(albedo / samples);
    }
  }
  return lut;
}

void karisAgainstItsOwnModel() {
  DfgLut ue4 = ue4ModelTable();
  std::printf("Karis 2014 against a table of the model it was fitted to (separable Schlick–Smith, k = α/2):\n\n");
  std::printf("| f0 | max abs error | at (n·v, r) | mean abs error |\n|---|---|---|---|\n");
  for (double f0 : {0.04, 1.0}) {
    ref::EnvBrdfError e =
        ref::envBrdfError(ue4, f0, [f0](double NoV, double r) { return envBrdfKaris(NoV, r).apply(f0); });
    std::printf("| %g | %.4f | (%.3f, %.3f) | %.4f |\n", f0, e.max, e.atNoV, e.atRoughness, e.mean);
  }
  std::printf("\n");
}

void sphericalHarmonics() {
  std::printf("## SH irradiance of the cap sky vs brute force (reference/irradiance_quadrature.h)\n\n");
  auto radiance = [](Vec3 d) {
    glm::dvec3 L = ref::capSkyRadiance(glm::dvec3(d.x, d.y, d.z));
    return Vec3{L.x, L.y, L.z};
  };
  double peak = 0;
  double worst[2] = {0, 0}, mean[2] = {0, 0};
  SphericalHarmonics irr[2] = {radianceToIrradiance(projectRadiance(radiance, 2, 128)),
                               radianceToIrradiance(projectRadiance(radiance, 3, 128))};
  int count = 0;
  for (int i = 0; i < 200; ++i, ++count) {
    glm::dvec3 n = ref::fibonacciSphere(i, 200);
    double truth = ref::irradianceByGrid(ref::capSkyRadiance, n, 256).x;
    peak = std::max(peak, truth);
    for (int b = 0; b < 2; ++b) {
      double e = std::abs(evaluateSh(irr[b], {n.x, n.y, n.z}).x - truth);
      worst[b] = std::max(worst[b], e);
      mean[b] += e;
    }
  }
  std::printf("Red channel over 200 normals; peak irradiance %.3f.\n\n", peak);
  std::printf("| bands | max abs error | max / peak | mean abs error |\n|---|---|---|---|\n");
  for (int b = 0; b < 2; ++b)
    std::printf("| SH%d | %.4f | %.2f %% | %.4f |\n", b + 2, worst[b], 100.0 * worst[b] / peak, mean[b] / count);
  std::printf("\n");
}

// Every texel of every level against the exact lobe average of the analytic cap sky (the source is
// that sky rendered at 128 × 64, so the source's own resolution is part of the error).
void prefilterAccuracy() {
  std::printf("## Prefiltered cap sky (128 × 64 source, 5 levels) vs the exact lobe average\n\n");
  auto radiance = [](Vec3 d) {
    glm::dvec3 L = ref::capSkyRadiance(glm::dvec3(d.x, d.y, d.z));
    return Vec3{L.x, L.y, L.z};
  };
  EquirectImage source = renderEquirect(128, 64, radiance);
  Vec3 sourceMean = meanRadiance(source);
  struct Config {
    int samples;
    double lodBias;
  };
  const Config configs[] = {{256, 1.0}, {256, 0.0}, {512, 0.0}, {1024, 0.0}};
  std::vector<std::vector<EquirectImage>> results;
  for (const Config& c : configs) {
    PrefilterOptions options;
    options.samples = c.samples;
    options.lodBias = c.lodBias;
    results.push_back(prefilterEnvironment(source, options));
  }
  std::printf(
      "Red channel; relative RMS = √(Σ (got − exact)² / Σ exact²) over the level's texels; mean = solid-angle-weighted"
      " mean / source mean.\n\n| level (r) |");
  for (const Config& c : configs) std::printf(" %d samples, lod bias %g |", c.samples, c.lodBias);
  std::printf("\n|---|");
  for (size_t i = 0; i < std::size(configs); ++i) std::printf("---|");
  std::printf("\n");
  for (int m = 1; m < 5; ++m) {
    const EquirectImage& shape = results[0][size_t(m)];
    double r = prefilterLevelRoughness(m, 5);
    std::vector<double> exact;
    for (int row = 0; row < shape.height; ++row)
      for (int column = 0; column < shape.width; ++column) {
        Vec3 n = equirectDirection(shape, column, row);
        exact.push_back(ref::ggxLobeAverageByGrid(ref::capSkyRadiance, glm::dvec3(n.x, n.y, n.z), r * r, 256).x);
      }
    std::printf("| %d (%.2f) |", m, r);
    for (const auto& levels : results) {
      const EquirectImage& level = levels[size_t(m)];
      double se = 0, norm = 0;
      size_t i = 0;
      for (int row = 0; row < level.height; ++row)
        for (int column = 0; column < level.width; ++column, ++i) {
          double d = level.texel(column, row).x - exact[i];
          se += d * d;
          norm += exact[i] * exact[i];
        }
      std::printf(" RMS %.2f %%, mean %.4f |", 100.0 * std::sqrt(se / norm), meanRadiance(level).x / sourceMean.x);
    }
    std::printf("\n");
  }
  std::printf("\n");
}

void prefilterCost() {
  std::printf("## Prefiltering time (default options: 5 levels, 512 samples per texel, one thread)\n\n");
  for (int height : {64, 128, 256}) {
    EquirectImage source = renderEquirect(2 * height, height, [](Vec3 d) {
      glm::dvec3 L = ref::capSkyRadiance(glm::dvec3(d.x, d.y, d.z));
      return Vec3{L.x, L.y, L.z};
    });
    auto start = std::chrono::steady_clock::now();
    std::vector<EquirectImage> levels = prefilterEnvironment(source);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Vec3 mean0 = meanRadiance(source), mean4 = meanRadiance(levels.back());
    std::printf("- %d × %d source: %.3f s (last level mean / source mean, red: %.4f)\n", 2 * height, height, seconds,
                mean4.x / mean0.x);
  }
  std::printf("\n");
}

}  // namespace

int main() {
  grazingPoint();
  DfgLut lut = table();
  fits(lut);
  karisAgainstItsOwnModel();
  sphericalHarmonics();
  prefilterAccuracy();
  prefilterCost();
  return 0;
}
