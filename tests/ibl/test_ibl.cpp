// Image-based lighting maths (ibl/): every generator against a brute-force quadrature that shares
// no code with it (reference/dfg_quadrature.h, reference/irradiance_quadrature.h, and the lobe
// integral below), or against values derived by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "facet/ibl/bilinear_axis.h"
#include "facet/ibl/dfg_lut.h"
#include "facet/ibl/embedded_dfg_lut.h"
#include "facet/ibl/env_brdf_fits.h"
#include "facet/ibl/irradiance_cube.h"
#include "facet/ibl/prefilter_environment.h"
#include "facet/ibl/sheen_lut.h"
#include "facet/ibl/sphere_quadrature.h"
#include "facet/ibl/spherical_harmonics.h"
#include "reference/dfg_quadrature.h"
#include "reference/env_brdf_error.h"
#include "reference/irradiance_quadrature.h"
#include "reference/prefilter_quadrature.h"

namespace {

using namespace facet::ibl;
namespace ref = facet::reference;

const DfgLut& shippedLut() {
  static const DfgLut lut = generateDfgLut();
  return lut;
}

glm::dvec3 toGlm(Vec3 v) { return {v.x, v.y, v.z}; }
Vec3 toVec3(glm::dvec3 v) { return {v.x, v.y, v.z}; }

double maxComponent(Vec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

void expectNearVec3(Vec3 got, Vec3 want, double tolerance) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

}  // namespace

// --- split-sum DFG ---

TEST(Dfg, GridQuadratureGivesTheGrazingAlbedoOfTheBrief) {
  ref::DfgByGrid g = ref::integrateDfgByGrid(1.0 / 64.0, 0.5);
  EXPECT_NEAR(g.albedo, 0.9737, 1e-4);
}

TEST(Dfg, VisibleNormalSamplingMatchesTheGridAtGrazingView) {
  ref::DfgByGrid g = ref::integrateDfgByGrid(1.0 / 64.0, 0.5);
  DfgTerms t = integrateDfg(1.0 / 64.0, 0.5, kDfgLutSamples);
  EXPECT_NEAR(t.albedo, 0.9737, 0.002);
  EXPECT_NEAR(t.albedo, g.albedo, 0.002);
  EXPECT_NEAR(t.fresnelWeighted, g.fresnelWeighted, 0.002);
}

TEST(Dfg, GgxNormalSamplingReadsTwoPercentHighAtGrazingView) {
  // The pitfall dfg_lut.h documents: h ~ D n·h with 1024 points gives 0.9956 here.
  DfgTerms t = integrateDfg(1.0 / 64.0, 0.5, 1024, DfgSampling::GgxNormals);
  EXPECT_GT(t.albedo, 0.99);
}

TEST(Dfg, MatchesTheGridAcrossViewAndRoughness) {
  // r ≥ 0.35: where the 1024-row grid itself is exact to 3e-5 (tools/measure_ibl).
  for (double NoV : {1.0 / 64.0, 0.2, 0.6, 1.0}) {
    for (double r : {0.35, 0.6, 1.0}) {
      ref::DfgByGrid g = ref::integrateDfgByGrid(NoV, r);
      DfgTerms t = integrateDfg(NoV, r, kDfgLutSamples);
      EXPECT_NEAR(t.albedo, g.albedo, 1e-3) << "n·v " << NoV << " r " << r;
      EXPECT_NEAR(t.fresnelWeighted, g.fresnelWeighted, 1e-3) << "n·v " << NoV << " r " << r;
    }
  }
}

TEST(Dfg, FullRoughnessAtNormalIncidenceIsOneMinusLn2) {
  // α = 1: D = 1/π, V = 1/(2 (1 + n·l)) at n·v = 1, so ∫ D V n·l dω = ∫₀¹ μ/(1 + μ) dμ = 1 − ln 2.
  EXPECT_NEAR(integrateDfg(1.0, 1.0, kDfgLutSamples).albedo, 1.0 - std::log(2.0), 1e-4);
}

TEST(Dfg, WhiteFurnaceNeverExceedsOne) {
  const DfgLut& lut = shippedLut();
  ASSERT_EQ(lut.size, kDfgLutSize);
  ASSERT_EQ(lut.texels.size(), size_t(kDfgLutSize) * kDfgLutSize * 2);
  double minAlbedo = 1.0;
  for (int row = 0; row < lut.size; ++row) {
    for (int column = 0; column < lut.size; ++column) {
      DfgTerms t = lut.at(column, row);
      EXPECT_LE(t.albedo, 1.0 + 1e-6) << column << ", " << row;
      EXPECT_GE(t.fresnelWeighted, 0.0) << column << ", " << row;
      EXPECT_LE(t.fresnelWeighted, t.albedo) << column << ", " << row;
      minAlbedo = std::min(minAlbedo, t.albedo);
    }
  }
  // Smallest at r → 1, n·v → 1, near 1 − ln 2; never the 0 a lost sample would give.
  EXPECT_GT(minAlbedo, 0.3);
  EXPECT_LT(minAlbedo, 0.32);
}

TEST(Dfg, SmoothLimitReflectsEverything) {
  for (double NoV : {1.0 / 64.0, 0.3, 1.0}) {
    DfgTerms mirror = integrateDfg(NoV, 0.0, 64);
    EXPECT_NEAR(mirror.albedo, 1.0, 1e-12);
    EXPECT_NEAR(mirror.fresnelWeighted, std::pow(1.0 - NoV, 5.0), 1e-12);
    EXPECT_GT(integrateDfg(NoV, 0.02, kDfgLutSamples).albedo, 0.999) << NoV;
  }
  // The table's smoothest row (r = 0.5/64).
  for (int column = 0; column < kDfgLutSize; ++column) EXPECT_GT(shippedLut().at(column, 0).albedo, 0.999) << column;
}

TEST(Dfg, TexelHoldsTheTermsAtItsCentre) {
  DfgLut lut = generateDfgLut(8, 256);
  for (int row : {0, 3, 7}) {
    for (int column : {0, 5, 7}) {
      DfgTerms want = integrateDfg((column + 0.5) / 8.0, (row + 0.5) / 8.0, 256);
      EXPECT_EQ(lut.at(column, row).fresnelWeighted, float(want.fresnelWeighted));
      EXPECT_EQ(lut.at(column, row).albedo, float(want.albedo));
    }
  }
  EXPECT_EQ(generateDfgLut(8, 256).texels, lut.texels);  // deterministic
}

TEST(Dfg, EnvironmentBrdfSplitsIntoF0AndF90Parts) {
  DfgTerms t = integrateDfg(0.3, 0.6, 512);
  EXPECT_DOUBLE_EQ(specularEnvironmentBrdf(t, 1.0), t.albedo);
  EXPECT_DOUBLE_EQ(specularEnvironmentBrdf(t, 0.0), t.fresnelWeighted);
  EXPECT_DOUBLE_EQ(specularEnvironmentBrdf(t, 0.0, 0.0), 0.0);
}

TEST(Dfg, MultiScatterCompensationRestoresTheWhiteFurnace) {
  const DfgLut& lut = shippedLut();
  for (int row : {10, 40, 63}) {
    for (int column : {0, 32, 63}) {
      DfgTerms t = lut.at(column, row);
      EXPECT_NEAR(specularEnvironmentBrdf(t, 1.0) * multiScatterCompensation(t, 1.0), 1.0, 1e-12);
      EXPECT_DOUBLE_EQ(multiScatterCompensation(t, 0.0), 1.0);
      EXPECT_LT(multiScatterCompensation(t, 1.0), 3.3);
    }
  }
}

// --- spherical harmonics ---

TEST(Sh, BasisIsOrthonormal) {
  // Order 8 is exact for polynomials of degree ≤ 13: products of two band-4 terms are degree 8.
  std::vector<SphereSample> quadrature = sphereQuadrature(8);
  for (int i = 0; i < kMaxShCoefficients; ++i) {
    for (int j = 0; j < kMaxShCoefficients; ++j) {
      double sum = 0;
      for (const SphereSample& s : quadrature) {
        std::vector<double> y = shBasis(kMaxShBands, s.direction);
        sum += y[size_t(i)] * y[size_t(j)] * s.weight;
      }
      EXPECT_NEAR(sum, i == j ? 1.0 : 0.0, 1e-12) << i << ", " << j;
    }
  }
}

TEST(Sh, ConstantEnvironmentGivesPiTimesRadianceForEveryNormal) {
  Vec3 L{0.25, 1.0, 3.0};
  for (int bands : {2, 3, 5}) {
    SphericalHarmonics radiance = projectRadiance([&](Vec3) { return L; }, bands);
    SphericalHarmonics irradiance = radianceToIrradiance(radiance);
    std::vector<Vec3> shader = shaderIrradianceCoefficients(radiance);
    for (int i = 0; i < 50; ++i) {
      Vec3 n = toVec3(ref::fibonacciSphere(i, 50));
      expectNearVec3(evaluateSh(irradiance, n), L * kPi, 1e-12);
      expectNearVec3(evaluateShaderIrradiance(shader, n), L, 1e-12);
    }
  }
}

TEST(Sh, LinearEnvironmentIsReproducedExactlyBySh2) {
  // L(d) = a + b (d·z): E(n) = π a + (2π/3) b (n·z), since ∫ (d·z) max(0, n·d) dω = (2π/3) n·z.
  Vec3 a{1.0, 2.0, 3.0}, b{0.5, -1.0, 2.0};
  auto radiance = [&](Vec3 d) { return a + b * d.z; };
  for (int bands : {2, 3, 5}) {
    SphericalHarmonics irradiance = radianceToIrradiance(projectRadiance(radiance, bands));
    std::vector<Vec3> shader = shaderIrradianceCoefficients(projectRadiance(radiance, bands));
    for (int i = 0; i < 50; ++i) {
      Vec3 n = toVec3(ref::fibonacciSphere(i, 50));
      Vec3 exact = a * kPi + b * (2.0 * kPi / 3.0 * n.z);
      expectNearVec3(evaluateSh(irradiance, n), exact, 1e-12);
      expectNearVec3(evaluateShaderIrradiance(shader, n) * kPi, exact, 1e-12);
    }
  }
}

namespace {

// An SH irradiance's error against the bright cap sky's, by brute force at 200 normals spread over
// the sphere, over the peak irradiance: the largest and the mean.
struct CapIrradianceError {
  double max = 0, mean = 0;
};

CapIrradianceError capIrradianceError(const SphericalHarmonics& sh) {
  struct Truth {
    std::vector<glm::dvec3> normals;
    std::vector<double> irradiance;
    double peak = 0;
  };
  static const Truth truth = [] {
    Truth t;
    const int count = 200;
    for (int i = 0; i < count; ++i) {
      t.normals.push_back(ref::fibonacciSphere(i, count));
      t.irradiance.push_back(ref::irradianceByGrid(ref::capSkyRadiance, t.normals.back(), 256).x);
      t.peak = std::max(t.peak, t.irradiance.back());
    }
    return t;
  }();
  CapIrradianceError error;
  for (size_t i = 0; i < truth.normals.size(); ++i) {
    double e = std::abs(evaluateSh(sh, toVec3(truth.normals[i])).x - truth.irradiance[i]) / truth.peak;
    error.max = std::max(error.max, e);
    error.mean += e / static_cast<double>(truth.normals.size());
  }
  return error;
}

}  // namespace

TEST(Sh, BrightCapSh3IrradianceIsWithinSixPercentOfPeakAndBeatsSh2) {
  // Measured (tools/measure_ibl, docs/ibl.md): max error 5.15 % of the peak for SH3, 20.6 % for SH2.
  auto radiance = [](Vec3 d) { return toVec3(ref::capSkyRadiance(toGlm(d))); };
  CapIrradianceError sh2 = capIrradianceError(radianceToIrradiance(projectRadiance(radiance, 2, 128)));
  CapIrradianceError sh3 = capIrradianceError(radianceToIrradiance(projectRadiance(radiance, 3, 128)));
  std::printf("cap sky irradiance error / peak: SH2 max %.4f mean %.4f, SH3 max %.4f mean %.4f\n", sh2.max, sh2.mean,
              sh3.max, sh3.mean);
  EXPECT_LT(sh3.max, 0.06);
  EXPECT_LT(sh3.max, sh2.max);
  EXPECT_LT(sh3.mean, sh2.mean);
}

// Band 4 (l = 0..4; band 3 vanishes under the clamped cosine) against the same brute force: the
// next term of the series must shrink SH3's truncation error on the same cap. Its Â_4 = −π/24
// (Ramamoorthi & Hanrahan 2001): with +π/24 or band 3 left in, the error grows instead.
TEST(Sh, BrightCapBand4IrradianceBeatsSh3) {
  auto radiance = [](Vec3 d) { return toVec3(ref::capSkyRadiance(toGlm(d))); };
  SphericalHarmonics sh5 = radianceToIrradiance(projectRadiance(radiance, 5, 128));
  for (size_t k = 9; k < 16; ++k) EXPECT_EQ(sh5.coefficients[k].x, 0.0) << k;
  CapIrradianceError sh3 = capIrradianceError(radianceToIrradiance(projectRadiance(radiance, 3, 128)));
  CapIrradianceError band4 = capIrradianceError(sh5);
  std::printf("cap sky irradiance error / peak: SH3 max %.4f mean %.4f, band 4 max %.4f mean %.4f\n", sh3.max, sh3.mean,
              band4.max, band4.mean);
  EXPECT_LT(band4.max, 0.6 * sh3.max);
  EXPECT_LT(band4.mean, 0.6 * sh3.mean);
}

TEST(Sh, ShaderCoefficientsEvaluateIrradianceOverPi) {
  auto radiance = [](Vec3 d) { return toVec3(ref::capSkyRadiance(toGlm(d))); };
  for (int bands : {3, 5}) {
    SphericalHarmonics sh = projectRadiance(radiance, bands, 32);
    SphericalHarmonics irradiance = radianceToIrradiance(sh);
    std::vector<Vec3> shader = shaderIrradianceCoefficients(sh);
    ASSERT_EQ(shader.size(), size_t(bands * bands));
    for (int i = 0; i < 50; ++i) {
      Vec3 n = toVec3(ref::fibonacciSphere(i, 50));
      Vec3 e = evaluateSh(irradiance, n);
      Vec3 clamped{std::max(e.x, 0.0), std::max(e.y, 0.0), std::max(e.z, 0.0)};
      expectNearVec3(evaluateShaderIrradiance(shader, n) * kPi, clamped, 1e-12 * maxComponent(e));
    }
  }
}

// The `cube` diffuse's table (irradiance_cube.h): SH3 of the bright cap tabulated at texel
// centres and read back as the GPU's seamless bilinear filter does (sampleBilinear). At texel
// centres the read is the sum exactly. Inside a face it interpolates a smooth quadratic: an error
// of second order in the texel size, each halving of the face dividing the worst by about 4. Within
// a texel of a face's edge the filter borrows the next face's edge texels (at a corner the mean of
// three), an error of first order, halved by each halving. The runtime's 32²
// (abi::kIrradianceMapSize) is held to 0.15 % of the peak inside the faces and 0.6 % at their edges
// (docs/ibl.md, "The irradiance cube", has the figures).
TEST(IrradianceCube, BilinearReadsOfTabulatedSh3ConvergeWithTheTexelSize) {
  auto radiance = [](Vec3 d) { return toVec3(ref::capSkyRadiance(toGlm(d))); };
  const std::vector<Vec3> c = shaderIrradianceCoefficients(projectRadiance(radiance, 3, 128));
  const int count = 20000;
  double peak = 0;
  for (int i = 0; i < count; ++i)
    peak = std::max(peak, evaluateShaderIrradiance(c, toVec3(ref::fibonacciSphere(i, count))).x);
  std::vector<double> interior, edges;
  for (int size : {8, 16, 32}) {
    const CubeImage cube = tabulateIrradiance(c, size);
    ASSERT_EQ(cube.size, size);
    for (int face = 0; face < kCubeFaces; ++face)
      expectNearVec3(cube.texel(face, size / 2, 1),
                     evaluateShaderIrradiance(c, cubeTexelDirection(size, face, size / 2, 1)),
                     1e-6 * peak);  // the cube's floats
    double inside = 0, near = 0;
    for (int i = 0; i < count; ++i) {
      const Vec3 n = toVec3(ref::fibonacciSphere(i, count));
      const Vec3 d = sampleBilinear(cube, n) - evaluateShaderIrradiance(c, n);
      const double e = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) / peak;
      int face = 0;
      double s = 0, t = 0;
      cubeCoordinates(n, &face, &s, &t);
      const bool edge = std::min({s, t, 1 - s, 1 - t}) * size < 1;
      (edge ? near : inside) = std::max(edge ? near : inside, e);
    }
    interior.push_back(inside);
    edges.push_back(near);
  }
  std::printf(
      "irradiance cube, bilinear against SH3, worst / peak inside the faces: 8² %.5f, 16² %.5f, 32² %.5f; within a "
      "texel of an edge: %.5f, %.5f, %.5f\n",
      interior[0], interior[1], interior[2], edges[0], edges[1], edges[2]);
  for (size_t i = 0; i + 1 < interior.size(); ++i) {
    EXPECT_GT(interior[i], 3 * interior[i + 1]) << i;
    EXPECT_GT(edges[i], 1.6 * edges[i + 1]) << i;
  }
  EXPECT_LT(interior[2], 0.0015);
  EXPECT_LT(edges[2], 0.006);
}

