// tools/measure_lut_shape.cpp — why the low tier's table lobe misses on rough metals
// (docs/specular-tiers.md, "What a table indexed by R·L cannot carry").
//
// A metal sphere (f0 = 1, no diffuse; reference/specular_sphere.h, 256 × 256, orthographic) under
// the two suns of `matc eval`'s grid (eval/src/grid_scene.cpp: "frontal" from behind the camera,
// "grazing" from the right and behind), E = 2.86 pre-exposed (the grid's 110 000 lux sun at the
// sunny-16 exposure), perceptual roughness 0.2 … 1. Tone-mapped 8-bit PSNR against the exact
// GGX · Smith (height-correlated) · Schlick lobe, per roughness (both views pooled) and over all,
// for the shipped `lut` lobe, S(R·L, r)/A(r) · E(n·v, r) (the shipped table, E the exact lobe's
// directional albedo; no energy compensation on either side), and for what could be added to it:
//   - × g(n·v, r), the best per-(n·v, r) factor (32 n·v bins, each searched for the least 8-bit
//     error over both views): what two more channels of the DFG table, read anyway, could carry
//     for free;
//   - × g(n·l, r), the same along n·l (a factor no table the shader reads could carry);
//   - the exact lobe with D taken at the table's angle n·h' (n·h'² = (1 + R·L)/2) and V and F
//     exact: the cost of indexing by R·L alone, whatever else the lobe gets right;
//   - mid's fused_hammon, for scale.
// The factors are fitted on the very pixels they are scored on: bounds for their families (to
// the search's 1/40-octave step), not forms to ship.
//
// Usage: measure_lut_shape    (prints Markdown; deterministic)
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "facet/compiler/specular_lut.h"
#include "reference/specular_sphere.h"
#include "reference/specular_tiers.h"

using namespace facet::reference;

namespace {

constexpr int kBins = 32;
using Factor = std::array<double, kBins>;

int binOf(double cosine) { return std::clamp(int(cosine * kBins), 0, kBins - 1); }

// E(n·v) of the exact lobe for f0 = 1 at one roughness, tabulated (257 points) and lerped: the
// quadrature per pixel would take minutes.
struct AlbedoCurve {
  std::vector<double> values;
  explicit AlbedoCurve(double alpha) {
    for (int i = 0; i <= 256; ++i) values.push_back(albedoExact(alpha, std::max(i / 256.0, 1e-4), 1.0, 1024));
  }
  double operator()(double NoV) const {
    double x = std::clamp(NoV, 0.0, 1.0) * 256.0;
    int i = std::min(int(x), 255);
    return values[size_t(i)] + (values[size_t(i) + 1] - values[size_t(i)]) * (x - i);
  }
};

}  // namespace