TEST(Sh, EquirectProjectionMatchesTheCallbackProjection) {
  // A smooth sky; the image's midpoint rule converges to the exact projection as 1/height².
  auto radiance = [](Vec3 d) { return Vec3{1.0 + 0.5 * d.y, 0.2 + d.x * d.x, std::exp(d.z)}; };
  SphericalHarmonics exact = projectRadiance(radiance, 3, 16);
  SphericalHarmonics fromImage = projectRadiance(renderEquirect(256, 128, radiance), 3);
  for (size_t k = 0; k < 9; ++k) expectNearVec3(fromImage.coefficients[k], exact.coefficients[k], 1e-3);
}

TEST(Sh, RejectsBandCountsOutsideOneToFive) {
  EXPECT_THROW(shBasis(6, {0, 0, 1}), std::invalid_argument);
  EXPECT_THROW(projectRadiance([](Vec3) { return Vec3{}; }, 0), std::invalid_argument);
}

// --- analytic environment BRDFs ---

TEST(EnvBrdf, KarisFitGivesHandComputedValues) {
  // r = 0, n·v = 1: k = (1, 0.0425, 1.04, −0.04), s = 2^−9.28 + 0.0425 = 0.0441086.
  EnvBrdfTerms smooth = envBrdfKaris(1.0, 0.0);
  EXPECT_NEAR(smooth.f0Scale, 0.9941271, 1e-7);
  EXPECT_NEAR(smooth.bias, 0.0058729, 1e-7);
  // r = 1, n·v = 0: k = (0, 0.015, 0.468, −0.018), s = 0.015.
  EnvBrdfTerms rough = envBrdfKaris(0.0, 1.0);
  EXPECT_NEAR(rough.f0Scale, 0.4524, 1e-12);
  EXPECT_NEAR(rough.bias, -0.0024, 1e-12);
}

TEST(EnvBrdf, ZiomaSlideFormExceedsOneForMetalsAndSaturatedFormDoesNot) {
  EnvBrdfTerms t = envBrdfZioma(0.2, 0.5);
  EXPECT_EQ(t.f0Scale, 1.0);
  EXPECT_NEAR(t.bias, 0.125, 1e-15);
  EXPECT_NEAR(t.apply(1.0), 1.125, 1e-15);
  EXPECT_EQ(envBrdfZiomaSaturated(1.0, 0.2, 0.5), 1.0);
  EXPECT_NEAR(envBrdfZiomaSaturated(0.04, 0.2, 0.5), 0.165, 1e-15);
}

TEST(EnvBrdf, FitErrorsAgainstTheTableStayWithinTheirMeasuredBounds) {
  // Loose bounds around the numbers of docs/ibl.md (tools/measure_ibl): they catch a wrong
  // constant or a changed table, not noise.
  const DfgLut& lut = shippedLut();
  struct Case {
    const char* name;
    double f0;
    std::function<double(double, double)> fit;
    double maxBound, meanBound;
  };
  auto karis = [](double f0) { return [f0](double NoV, double r) { return envBrdfKaris(NoV, r).apply(f0); }; };
  auto zioma = [](double f0) { return [f0](double NoV, double r) { return envBrdfZioma(NoV, r).apply(f0); }; };
  auto ziomaSat = [](double f0) { return [f0](double NoV, double r) { return envBrdfZiomaSaturated(f0, NoV, r); }; };
  const Case cases[] = {
      {"Karis", 0.04, karis(0.04), 0.10, 0.02},
      {"Karis", 1.0, karis(1.0), 0.55, 0.13},
      {"Zioma", 0.04, zioma(0.04), 0.25, 0.06},
      {"Zioma", 1.0, zioma(1.0), 1.0, 0.30},
      {"Zioma saturated", 1.0, ziomaSat(1.0), 0.70, 0.19},
  };
  for (const Case& c : cases) {
    ref::EnvBrdfError e = ref::envBrdfError(lut, c.f0, c.fit);
    std::printf("%-16s f0 = %-4g max %.4f mean %.4f\n", c.name, c.f0, e.max, e.mean);
    EXPECT_LT(e.max, c.maxBound) << c.name << " f0 " << c.f0;
    EXPECT_LT(e.mean, c.meanBound) << c.name << " f0 " << c.f0;
  }
  // Karis's fit beats Zioma's slide on average, for dielectrics and metals.
  for (double f0 : {0.04, 1.0})
    EXPECT_LT(ref::envBrdfError(lut, f0, karis(f0)).mean, ref::envBrdfError(lut, f0, zioma(f0)).mean) << f0;
}