int main() {
  const facet::compiler::SpecularLut table = facet::compiler::generateSpecularLut({});
  auto tableLobe = [&](const ShadingPoint& p) {  // S/A, as chunks/specular_lut.glsl decodes it
    double u = std::pow(std::clamp(p.RoL, 0.0, 1.0), 4.0);
    double s = sampleR8Bilinear(table.texels, table.width, table.height, lutTexelCoordinate(u, table.width),
                                lutTexelCoordinate(p.perceptualRoughness, table.height));
    return s * s * table.scale;
  };

  SphereScene frontal, grazing;
  frontal.size = grazing.size = 256;
  frontal.illuminance = grazing.illuminance = 2.86;
  frontal.light = glm::normalize(glm::dvec3(0.35, 0.45, 1.0));
  grazing.light = glm::normalize(glm::dvec3(1.0, 0.25, -0.25));
  const std::vector<double> roughness = {0.2, 0.4, 0.6, 0.8, 1.0};

  const char* names[] = {"shipped lut lobe: S(R·L)/A · E(n·v)", "× best g(n·v, r) (DFG channels)", "× best g(n·l, r)",
                         "exact V and F, D at n·h' (R·L's angle)", "fused_hammon (mid)"};
  constexpr int kForms = 5;
  std::array<SquaredError, kForms> all;
  std::array<std::vector<double>, kForms> perRoughness;

  for (double r : roughness) {
    const AlbedoCurve albedo(r * r);
    auto shipped = [&](const ShadingPoint& p) { return tableLobe(p) * albedo(p.NoV); };
    // The best factor per bin: each lit pixel lies in one n·v bin and one n·l bin, so each bin's
    // factor is searched on its own, on the 8-bit tone-mapped error the PSNR counts (log grid,
    // 1/16 … 16). Fitted on the very pixels it is scored on: the most such a factor can buy here.
    struct Pixel {
      int binV, binL;
      double exact, lobe;  // f · n·l · E, exact and shipped
    };
    std::vector<Pixel> pixels;
    const SphereMaterial metal{1.0, r};
    for (const SphereScene* scene : {&frontal, &grazing}) {
      renderSphere(*scene, metal, [&](const ShadingPoint& p) {
        pixels.push_back({binOf(p.NoV), binOf(p.NoL), specularExactForm(p) * p.NoL * scene->illuminance,
                          shipped(p) * p.NoL * scene->illuminance});
        return 0.0;
      });
    }
    auto display = [](double radiance) { return quantize8(srgbFromLinear(tonemapAcesFitted(radiance))); };
    auto bestFactor = [&](int Pixel::*bin) {
      Factor best{};
      for (int b = 0; b < kBins; ++b) {
        double bestError = INFINITY;
        for (int step = 0; step <= 320; ++step) {
          double g = std::exp2(-4.0 + step / 40.0), error = 0;
          for (const Pixel& px : pixels) {
            if (px.*bin != b) continue;
            double d = display(g * px.lobe) - display(px.exact);
            error += d * d;
          }
          if (error < bestError) bestError = error, best[size_t(b)] = g;
        }
      }
      return best;
    };
    const Factor gV = bestFactor(&Pixel::binV), gL = bestFactor(&Pixel::binL);
    std::array<SpecularForm, kForms> forms = {
        shipped,
        [&](const ShadingPoint& p) { return shipped(p) * gV[size_t(binOf(p.NoV))]; },
        [&](const ShadingPoint& p) { return shipped(p) * gL[size_t(binOf(p.NoL))]; },
        [&](const ShadingPoint& p) {
          ShadingPoint q = p;
          q.NoH = std::sqrt((1.0 + std::clamp(p.RoL, -1.0, 1.0)) * 0.5);
          return specularExactForm(q);
        },
        [&](const ShadingPoint& p) { return specularFusedHammon(p.alpha, p.NoV, p.NoL, p.NoH) * p.f0; },
    };
    for (int k = 0; k < kForms; ++k) {
      SquaredError one;
      for (const SphereScene* scene : {&frontal, &grazing}) {
        auto reference = renderSphere(*scene, metal, specularExactForm);
        auto image = renderSphere(*scene, metal, forms[size_t(k)]);
        one.add(image, reference);
        all[size_t(k)].add(image, reference);
      }
      perRoughness[size_t(k)].push_back(one.psnr());
    }
  }

  std::printf(
      "Metal sphere (f0 = 1) %dx%d, the eval grid's frontal and grazing suns, E = %.2f; 8-bit PSNR (dB) vs exact "
      "GGX/Smith/Schlick\n\n",
      frontal.size, frontal.size, frontal.illuminance);
  std::printf("| form | all |");
  for (double r : roughness) std::printf(" r = %.1f |", r);
  std::printf("\n|---|--:|");
  for (size_t i = 0; i < roughness.size(); ++i) std::printf("--:|");
  std::printf("\n");
  for (int k = 0; k < kForms; ++k) {
    std::printf("| %s | %.1f |", names[k], all[size_t(k)].psnr());
    for (double p : perRoughness[size_t(k)]) std::printf(" %.1f |", p);
    std::printf("\n");
  }
  return 0;
}