// --- prefiltered environment ---

namespace {

// A sky brightening towards the zenith and a small bright sun with a smooth (Gaussian-like) edge,
// so bilinear sampling of a 128 × 64 image represents it without aliasing.
const Vec3 kSunAxis = normalize(Vec3{0.4, 0.7, -0.3});
Vec3 sunSkyRadiance(Vec3 d) {
  double sky = 0.5 + 0.5 * std::max(d.y, 0.0);
  double sun = 40.0 * std::exp((dot(d, kSunAxis) - 1.0) / 0.004);
  return Vec3{sky, sky, 1.2 * sky} + Vec3{sun, 0.9 * sun, 0.8 * sun};
}

const std::vector<EquirectImage>& prefilteredSunSky() {
  static const std::vector<EquirectImage> levels = prefilterEnvironment(renderEquirect(128, 64, sunSkyRadiance));
  return levels;
}

}  // namespace

TEST(Prefilter, LevelsHalveResolutionAndInvertTheShadersLodMapping) {
  const std::vector<EquirectImage>& levels = prefilteredSunSky();
  ASSERT_EQ(levels.size(), 5u);
  for (int m = 0; m < 5; ++m) {
    EXPECT_EQ(levels[size_t(m)].width, 128 >> m);
    EXPECT_EQ(levels[size_t(m)].height, 64 >> m);
    // The shader reads lod = 4 r (2 − r) (chunks/ibl_prefiltered.glsl): level m must hold its inverse.
    const double r = prefilterLevelRoughness(m, 5);
    EXPECT_NEAR(4.0 * r * (2.0 - r), double(m), 1e-12);
  }
}

TEST(Prefilter, ConstantEnvironmentStaysConstantAtEveryLevel) {
  Vec3 L{0.5, 2.0, 7.0};
  for (const EquirectImage& level : prefilterEnvironment(renderEquirect(64, 32, [&](Vec3) { return L; }))) {
    for (int row = 0; row < level.height; ++row)
      for (int column = 0; column < level.width; ++column) {
        Vec3 v = level.texel(column, row);
        EXPECT_NEAR(v.x / L.x, 1.0, 1e-5);
        EXPECT_NEAR(v.y / L.y, 1.0, 1e-5);
        EXPECT_NEAR(v.z / L.z, 1.0, 1e-5);
      }
  }
}

TEST(Prefilter, LevelZeroReproducesTheSource) {
  EquirectImage source = renderEquirect(128, 64, sunSkyRadiance);
  const EquirectImage& level0 = prefilteredSunSky()[0];
  for (int row = 0; row < source.height; ++row)
    for (int column = 0; column < source.width; ++column) {
      Vec3 want = source.texel(column, row), got = level0.texel(column, row);
      EXPECT_NEAR(got.x, want.x, 1e-5 * want.x);
      EXPECT_NEAR(got.y, want.y, 1e-5 * want.y);
      EXPECT_NEAR(got.z, want.z, 1e-5 * want.z);
    }
}

TEST(Prefilter, EveryLevelKeepsTheMeanRadiance) {
  // A zonal, normalised lobe leaves the sphere's mean unchanged; what moves it is the discrete
  // sampling and the mip selection.
  Vec3 source = meanRadiance(renderEquirect(128, 64, sunSkyRadiance));
  for (const EquirectImage& level : prefilteredSunSky()) {
    Vec3 mean = meanRadiance(level);
    std::printf("level %dx%d mean / source mean: %.4f %.4f %.4f\n", level.width, level.height, mean.x / source.x,
                mean.y / source.y, mean.z / source.z);
    EXPECT_NEAR(mean.x / source.x, 1.0, 0.02);
    EXPECT_NEAR(mean.y / source.y, 1.0, 0.02);
    EXPECT_NEAR(mean.z / source.z, 1.0, 0.02);
  }
}

TEST(Prefilter, RoughLevelsMatchTheLobeIntegral) {
  // Levels 2 (r = 0.5) and 4 (r = 1) at the texel nearest the sun, one 88° away and one opposite.
  const std::vector<EquirectImage>& levels = prefilteredSunSky();
  for (int m : {2, 4}) {
    const EquirectImage& level = levels[size_t(m)];
    double r = prefilterLevelRoughness(m, 5);
    double s, t;
    Vec3 away = normalize(kSunAxis + Vec3{0.0, -1.2, 0.0});
    for (Vec3 target : {kSunAxis, away, kSunAxis * -1.0}) {
      equirectCoordinates(target, &s, &t);
      int column = std::min(int(s * level.width), level.width - 1),
          row = std::min(int(t * level.height), level.height - 1);
      Vec3 want = toVec3(ref::ggxLobeAverageByGrid([](glm::dvec3 d) { return toGlm(sunSkyRadiance(toVec3(d))); },
                                                   toGlm(equirectDirection(level, column, row)), r * r));
      Vec3 got = level.texel(column, row);
      std::printf("level %d texel (%d, %d): prefiltered %.4f, lobe integral %.4f\n", m, column, row, got.x, want.x);
      EXPECT_NEAR(got.x / want.x, 1.0, 0.02) << "level " << m;
      EXPECT_NEAR(got.z / want.z, 1.0, 0.02) << "level " << m;
    }
  }
}

TEST(Prefilter, RejectsSourcesThatDoNotHalveEvenly) {
  EXPECT_THROW(prefilterEnvironment(EquirectImage(96, 24)), std::invalid_argument);  // not 2h × h
  PrefilterOptions options;
  options.levels = 5;
  EXPECT_THROW(prefilterEnvironment(EquirectImage(48, 24), options), std::invalid_argument);  // 24 % 16 ≠ 0
  options.levels = 0;
  EXPECT_THROW(prefilterEnvironment(EquirectImage(64, 32), options), std::invalid_argument);
}

// --- cube map environment (what the runtime uploads) ---

namespace {

// Directions over the whole sphere: a Fibonacci set plus the axes and points on face edges.
std::vector<Vec3> testDirections() {
  std::vector<Vec3> out = {{1, 0, 0},  {-1, 0, 0},    {0, 1, 0},  {0, -1, 0},       {0, 0, 1},
                           {0, 0, -1}, {1, -1e-9, 1}, {-1, 1, 1}, {0.3, -0.2, -0.7}};
  const int n = 500;
  for (int i = 0; i < n; ++i) {
    double y = 1 - 2 * (i + 0.5) / n, rho = std::sqrt(1 - y * y), phi = i * 2.399963229728653;
    out.push_back({rho * std::cos(phi), y, rho * std::sin(phi)});
  }
  for (Vec3& d : out) d = normalize(d);
  return out;
}

const std::vector<CubeImage>& prefilteredSunSkyCube() {
  static const std::vector<CubeImage> levels = prefilterEnvironmentCube(renderEquirect(128, 64, sunSkyRadiance), 64);
  return levels;
}

}  // namespace

TEST(CubeMap, CoordinatesInvertTheDirectionMapping) {
  for (Vec3 d : testDirections()) {
    int face = -1;
    double s, t;
    cubeCoordinates(d, &face, &s, &t);
    ASSERT_GE(face, 0);
    ASSERT_LT(face, kCubeFaces);
    EXPECT_GE(s, 0.0);
    EXPECT_LE(s, 1.0);
    EXPECT_GE(t, 0.0);
    EXPECT_LE(t, 1.0);
    expectNearVec3(cubeDirection(face, s, t), d, 1e-12);
  }
}

// The face table of the Vulkan specification (and GLES 3.0 §3.8.10), read off for one direction
// per face: +X (sc, tc) = (−z, −y), −X (z, −y), +Y (x, z), −Y (x, −z), +Z (x, −y), −Z (−x, −y),
// over the major axis, then (· + 1)/2. The renders (IblShading.*) check the GPU agrees.
TEST(CubeMap, FacesFollowTheApiTable) {
  struct Case {
    Vec3 d;
    int face;
    double s, t;
  };
  const Case cases[] = {
      {{2, 0.5, 1}, 0, 0.25, 0.375},  {{-2, 0.5, 1}, 1, 0.75, 0.375}, {{0.5, 2, 1}, 2, 0.625, 0.75},
      {{0.5, -2, 1}, 3, 0.625, 0.25}, {{0.5, 1, 2}, 4, 0.625, 0.25},  {{0.5, 1, -2}, 5, 0.375, 0.25},
  };
  for (const Case& c : cases) {
    int face = -1;
    double s, t;
    cubeCoordinates(c.d, &face, &s, &t);
    EXPECT_EQ(face, c.face);
    EXPECT_NEAR(s, c.s, 1e-15) << c.face;
    EXPECT_NEAR(t, c.t, 1e-15) << c.face;
  }
  // Texel (column, row) of a face is at (s, t) = ((column + 0.5) / size, (row + 0.5) / size).
  int face = -1;
  double s, t;
  cubeCoordinates(cubeTexelDirection(8, 3, 1, 6), &face, &s, &t);
  EXPECT_EQ(face, 3);
  EXPECT_NEAR(s, 1.5 / 8, 1e-12);
  EXPECT_NEAR(t, 6.5 / 8, 1e-12);
}

// Seamless bilinear reconstruction of a smooth function: two points a hair either side of a face
// edge (or near a corner) read the same value, and the map follows the function within its
// texel size everywhere.
TEST(CubeMap, BilinearSamplingHasNoSeamAtFaceEdges) {
  auto f = [](Vec3 d) { return Vec3{1.0 + d.x, 2.0 + d.z, 1.5 + d.y + 0.5 * d.x * d.z}; };
  const int size = 16;
  CubeImage image(size);
  for (int face = 0; face < kCubeFaces; ++face)
    for (int row = 0; row < size; ++row)
      for (int column = 0; column < size; ++column)
        image.setTexel(face, column, row, f(cubeTexelDirection(size, face, column, row)));
  double worstSeam = 0;
  const double e = 1e-9;
  for (int i = 0; i <= 100; ++i) {
    double a = -1 + 2 * i / 100.0;  // along the edge, corners included
    worstSeam =
        std::max({worstSeam, maxComponent(sampleBilinear(image, {1, a, 1 - e}) - sampleBilinear(image, {1 - e, a, 1})),
                  maxComponent(sampleBilinear(image, {a, 1, 1 - e}) - sampleBilinear(image, {a, 1 - e, 1})),
                  maxComponent(sampleBilinear(image, {-1, 1 - e, a}) - sampleBilinear(image, {-1 + e, 1, a})),
                  maxComponent(sampleBilinear(image, {a, -1, -1 + e}) - sampleBilinear(image, {a, -1 + e, -1}))});
  }
  EXPECT_LT(worstSeam, 1e-6);
  double worst = 0;
  for (Vec3 d : testDirections()) worst = std::max(worst, maxComponent(sampleBilinear(image, d) - f(d)));
  std::printf("cube %d² faces: seam %.2g, worst |bilinear − f| %.4f\n", size, worstSeam, worst);
  EXPECT_LT(worst, 0.1);  // |∇f| ≤ ~1.5 per radian, texels ≤ ~0.1 rad at 16²
}

TEST(CubeMap, PrefilteredLevelsHalveAndKeepAConstantEnvironment) {
  const auto& levels = prefilteredSunSkyCube();
  ASSERT_EQ(levels.size(), 5u);
  for (int m = 0; m < 5; ++m) EXPECT_EQ(levels[size_t(m)].size, 64 >> m);
  Vec3 L{0.5, 2.0, 7.0};
  for (const CubeImage& level : prefilterEnvironmentCube(renderEquirect(64, 32, [&](Vec3) { return L; }), 16))
    for (int face = 0; face < kCubeFaces; ++face)
      for (int row = 0; row < level.size; ++row)
        for (int column = 0; column < level.size; ++column) {
          Vec3 v = level.texel(face, column, row);
          EXPECT_NEAR(v.x / L.x, 1.0, 1e-5);
          EXPECT_NEAR(v.z / L.z, 1.0, 1e-5);
        }
  EXPECT_THROW(prefilterEnvironmentCube(renderEquirect(64, 32, [&](Vec3) { return L; }), 24), std::invalid_argument);
  EXPECT_THROW(prefilterEnvironmentCube(renderEquirect(64, 32, [&](Vec3) { return L; }), 8), std::invalid_argument);
}

// The runtime prefilters on every core a scene load can have; the levels must be the same bits
// whatever the count, or renders would depend on the machine.
TEST(CubeMap, PrefilteredLevelsDoNotDependOnTheThreadCount) {
  const EquirectImage source = renderEquirect(64, 32, sunSkyRadiance);
  PrefilterOptions one;
  one.samples = 64;
  one.threads = 1;
  PrefilterOptions three = one;
  three.threads = 3;
  const std::vector<CubeImage> a = prefilterEnvironmentCube(source, 16, one);
  const std::vector<CubeImage> b = prefilterEnvironmentCube(source, 16, three);
  ASSERT_EQ(a.size(), b.size());
  for (size_t m = 0; m < a.size(); ++m) {
    EXPECT_EQ(a[m].size, b[m].size);
    EXPECT_EQ(a[m].rgb, b[m].rgb) << "level " << m;
  }
}

// The same checks as the equirect levels (Prefilter.*): level 0 is the source (read bilinearly
// at each texel's direction), the rough levels are the GGX lobe integral of the radiance
// function: 2 % at level 2, 3 % at level 4, whose RMS error over the level is 2.6 % with the
// default 512 samples (docs/ibl.md, "Prefiltering"; measured here: 2.2 % at worst, level 4 at the
// texel 88° from the sun).
TEST(CubeMap, PrefilteredLevelsMatchTheSourceAndTheLobeIntegral) {
  const auto& levels = prefilteredSunSkyCube();
  const EquirectImage source = renderEquirect(128, 64, sunSkyRadiance);
  const CubeImage& level0 = levels[0];
  for (int face = 0; face < kCubeFaces; ++face)
    for (int row = 0; row < level0.size; row += 3)
      for (int column = 0; column < level0.size; column += 3) {
        double s, t;
        equirectCoordinates(cubeTexelDirection(level0.size, face, column, row), &s, &t);
        Vec3 want = sampleBilinear(source, s, t), got = level0.texel(face, column, row);
        EXPECT_NEAR(got.x, want.x, 1e-5 * want.x);
      }
  Vec3 away = normalize(kSunAxis + Vec3{0.0, -1.2, 0.0});
  for (int m : {2, 4}) {
    const CubeImage& level = levels[size_t(m)];
    double r = prefilterLevelRoughness(m, 5);
    for (Vec3 target : {kSunAxis, away, kSunAxis * -1.0}) {
      int face = 0;
      double s, t;
      cubeCoordinates(target, &face, &s, &t);
      int column = std::min(int(s * level.size), level.size - 1), row = std::min(int(t * level.size), level.size - 1);
      Vec3 want = toVec3(ref::ggxLobeAverageByGrid([](glm::dvec3 d) { return toGlm(sunSkyRadiance(toVec3(d))); },
                                                   toGlm(cubeTexelDirection(level.size, face, column, row)), r * r));
      Vec3 got = level.texel(face, column, row);
      std::printf("cube level %d face %d texel (%d, %d): prefiltered %.4f, lobe integral %.4f\n", m, face, column, row,
                  got.x, want.x);
      const double bound = m == 4 ? 0.03 : 0.02;
      EXPECT_NEAR(got.x / want.x, 1.0, bound) << "level " << m;
      EXPECT_NEAR(got.z / want.z, 1.0, bound) << "level " << m;
    }
  }
}

// The table the runtime links (computed at build time by ibl/tools/write_dfg_table.cpp) is the
// generator's output bit for bit: hexadecimal float literals round-trip exactly.
TEST(Dfg, EmbeddedTableIsTheGeneratedOne) {
  const DfgLut& embedded = embeddedDfgLut();
  EXPECT_EQ(embedded.size, kDfgLutSize);
  EXPECT_EQ(embedded.texels, shippedLut().texels);
}

// The sheen's directional albedo (sheen_lut.h). At r = 1 (α = 1) and n·v = 1: D = 3 sin θ_h / (2π),
// V = 1/4 and θ_h = θ_l / 2, so E = (3/4) ∫₀^{π/2} sin(θ/2) cos θ sin θ dθ = √2/10.
TEST(Sheen, RoughAlbedoAtNormalIncidenceIsRootTwoOverTen) {
  EXPECT_NEAR(integrateSheenAlbedo(1.0, 1.0, kSheenLutSteps), std::sqrt(2.0) / 10.0, 3e-5);
  EXPECT_NEAR(integrateSheenAlbedo(1.0, 1.0, 1024), std::sqrt(2.0) / 10.0, 2e-6);  // converging
}

TEST(Sheen, AlbedoMatchesAFinerGrid) {
  for (double NoV : {1e-4, 0.005, 0.05, 0.3, 1.0}) {
    for (double r : {0.089, 0.2, 0.5, 1.0}) {
      const double fine = integrateSheenAlbedo(NoV, r, 1024), shipped = integrateSheenAlbedo(NoV, r, kSheenLutSteps);
      EXPECT_NEAR(shipped, fine, fine > 1.0 ? 4e-3 * fine : 6e-4) << "n·v " << NoV << " r " << r;
    }
  }
}

// Charlie × Neubelt creates light at grazing views of a narrow lobe; the correction (the lobe ÷
// max(1, E)) bounds the albedo by 1 and leaves every view with n·v ≥ 0.1 as it was. The figures
// of docs/material-models.md ("Cloth", energy) are printed here.
TEST(Sheen, AlbedoExceedsOneAtGrazingViewsAndTheCorrectionBoundsIt) {
  double maxBefore = 0, maxAfter = 0, atNoV = 0, atR = 0, maxAtNormalViews = 0;
  for (double NoV : {1e-4, 1e-3, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0}) {
    for (int i = 0; i <= 16; ++i) {
      const double r = 0.089 + (1.0 - 0.089) * i / 16.0;
      const double E = integrateSheenAlbedo(NoV, r, kSheenLutSteps);
      const SheenTerms corrected = correctedSheen(E);
      EXPECT_NEAR(corrected.albedo, E * corrected.scale, 1e-12);
      if (E > maxBefore) maxBefore = E, atNoV = NoV, atR = r;
      maxAfter = std::max(maxAfter, corrected.albedo);
      if (NoV >= 0.1) maxAtNormalViews = std::max(maxAtNormalViews, E);
    }
  }
  std::printf(
      "sheen albedo: max %.3f at n.v %g, r %.3f before the correction; max %.3f after; max %.3f "
      "over n.v >= 0.1\n",
      maxBefore, atNoV, atR, maxAfter, maxAtNormalViews);
  EXPECT_GT(maxBefore, 3.5);
  EXPECT_EQ(atR, 0.089);
  EXPECT_LE(maxAfter, 1.0);
  EXPECT_LT(maxAtNormalViews, 1.0);
}

// The texels' terms (sheenTexelTerms) blended as the shaders' bilinear filter with clamp to edge
// blends them, at points between the texel centres and in the clamped strips: the corrected lobe
// E(p) · s(p) never exceeds 1 (the table's quadrature at p, in double: what is left is the
// texture's fp16 rounding, which EvalLobeSweep.SheenFurnaceKeepsTheWhiteFurnaceAtEveryPrecision
// measures on the GPU), and the layer over a white base, E(p) · s(p) + 1 − B(p), exceeds it by at
// most the bilinear interpolation error of E (1.4e-4). Every point whose texels' footprints lie at
// n·v ≥ 0.1, where E ≤ 0.953, reads s = 1: nothing is corrected where nothing needed it.
TEST(Sheen, TexelTermsBoundEveryBilinearBlendAndLeaveOpenViewsUncorrected) {
  const SheenLut& lut = embeddedSheenLut();
  const int size = lut.size;
  auto blend = [&](double NoV, double r) {
    const BilinearAxis x = bilinearAxis(NoV, size), y = bilinearAxis(r, size);
    SheenTerms out{0, 0};
    for (auto [c, r2, w] : {std::tuple{x.i0, y.i0, (1 - x.t) * (1 - y.t)}, std::tuple{x.i1, y.i0, x.t * (1 - y.t)},
                            std::tuple{x.i0, y.i1, (1 - x.t) * y.t}, std::tuple{x.i1, y.i1, x.t * y.t}}) {
      const SheenTerms t = sheenTexelTerms(lut, c, r2);
      out.albedo += w * t.albedo, out.scale += w * t.scale;
    }
    return out;
  };
  // n·v from MIN_N_DOT_V through the clamped strip, then every cell at a third and two thirds of
  // its width and the last strip; r from the floor to 1 (the last row's strip).
  std::vector<double> cosines = {1e-4, 1e-3, 2e-3, 4e-3, 6e-3, 1.0};
  for (int i = 0; i < size; ++i)
    for (double f : {1.0 / 3.0, 2.0 / 3.0}) cosines.push_back(dfgLutNoV(i, size) + f / size);
  const double open = 0.1 + 2.0 / size;  // a point's texels lie within 1/size, their footprints 2/size
  double worstLobe = 0, worstLayer = 0, lobeNoV = 0, lobeR = 0, layerNoV = 0, layerR = 0, scaleAtOpen = 1;
  double uncorrectedFrom = 0;  // every n·v beyond it reads s = 1 at every r
  for (double NoV : cosines) {
    if (NoV > 1.0) continue;
    for (double r : {0.089, 0.1, 0.13, 0.17, 0.22, 0.3, 0.4, 0.5, 0.65, 0.8, 0.9, 0.97, 1.0}) {
      const double E = integrateSheenAlbedo(NoV, r, kSheenLutSteps);
      const SheenTerms t = blend(NoV, r);
      const double lobe = E * t.scale, layer = lobe + 1.0 - t.albedo;
      if (lobe > worstLobe) worstLobe = lobe, lobeNoV = NoV, lobeR = r;
      if (layer > worstLayer) worstLayer = layer, layerNoV = NoV, layerR = r;
      if (NoV >= open) scaleAtOpen = std::min(scaleAtOpen, t.scale);
      if (t.scale < 1.0 - 1e-12) uncorrectedFrom = std::max(uncorrectedFrom, NoV);  // the weights' rounding
    }
  }
  std::printf(
      "sheen texel terms: lobe x s at most %.6f (n.v %g, r %.3f), layer at most %.6f (n.v %g, r %.3f); s = 1 "
      "beyond n.v %.4f\n",
      worstLobe, lobeNoV, lobeR, worstLayer, layerNoV, layerR, uncorrectedFrom);
  EXPECT_LE(worstLobe, 1.0 + 1e-9);
  EXPECT_GT(worstLobe, 0.99);  // the bound is reached, not undershot by a blanket scale
  EXPECT_LE(worstLayer, 1.0 + 2e-4);
  EXPECT_GT(scaleAtOpen, 1.0 - 1e-12);
}

TEST(Sheen, EmbeddedTableIsTheGeneratedOne) {
  const SheenLut& embedded = embeddedSheenLut();
  ASSERT_EQ(embedded.size, kDfgLutSize);
  EXPECT_EQ(embedded.albedo, generateSheenLut(kDfgLutSize).albedo);
  // The texel centres of the DFG table (column = n·v, row = r).
  EXPECT_EQ(embedded.at(5, 40), float(integrateSheenAlbedo(dfgLutNoV(5, 64), dfgLutRoughness(40, 64), kSheenLutSteps)));
}
