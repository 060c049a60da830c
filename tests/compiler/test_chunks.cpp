// The specular chunks, run on lavapipe and compared with the double-precision references in
// reference/, plus the energy facts the tiers rely on (docs/specular-tiers.md).
//
// lavapipe evaluates every float op in fp32 whatever the declared precision (it ignores
// RelaxedPrecision), so these tests check the formulas and their fp32 evaluation order; each
// test runs the shader with `highp` and with `mediump` as the default float precision, which
// proves the mediump declarations compile. fp16 behaviour is the fp16-emulation build's job
// (docs/fp16-emulation.md).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app_vulkan.h"
#include "facet/compiler/specular_lut.h"
#include "facet/eval/compute_evaluator.h"
#include "facet/eval/standard_model.h"
#include "facet/runtime/vulkan_backend.h"
#include "reference/anisotropy.h"
#include "reference/clear_coat.h"
#include "reference/specular_tiers.h"
#include "test_support.h"

namespace facet {
namespace {

using eval::FloatPrecision;
using eval::GpuEvalRequest;
using reference::kPi;

constexpr double kMediumpMax = 65504.0;     // saturateMediump's ceiling (precision.glsl)
constexpr double kUlp1 = 1.0 / 16777216.0;  // 2^-24: half an fp32 ulp at 1
const FloatPrecision kPrecisions[] = {FloatPrecision::Highp, FloatPrecision::Mediump};

eval::GpuEvaluator& gpu() {
  static eval::GpuEvaluator evaluator;
  return evaluator;
}

// The named chunks' text, in order. `#include` lines are dropped: the list names every chunk a
// test needs, in dependency order (matc's assembly resolves includes; the compute evaluator pastes text).
std::vector<std::string> chunks(std::initializer_list<const char*> names) {
  std::vector<std::string> out;
  for (const char* name : names) {
    std::string text = test::readText(test::sourceDir() + "/chunks/" + name);
    EXPECT_FALSE(text.empty()) << "cannot read chunks/" << name;
    std::string kept;
    for (size_t pos = 0; pos < text.size();) {
      size_t end = std::min(text.find('\n', pos), text.size());
      if (text.compare(pos, 8, "#include") != 0) kept += text.substr(pos, end - pos) + "\n";
      pos = end + 1;
    }
    out.push_back(kept);
  }
  return out;
}

// Runs the request; fails the test (and returns an empty vector) on any compile, Vulkan or
// validation error.
std::vector<glm::vec4> run(GpuEvalRequest request) {
  if (!gpu().ready()) {
    ADD_FAILURE() << "GPU evaluator: " << gpu().initError();
    return {};
  }
  auto result = gpu().run(request);
  if (!result.ok()) {
    ADD_FAILURE() << result.error << "\n--- shader ---\n" << eval::GpuEvaluator::shaderSource(request);
    return {};
  }
  return result.values;
}

// Runs the request with highp and with mediump as the default float precision and calls
// check(i, result) for every input i of each run.
template <typename Check>
void checkAtBothPrecisions(GpuEvalRequest req, Check check) {
  for (FloatPrecision p : kPrecisions) {
    req.precision = p;
    auto out = run(req);
    ASSERT_EQ(out.size(), req.in0.size());
    for (size_t i = 0; i < out.size(); ++i) check(i, out[i]);
  }
}

const std::vector<double> kRoughness{0.089, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 1.0};
const std::vector<double> kCosines{1e-4, 0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 1.0};
const std::vector<double> kNoH{0.0, 0.1, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 0.99, 0.995, 0.999, 0.9999, 0.99999, 1.0};
const std::vector<double> kLoH{0.0, 0.01, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0};

// |gpu − ref| ≤ rel · |ref| + abs, reported with the inputs when it fails.
void expectClose(double gpuValue, double ref, double rel, double abs, const std::string& where) {
  EXPECT_LE(std::abs(gpuValue - ref), rel * std::abs(ref) + abs) << where << ": gpu " << gpuValue << " ref " << ref;
}

TEST(GpuEval, RunsComputeShaderOnLavapipe) {
  GpuEvalRequest req;
  req.body = "result = in0 * 2.0 + in1;";
  req.in0 = {glm::vec4(1, 2, 3, 4), glm::vec4(-1)};
  req.in1 = {glm::vec4(0.5f), glm::vec4(1)};
  auto out = run(req);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0], glm::vec4(2.5f, 4.5f, 6.5f, 8.5f));
  EXPECT_EQ(out[1], glm::vec4(-1.0f));
}

// The evaluator on a device an app made (runtime::AppDevice, as the Vulkan backend runs on one):
// the same values as on a device of its own, the LUT's upload included, nothing for the app's
// validation layer (synchronization validation on) to report, and the app's device left alive.
TEST(GpuEval, RunsOnTheAppsDeviceAndLeavesItAlive) {
  eval::GpuR8Texture texture{2, 2, {0, 64, 128, 255}};
  GpuEvalRequest req;
  req.lut = &texture;
  req.body = "result = in0 * in1 + texture(lut, in0.xy).r;";
  for (int i = 0; i < 100; ++i) {  // more than one work group
    req.in0.push_back(glm::vec4(float(i % 10) / 9.0f, float(i / 10) / 9.0f, 1, 2));
    req.in1.push_back(glm::vec4(float(i)));
  }
  const std::vector<glm::vec4> own = run(req);
  ASSERT_EQ(own.size(), req.in0.size());

  example::AppVulkan app;
  std::string error;
  ASSERT_TRUE(app.create(/*validation=*/true, &error)) << error;
  {
    eval::GpuEvaluator onApp(app.appDevice());
    ASSERT_TRUE(onApp.ready()) << onApp.initError();
    const eval::GpuEvalResult result = onApp.run(req);
    ASSERT_TRUE(result.ok()) << result.error;
    EXPECT_EQ(result.values, own);
  }
  EXPECT_TRUE(app.waitIdle());
  for (const std::string& m : app.validationErrors) ADD_FAILURE() << "Vulkan validation: " << m;

  eval::GpuEvaluator incomplete(runtime::AppDevice{});
  EXPECT_FALSE(incomplete.ready());
  EXPECT_NE(incomplete.initError().find("the app's Vulkan device is incomplete"), std::string::npos)
      << incomplete.initError();
}

// GGX D in the Lagrange form. h is built in double, rounded to float and sent as a vector; the
// reference evaluates the textbook D for the exact direction of that float vector.
// Tolerance 1e-5 relative: the Lagrange form has no cancellation, so the fp32 error is the sum
// of ~8 correctly rounded ops (≤ 2^-24 each) and one division (≤ 2.5 ulp), doubled by the final
// square: < 2e-6. No saturation happens: the peak 1/(π α²) is ≤ 5075 for r ≥ 0.089.
TEST(Chunks, DistributionGgxMatchesReference) {
  GpuEvalRequest req;
  req.chunks = chunks({"precision.glsl", "math.glsl", "ggx_denominator.glsl", "brdf_ggx.glsl"});
  req.body = "result.x = distribution_ggx(in0.x, in1.z, vec3(0.0, 0.0, 1.0), in1.xyz);";
  for (double r : kRoughness)
    for (double c : kNoH) {
      glm::vec3 h(float(std::sqrt(1.0 - c * c)), 0.0f, float(c));
      req.in0.push_back(glm::vec4(float(r * r), 0, 0, 0));
      req.in1.push_back(glm::vec4(h, 0.0f));
    }
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    glm::dvec3 h(req.in1[i]);
    double ref = reference::distributionGgx(double(req.in0[i].x), h.z / glm::length(h));
    expectClose(result.x, ref, 1e-5, 0.0, "alpha=" + std::to_string(req.in0[i].x) + " NoH=" + std::to_string(h.z));
  });
}

// A visibility term V(α, n·v, n·l) over roughness × n·v × n·l, against its double reference
// saturated at 65504 as the chunks saturate it; 1e-5 relative (each test says why that holds).
void checkVisibility(const char* chunk, const char* function, double (*exact)(double, double, double)) {
  GpuEvalRequest req;
  req.chunks = chunks({"precision.glsl", "math.glsl", "ggx_denominator.glsl", chunk});
  req.body = std::string("result.x = ") + function + "(in0.x, in0.y, in0.z);";
  for (double r : kRoughness)
    for (double v : kCosines)
      for (double l : {0.0, 1e-4, 0.01, 0.1, 0.5, 0.9, 1.0})
        req.in0.push_back(glm::vec4(float(r * r), float(v), float(l), 0)), req.in1.push_back({});
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    glm::dvec4 a(req.in0[i]);
    double ref = std::min(exact(a.x, a.y, a.z), kMediumpMax);
    expectClose(result.x, ref, 1e-5, 0.0,
                std::string(function) + " alpha=" + std::to_string(a.x) + " NoV=" + std::to_string(a.y) +
                    " NoL=" + std::to_string(a.z));
  });
}

// Height-correlated Smith V. Tolerance 1e-5 relative: no cancellation (every term is ≥ 0), two
// sqrt (≤ 3 ulp each under Vulkan's rules) and one division (2.5 ulp) in fp32. Where the exact V
// exceeds 65504 (n·l = 0 with n·v ≤ 0.01) the chunk saturates, so the reference is min(V, 65504).
TEST(Chunks, VisibilitySmithGgxCorrelatedMatchesReference) {
  checkVisibility("brdf_ggx.glsl", "visibility_smith_ggx_correlated", reference::visibilitySmithGgxCorrelated);
}

// Schlick F with f90 = 1, per channel. Tolerance 1e-6 absolute: 1 − LoH is exact in fp32
// (Sterbenz) or rounded once, the fifth power by 3 products, then one mad; all values ≤ 1.
TEST(Chunks, FresnelSchlickMatchesReference) {
  GpuEvalRequest req;
  req.chunks = chunks({"precision.glsl", "math.glsl", "ggx_denominator.glsl", "brdf_ggx.glsl"});
  req.body = "result.xyz = fresnel_schlick(in0.xyz, in1.x);";
  for (double f0 : {0.0, 0.02, 0.04, 0.5, 1.0})
    for (double lh : kLoH)
      req.in0.push_back(glm::vec4(float(f0), 0.04f, 0.9f, 0)), req.in1.push_back(glm::vec4(float(lh), 0, 0, 0));
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    glm::dvec3 ref = reference::fresnelSchlick(glm::dvec3(req.in0[i]), double(req.in1[i].x));
    for (int c = 0; c < 3; ++c) expectClose(result[c], ref[c], 0.0, 1e-6, "LoH=" + std::to_string(req.in1[i].x));
  });
}

// Hammon's V. Tolerance 1e-5 relative: mix(a, b, α) = a + (b − a)α with b ≥ a (no cancellation),
// 4 ops and one division in fp32. Saturated at 65504 like the chunk (n·l = 0, small n·v).
TEST(Chunks, VisibilityHammonMatchesReference) {
  checkVisibility("brdf_ggx_fastv.glsl", "visibility_hammon", reference::visibilityHammon);
}

// The Zioma forms against reference::specularZioma over (α, n·h, l·h). in1.x carries sin θ_h
// (from n·h in double, rounded to fp32) for the form that takes n and h.
//  - `specular_zioma_published` and `specular_zioma` compute d = NoH²(α² − 1) + 1 as written
//    (their signature has no n × h), which cancels near the peak: three fp32 roundings of values
//    ≤ 1 put up to 3·2^-24 of absolute error on d, and d appears squared, so the relative error
//    of the result is up to 6·2^-24/d (≤ 0.6 % at the peak of r = 0.089, where d = α² = 6.3e-5).
//  - `specular_zioma_nxh`, the form the mid tier ships, takes d from the Lagrange identity
//    |n × h|² + (α n·h)²: no cancellation, so 1e-5 relative (a handful of ops, one division)
//    holds at the peak too.
void checkZioma(const char* call, const reference::ZiomaCoefficients& k, bool cancels) {
  GpuEvalRequest req;
  req.chunks = chunks({"precision.glsl", "math.glsl", "ggx_denominator.glsl", "specular_zioma.glsl"});
  req.body = std::string("result.x = ") + call + ";";
  for (double r : kRoughness)
    for (double nh : kNoH)
      for (double lh : kLoH) {
        float noh = float(nh);
        req.in0.push_back(glm::vec4(float(r * r), noh, float(lh), 0));
        req.in1.push_back(glm::vec4(float(std::sqrt(1.0 - double(noh) * double(noh))), 0, 0, 0));
      }
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    glm::dvec4 a(req.in0[i]);
    double ref = reference::specularZioma(k, a.x, a.y, a.z);
    double d = a.y * a.y * (a.x * a.x - 1.0) + 1.0;
    expectClose(result.x, ref, 1e-5 + (cancels ? 6.0 * kUlp1 / d : 0.0), 0.0,
                std::string(call) + " alpha=" + std::to_string(a.x) + " NoH=" + std::to_string(a.y) +
                    " LoH=" + std::to_string(a.z));
  });
}

TEST(Chunks, SpecularZiomaPublishedMatchesReference) {
  checkZioma("specular_zioma_published(in0.x, in0.y, in0.z)", reference::kZiomaPublished, true);
}
TEST(Chunks, SpecularZiomaMatchesReference) {
  checkZioma("specular_zioma(in0.x, in0.y, in0.z)", reference::kZiomaFacet, true);
}
TEST(Chunks, SpecularZiomaNxhMatchesReference) {
  checkZioma("specular_zioma_nxh(in0.x, in0.y, vec3(0.0, 0.0, 1.0), vec3(in1.x, 0.0, in0.y), in0.z)",
             reference::kZiomaFacet, false);
}

// The mid tier's fused lobe against reference::specularFusedHammon over (α, n·h, n·v, n·l), n and h
// given as vectors (in1.x carries sin θ_h from n·h in double) as the lobe takes them. Tolerance
// 1e-5 relative: d by the Lagrange identity does not cancel, M has no cancellation (b ≥ a), a
// handful of ops and one division in fp32. Where the exact value exceeds 65504 (the grazing
// mirror peak) the chunk saturates, so the reference is min(spec, 65504).
TEST(Chunks, SpecularFusedHammonMatchesReference) {
  GpuEvalRequest req;
  req.chunks = chunks({"precision.glsl", "math.glsl", "ggx_denominator.glsl", "specular_fused_hammon.glsl"});
  req.body =
      "result.x = specular_fused_hammon(in0.x, in0.z, in0.w, in0.y, vec3(0.0, 0.0, 1.0), vec3(in1.x, 0.0, in0.y));";
  for (double r : kRoughness)
    for (double nh : kNoH)
      for (double nv : {1e-4, 0.01, 0.1, 0.5, 1.0})
        for (double nl : {0.0, 0.01, 0.3, 1.0}) {
          float noh = float(nh);
          req.in0.push_back(glm::vec4(float(r * r), noh, float(nv), float(nl)));
          req.in1.push_back(glm::vec4(float(std::sqrt(1.0 - double(noh) * double(noh))), 0, 0, 0));
        }
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    glm::dvec4 a(req.in0[i]);
    double ref = std::min(reference::specularFusedHammon(a.x, a.z, a.w, a.y), kMediumpMax);
    expectClose(result.x, ref, 1e-5, 0.0,
                "alpha=" + std::to_string(a.x) + " NoH=" + std::to_string(a.y) + " NoV=" + std::to_string(a.z) +
                    " NoL=" + std::to_string(a.w));
  });
}

// The LUT chunk on the GPU against the same table sampled bilinearly in double on the CPU, the
// filtered (√-encoded) value squared. Tolerance 2 LSB of the encoded table, decoded: the GPU
// quantises the bilinear weights (lavapipe: 8 sub-texel bits), which can move a sample by up to
// 1/256 of the difference between neighbouring texels per axis — up to ~1 LSB each on the steep
// flank of a smooth lobe.
TEST(Chunks, SpecularLutMatchesTableSampling) {
  compiler::SpecularLut table = compiler::generateSpecularLut();
  eval::GpuR8Texture texture{table.width, table.height, table.texels};
  GpuEvalRequest req;
  req.chunks = chunks({"precision.glsl", "math.glsl", "specular_lut.glsl"});
  req.lut = &texture;
  req.body = "result.x = specular_lut(lut, in0.x, in0.y);";
  for (int j = 0; j <= 40; ++j)
    for (int i = 0; i <= 120; ++i) {
      double rol = -0.2 + 1.2 * i / 120.0;
      double r = j == 0 ? 0.089 : j / 40.0;
      req.in0.push_back(glm::vec4(float(rol), float(r), 0, 0));
      req.in1.push_back({});
    }
  for (double rol : {0.999, 0.9999, 1.0}) req.in0.push_back(glm::vec4(float(rol), 0.089f, 0, 0)), req.in1.push_back({});
  ASSERT_EQ(table.encoding, compiler::SpecularLutEncoding::Sqrt);
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    double rol = std::clamp(double(req.in0[i].x), 0.0, 1.0), r = req.in0[i].y;
    double u = std::pow(rol, 4.0);
    double encoded = reference::sampleR8Bilinear(table.texels, table.width, table.height,
                                                 reference::lutTexelCoordinate(u, table.width),
                                                 reference::lutTexelCoordinate(r, table.height));
    double ref = table.scale * encoded * encoded;
    double tolerance = table.scale * ((encoded + 2.0 / 255.0) * (encoded + 2.0 / 255.0) - encoded * encoded);
    expectClose(result.x, ref, 0.0, tolerance, "RoL=" + std::to_string(req.in0[i].x) + " r=" + std::to_string(r));
  });
}

// The chunk's hard-coded table size and scale are the generator's defaults.
TEST(SpecularLut, ChunkConstantsMatchGenerator) {
  std::string text = test::readText(test::sourceDir() + "/chunks/specular_lut.glsl");
  EXPECT_NE(text.find("vec2(" + std::to_string(compiler::kSpecularLutWidth) + ".0, " +
                      std::to_string(compiler::kSpecularLutHeight) + ".0)"),
            std::string::npos);
  EXPECT_NE(text.find("SPECULAR_LUT_SCALE = 5.0929582;"), std::string::npos);
  EXPECT_NEAR(compiler::kSpecularLutScale, 5.0929582, 1e-7);
  EXPECT_NE(text.find("return encoded * encoded * SPECULAR_LUT_SCALE;"), std::string::npos);
  compiler::SpecularLut table = compiler::generateSpecularLut();
  EXPECT_EQ(table.width, compiler::kSpecularLutWidth);
  EXPECT_EQ(table.height, compiler::kSpecularLutHeight);
  EXPECT_EQ(table.scale, compiler::kSpecularLutScale);
}

TEST(SpecularLut, GenerationIsDeterministic) {
  EXPECT_EQ(compiler::generateSpecularLut().texels, compiler::generateSpecularLut().texels);
}

// The closed form of the table lobe's albedo at normal incidence (specular_lut.cpp) against a
// quadrature of its definition, A(r) = 2π ∫₀¹ S(μ, r) μ dμ (v = n: R·L = n·l = μ), with the
// peak resolved by μ = 1 − x²: 1 for a mirror, 1/4 at r = 1 (D = 1/π, and the implicit geometric
// term V = 1/4). This is what each row of the table is divided by, so that the shader's
// multiplier, the environment BRDF's albedo E(n·v, r, f0), sets the lobe's energy.
TEST(SpecularLut, LobeAlbedoClosedFormMatchesQuadrature) {
  for (double r : {0.089, 0.15, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0}) {
    const int n = 200000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      double x = (i + 0.5) / n, mu = 1.0 - x * x;
      sum += compiler::specularLutIntensity(compiler::SpecularLutAxis::ReflectedCosine4, mu, r) * mu * 2.0 * x / n;
    }
    EXPECT_NEAR(compiler::specularLutAlbedo(r), 2.0 * 3.14159265358979323846 * sum, 2e-5) << "r=" << r;
  }
  EXPECT_NEAR(compiler::specularLutAlbedo(0.089), 1.0, 2e-3);
  EXPECT_DOUBLE_EQ(compiler::specularLutAlbedo(1.0), 0.25);
}

// What the table stores against the GGX function it is built from (S = D/4 with n·h'² = (1 + R·L)/2,
// divided by the row's albedo A(r)), in the encoded domain e = √min(S/(A·scale), 1) (the √ encoding):
// - at texel centres the only error is 8-bit rounding: ≤ 0.5 LSB of e;
// - between texels, sampled exactly as the chunk does (lerp of e, then squared), for r ≥ 0.3
//   (lobes wider than a few texels) the bilinear error stays ≤ 6 LSB of e (measured 4.83, at
//   r = 0.30, R·L = 0.993: the lobe's steep flank under the ceiling, interpolated across roughness
//   rows; the linear table measured 9.0 of its own LSB); for every r the peak R·L = 1 is exact to 0.5 LSB
//   of e between roughness rows (the last column is the peak, by the mapping).
TEST(SpecularLut, TableMatchesGgxWithinStatedError) {
  compiler::SpecularLut table = compiler::generateSpecularLut();
  ASSERT_EQ(table.encoding, compiler::SpecularLutEncoding::Sqrt);
  const double lsb = 1.0 / 255.0;
  auto e = [&](double rol, double r) {
    double rowAlbedo = compiler::specularLutAlbedo(r);
    return std::sqrt(std::min(
        compiler::specularLutIntensity(compiler::SpecularLutAxis::ReflectedCosine4, rol, r) / (rowAlbedo * table.scale),
        1.0));
  };
  for (uint32_t j = 0; j < table.height; ++j)
    for (uint32_t i = 0; i < table.width; ++i) {
      double u = double(i) / (table.width - 1), r = double(j) / (table.height - 1);
      double stored = table.texels[j * table.width + i] * lsb;
      ASSERT_LE(std::abs(stored - e(std::pow(u, 0.25), r)), 0.5 * lsb + 1e-12) << "texel " << i << "," << j;
    }
  double worst = 0.0, atR = 0, atRoL = 0;
  for (int j = 0; j <= 200; ++j) {
    double r = 0.3 + 0.7 * j / 200.0;
    for (int i = 0; i <= 1000; ++i) {
      double rol = i / 1000.0;
      double sampled = reference::sampleR8Bilinear(table.texels, table.width, table.height,
                                                   reference::lutTexelCoordinate(std::pow(rol, 4.0), table.width),
                                                   reference::lutTexelCoordinate(r, table.height));
      double err = std::abs(sampled - e(rol, r)) / lsb;
      if (err > worst) worst = err, atR = r, atRoL = rol;
    }
  }
  std::printf("√-encoded table: worst bilinear error %.2f LSB of e at r=%.3f RoL=%.3f\n", worst, atR, atRoL);
  EXPECT_LE(worst, 6.0) << "at r=" << atR << " RoL=" << atRoL;
  for (int j = 0; j <= 20; ++j) {
    double r = 0.089 + (1.0 - 0.089) * j / 20.0;
    double peak = reference::sampleR8Bilinear(table.texels, table.width, table.height,
                                              reference::lutTexelCoordinate(1.0, table.width),
                                              reference::lutTexelCoordinate(r, table.height));
    // Rows are at r_j = j/63; between rows the peak is a lerp of two exact (encoded) peaks.
    double x = r * (table.height - 1), j0 = std::floor(x), f = x - j0;
    double expected = e(1.0, j0 / (table.height - 1)) * (1 - f) +
                      e(1.0, std::min(j0 + 1, table.height - 1.0) / (table.height - 1)) * f;
    EXPECT_NEAR(peak, expected, 0.5 * lsb + 1e-9) << "r=" << r;
  }
}

// The white furnace: GGX · Smith (height-correlated) with F = 1 reflects at most all the light
// (single scattering loses energy, never creates it). n·v ∈ [0.05, 1] and tolerance 3e-3: the
// quadrature samples D(h) n·h, whose estimator converges slowly at grazing views (at n·v = 1e-4,
// r = 0.48 it reads 1.011 with 2048 samples, 1.0003 with 2^20); from n·v = 0.05 on, 8192
// samples are within 2e-3 of the converged value.
TEST(Reference, WhiteFurnaceGgxSmithIsAtMostOne) {
  double worst = 0.0;
  for (int j = 0; j <= 20; ++j) {
    double r = 0.089 + (1.0 - 0.089) * j / 20.0;
    for (int i = 0; i <= 19; ++i) {
      double NoV = 0.05 * (i + 1);
      worst = std::max(worst, reference::albedoExact(r * r, NoV, 1.0, 8192));
    }
  }
  EXPECT_LE(worst, 1.0 + 3e-3);
  EXPECT_GT(worst, 0.9);  // and the quadrature sees the lobe: smooth surfaces reflect nearly all of it
}

// The white furnace on the GPU, for the lobe the reference tier ships (specular_ggx_smith.glsl,
// highp): its directional albedo for f0 = 1 is at most 1 and matches the CPU quadrature.
// Each invocation importance-samples h from GGX with 4096 Hammersley points and weighs
// f_s · n·l by 1/pdf(l), pdf(l) = D(h) n·h / (4 v·h). The pdf's D is written here from tan θ_h,
// independently of the chunk's Lagrange form, so the estimate tests D's normalization as well
// as V and F (the CPU quadrature cancels D analytically). The CPU runs the same 4096-point
// estimator, so the two agree to fp32 rounding (measured: max difference 6.8e-6) even where
// the estimate itself is still converging (n·v = 0.05, r = 0.5: 0.9401 at 4096 points, 0.9331
// at 2^20).
TEST(Reference, WhiteFurnaceOfTheShippedLobeOnTheGpu) {
  GpuEvalRequest req;
  req.chunks =
      chunks({"precision.glsl", "math.glsl", "ggx_denominator.glsl", "brdf_ggx.glsl", "specular_ggx_smith.glsl"});
  req.chunks.insert(req.chunks.begin(), "#define FACET_PRECISION_HIGHP 1\n");  // as assembly does for `reference`
  req.body = R"(
    float alpha = in0.x, NoV = in0.y;
    vec3 n = vec3(0.0, 0.0, 1.0), v = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
    const uint N = 4096u;
    float sum = 0.0;
    for (uint i = 0u; i < N; ++i) {
        float u1 = (float(i) + 0.5) / float(N), u2 = float(bitfieldReverse(i)) * 2.3283064365386963e-10;
        float tanTheta = alpha * sqrt(u1 / (1.0 - u1)), phi = 2.0 * PI * u2;
        vec3 h = normalize(vec3(tanTheta * cos(phi), tanTheta * sin(phi), 1.0));
        vec3 l = reflect(-v, h);
        float NoL = l.z, NoH = h.z, VoH = dot(v, h);
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        float cos2 = NoH * NoH, t = 1.0 + tanTheta * tanTheta / (alpha * alpha);
        float D = 1.0 / (PI * alpha * alpha * cos2 * cos2 * t * t);
        vec3 f = specular_lobe(sqrt(alpha), alpha, NoV, NoL, NoH, VoH, n, v, l, h, vec3(1.0));
        sum += f.x * NoL * 4.0 * VoH / (D * NoH);
    }
    result.x = sum / float(N);)";
  std::vector<std::pair<double, double>> points;
  for (double r : {0.089, 0.2, 0.35, 0.5, 0.7, 1.0})
    for (double NoV : {0.05, 0.2, 0.5, 0.8, 1.0}) {
      points.push_back({r, NoV});
      req.in0.push_back(glm::vec4(float(r * r), float(NoV), 0, 0));
      req.in1.push_back({});
    }
  auto out = run(req);
  ASSERT_EQ(out.size(), points.size());
  double worst = 0, maxDiff = 0;
  for (size_t i = 0; i < out.size(); ++i) {
    auto [r, NoV] = points[i];
    double cpu = reference::albedoExact(r * r, NoV, 1.0, 4096);
    worst = std::max(worst, double(out[i].x));
    maxDiff = std::max(maxDiff, std::abs(out[i].x - cpu));
    EXPECT_NEAR(out[i].x, cpu, 1e-3) << "r=" << r << " NoV=" << NoV;
  }
  std::printf("GPU white furnace of the reference lobe: max albedo %.5f, max |GPU - CPU| %.2g\n", worst, maxDiff);
  EXPECT_LE(worst, 1.0 + 3e-3);
  EXPECT_GT(worst, 0.9);
}

// The clear coat's chunks with a minimal MaterialInputs, and the prefiltered environment replaced
// by a constant white one (a white furnace for clear_coat_layer).
std::vector<std::string> clearCoatChunks() {
  std::vector<std::string> out = chunks({"precision.glsl", "math.glsl"});
  out.push_back(
      "#define FACET_CLEAR_COAT_LOBE 1\n"  // the shipped variants' form of ggx_denominator.glsl
      "struct MaterialInputs { float clearCoat; float clearCoatRoughness; };\n"
      "vec3 prefiltered_radiance(vec3 direction, float perceptualRoughness) { return vec3(1.0); }\n");
  for (std::string& text : chunks({"clear_coat_ambient.glsl", "ggx_denominator.glsl", "clear_coat_ggx_kelemen.glsl"}))
    out.push_back(text);
  return out;
}

// The coat's lobe f_c · E · n·l for a unit light, l in the plane of v on the mirror side
// (φ = π) and towards the viewer (φ = 0), over coat roughness × n·v × n·l, against the double
// model (standard_model.h) with the chunks' fp16 bounds: (l·h)² floored at 2^-14 and D · V
// saturated at 65504 (the chunk runs here without FACET_PRECISION_HIGHP). 1e-5 relative: D · V_K
// in one division (k rounded twice), Schlick by products; no cancellation.
TEST(Chunks, ClearCoatLobeMatchesReference) {
  GpuEvalRequest req;
  req.chunks = clearCoatChunks();
  // in0 = (l, coat roughness), in1 = (h, l·h), formed in double on the CPU (n = +z).
  req.body = R"(
    shading_clear_coat_normal = vec3(0.0, 0.0, 1.0);
    result.x = clear_coat_direct(MaterialInputs(1.0, in0.w), in0.xyz, in1.xyz, in1.w, vec3(1.0)).x;)";
  struct Point {
    double r, NoV, NoL, NoH, LoH;
  };
  std::vector<Point> points;
  for (double r : {0.0, 0.089, 0.2, 0.5, 1.0})
    for (double cv : kCosines)
      for (double cl : {0.0, 0.01, 0.1, 0.5, 0.9, 1.0})
        for (double phi : {kPi, 0.0}) {
          glm::dvec3 v(std::sqrt(1.0 - cv * cv), 0.0, cv);
          double sinL = std::sqrt(1.0 - cl * cl);
          glm::dvec3 l(sinL * std::cos(phi), sinL * std::sin(phi), cl);
          glm::dvec3 h = glm::normalize(v + l);
          double LoH = std::clamp(glm::dot(l, h), 0.0, 1.0);
          points.push_back({r, cv, cl, std::clamp(h.z, 0.0, 1.0), LoH});
          req.in0.push_back(glm::vec4(glm::vec3(l), float(r)));
          req.in1.push_back(glm::vec4(glm::vec3(h), float(LoH)));
        }
  for (FloatPrecision p : kPrecisions) {
    req.precision = p;
    auto out = run(req);
    ASSERT_EQ(out.size(), points.size());
    for (size_t i = 0; i < out.size(); ++i) {
      const Point& a = points[i];
      double rc = std::clamp(a.r, 0.089, 1.0);
      double dv = reference::distributionGgx(rc * rc, a.NoH) * 0.25 / std::max(a.LoH * a.LoH, 1.0 / 16384.0);
      dv = std::min(dv, kMediumpMax);
      double ref = dv * reference::fresnelClearCoat(a.LoH) * a.NoL;
      expectClose(out[i].x, ref, 1e-5, 1e-7,
                  "clear coat r=" + std::to_string(a.r) + " NoV=" + std::to_string(a.NoV) +
                      " NoL=" + std::to_string(a.NoL) + " NoH=" + std::to_string(a.NoH));
    }
  }
}

// The cloth model's sheen lobe D · V · n·l (sheen_charlie_neubelt.glsl) over roughness (the floor
// and above) × n·v (grazing included) × n·l × n·h, against the double model
// (standard_model.h sheenLobeTimesNoL). 2e-5 relative: pow(x, 0.5/α) with exponents up to 63
// amplifies fp32's log2/exp2 rounding (≈ 1e-7) to ≈ 4e-6; the rest are products and one division.
TEST(Chunks, SheenLobeMatchesReference) {
  GpuEvalRequest req;
  req.chunks = chunks({"precision.glsl", "math.glsl", "sheen_charlie_neubelt.glsl"});
  // in0 = (r, n·v, n·l, n·h); the caller's clamp of r as shading_cloth.glsl's material_alpha.
  req.body = R"(
    float r = max(in0.x, MIN_PERCEPTUAL_ROUGHNESS);
    result.x = sheen_lobe_times_n_dot_l(r * r, max(in0.y, MIN_N_DOT_V), in0.z, in0.w);)";
  for (double r : {0.0, 0.089, 0.2, 0.5, 1.0})
    for (double cv : kCosines)
      for (double cl : {0.0, 0.01, 0.1, 0.5, 1.0})
        for (double ch : {0.0, 0.05, 0.3, 0.7, 0.99, 1.0})
          req.in0.push_back(glm::vec4(float(r), float(cv), float(cl), float(ch))), req.in1.push_back({});
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    glm::dvec4 a(req.in0[i]);
    double ref = reference::sheenLobeTimesNoL(a.x, a.y, a.z, a.w);
    EXPECT_LE(ref, 5.2);  // the chunk's bound: D ≤ 20.5, V · n·l ≤ 1/4
    expectClose(result.x, ref, 2e-5, 1e-7,
                "r=" + std::to_string(a.x) + " NoV=" + std::to_string(a.y) + " NoL=" + std::to_string(a.z) +
                    " NoH=" + std::to_string(a.w));
  });
}

// clear_coat_layer in a white furnace (the environment 1 everywhere): a base that reflects b ≤ 1
// comes out as mix(b, 1, Fc) ≤ 1, with Fc = Fc(n·v) · strength; and it leaves 1 − Fc for the lights.
TEST(Chunks, ClearCoatLayerIsAConvexMixAndLeavesOneMinusFcForTheLights) {
  GpuEvalRequest req;
  req.chunks = clearCoatChunks();
  req.body = R"(
    shading_clear_coat_normal = vec3(0.0, 0.0, 1.0);
    vec3 v = vec3(sqrt(1.0 - in0.y * in0.y), 0.0, in0.y);
    result.x = clear_coat_layer(MaterialInputs(in0.z, in0.x), vec3(in0.w), v).x;
    result.y = shading_clear_coat_attenuation;)";
  for (double r : {0.089, 0.5, 1.0})
    for (double v : kCosines)
      for (double strength : {0.0, 0.3, 1.0})
        for (double base : {0.0, 0.5, 1.0})
          req.in0.push_back(glm::vec4(float(r), float(v), float(strength), float(base))), req.in1.push_back({});
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    glm::dvec4 a(req.in0[i]);
    double Fc = reference::fresnelClearCoat(std::max(a.y, 1e-4)) * a.z;
    expectClose(result.x, a.w * (1.0 - Fc) + Fc, 0.0, 1e-6, "NoV=" + std::to_string(a.y));
    expectClose(result.y, 1.0 - Fc, 0.0, 1e-6, "NoV=" + std::to_string(a.y));
    EXPECT_LE(result.x, 1.0f + 1e-6f);
  });
}

// The white furnace of the layered model for one light direction at a time: the coat's lobe plus a
// white Lambertian base (albedo exactly 1) under it reflect at most all the light when the base is
// attenuated by the view's Fresnel, 1 − Fc(n·v) (the shipped form, clear_coat_ambient.glsl); with
// Filament's 1 − Fc(l·h) per light they reflect up to 1.66 at grazing views (the figures the chunk
// quotes). 512² deterministic samples; n·v from 0.01 (the CPU quadrature of the coat's part samples
// D n·h, exact for a smooth coat's mirror peak).
TEST(Reference, ClearCoatLayeredFurnaceIsAtMostOne) {
  double worstView = 0, worstHalfVector = 0;
  for (double r : {0.089, 0.2, 0.4, 0.6, 0.8, 1.0})
    for (double NoV : {1.0, 0.7, 0.5, 0.3, 0.2, 0.1, 0.05, 0.02, 0.01}) {
      worstView = std::max(worstView, reference::clearCoatLayeredAlbedo(r, NoV, reference::CoatAttenuation::View));
      worstHalfVector =
          std::max(worstHalfVector, reference::clearCoatLayeredAlbedo(r, NoV, reference::CoatAttenuation::HalfVector));
    }
  std::printf("clear coat + white base, layered albedo: max %.5f (1 - Fc(n.v)), %.5f (1 - Fc(l.h))\n", worstView,
              worstHalfVector);
  EXPECT_LE(worstView, 1.0 + 1e-3);
  EXPECT_GT(worstView, 0.99);  // the quadrature sees the light: a smooth coat at n·v = 1 reflects all of it
  EXPECT_GT(worstHalfVector, 1.5);
}

// The anisotropy chunks with a minimal MaterialInputs and the varyings the frame reads (the
// `ggx_smith` form: FACET_ANISOTROPY_LOBE, so the frame is projected and normalized).
std::vector<std::string> anisotropyChunks() {
  std::vector<std::string> out = chunks({"precision.glsl", "math.glsl"});
  out.push_back(
      "#define FACET_ANISOTROPY_LOBE 1\n"
      "struct MaterialInputs { float anisotropy; vec3 anisotropyDirection; };\n"
      "vec3 v_normal; vec4 v_tangent;\n");
  for (std::string& text :
       chunks({"ggx_denominator.glsl", "brdf_ggx.glsl", "anisotropy_frame.glsl", "anisotropy_ggx_smith.glsl"}))
    out.push_back(text);
  return out;
}

// One light on the anisotropic lobe: in0 = (v, l.x), in1 = (l.y, l.z, anisotropy, roughness),
// n = +z and the mesh's tangent +x (the frame of standard_model.h's anisotropicLobe).
constexpr const char* kAnisotropicLobeBody = R"(
    highp vec3 v = in0.xyz;
    highp vec3 l = vec3(in0.w, in1.x, in1.y);
    highp vec3 h = normalize(v + l);
    vec3 n = vec3(0.0, 0.0, 1.0);
    v_normal = n;
    v_tangent = vec4(1.0, 0.0, 0.0, 1.0);
    MaterialInputs m = MaterialInputs(in1.z, vec3(1.0, 0.0, 0.0));
    float alpha = max(in1.w, MIN_PERCEPTUAL_ROUGHNESS) * max(in1.w, MIN_PERCEPTUAL_ROUGHNESS);
    float NoV = max(v.z, MIN_N_DOT_V);
    anisotropy_frame(m, n);
    anisotropy_setup(m, alpha, n, NoV, v);
    result.x = anisotropic_ggx_smith(NoV, clamp(l.z, 0.0, 1.0), clamp(h.z, 0.0, 1.0), l, h);
    result.y = float(shading_anisotropic_b.y);)";

glm::dvec3 direction(double cosTheta, double phi) {
  double s = std::sqrt(std::max(1.0 - cosTheta * cosTheta, 0.0));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

// The anisotropic lobe on lavapipe against standard_model.h's anisotropicLobe in double, with the
// chunk's saturations (V and D · V at 65504, the chunk running without FACET_PRECISION_HIGHP), over
// roughness × anisotropy × n·v × n·l × the azimuths of v and l about the tangent (the mirror, off it,
// towards the viewer): 1e-4 relative (two divisions, square roots of sums, no cancellation).
TEST(Chunks, AnisotropicLobeMatchesReference) {
  GpuEvalRequest req;
  req.chunks = anisotropyChunks();
  req.body = kAnisotropicLobeBody;
  req.highpInputs = true;
  struct Point {
    double r, k;
    glm::dvec3 v, l;
  };
  std::vector<Point> points;
  for (double r : {0.0, 0.089, 0.2, 0.5, 0.8, 1.0})
    for (double k : {-1.0, -0.5, 0.0, 0.5, 0.8, 1.0})
      for (double cv : {1e-4, 0.05, 0.3, 0.7, 1.0})
        for (double cl : {0.0, 0.05, 0.3, 0.7, 1.0})
          for (double phiV : {0.0, 0.7, kPi / 2})
            for (double dPhi : {kPi, kPi + 0.05, kPi + 0.4, 0.3}) {
              Point p{r, k, direction(cv, phiV), direction(cl, phiV + dPhi)};
              points.push_back(p);
              req.in0.push_back(glm::vec4(glm::vec3(p.v), float(p.l.x)));
              req.in1.push_back(glm::vec4(float(p.l.y), float(p.l.z), float(k), float(r)));
            }
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    const Point& p = points[i];
    glm::dvec3 v = glm::dvec3(glm::vec3(req.in0[i])), l(req.in0[i].w, req.in1[i].x, req.in1[i].y);
    double rc = std::clamp(p.r, 0.089, 1.0);
    glm::dvec2 alpha = reference::anisotropicAlpha(rc * rc, p.k);
    glm::dvec3 h = glm::normalize(v + l);
    double NoV = std::max(v.z, 1e-4), NoL = std::clamp(l.z, 0.0, 1.0);
    double D = reference::distributionGgxAnisotropic(alpha.x, alpha.y, h.x, h.y, std::clamp(h.z, 0.0, 1.0));
    double V =
        std::min(reference::visibilitySmithGgxCorrelatedAnisotropic(alpha.x, alpha.y, v.x, v.y, NoV, l.x, l.y, NoL),
                 kMediumpMax);
    double ref = std::min(D * V, kMediumpMax);
    expectClose(result.x, ref, 1e-4, 1e-7,
                "r=" + std::to_string(p.r) + " k=" + std::to_string(p.k) + " NoV=" + std::to_string(v.z) +
                    " NoL=" + std::to_string(l.z) + " phiV=" + std::to_string(std::atan2(v.y, v.x)));
    EXPECT_NEAR(result.y, 1.0, 1e-6);  // b = n × t = +y
  });
}

// The anisotropic lobe at anisotropy 0 is the isotropic GGX × height-correlated Smith of the
// ggx_smith tiers (the formulas, in double: the same α in both directions), and its D integrates
// to 1 over the projected hemisphere (∫ D n·h dω = 1) whatever the anisotropy.
TEST(Reference, AnisotropicLobeIsTheIsotropicOneAtZeroAndNormalized) {
  for (double r : {0.089, 0.3, 0.7, 1.0})
    for (double cv : {0.05, 0.5, 1.0})
      for (double cl : {0.05, 0.5, 1.0})
        for (double phi : {0.0, 1.0, 2.5}) {
          glm::dvec3 v = direction(cv, 0.3), l = direction(cl, 0.3 + phi);
          glm::dvec3 h = glm::normalize(v + l);
          double a = r * r;
          double iso = reference::distributionGgx(a, h.z) * reference::visibilitySmithGgxCorrelated(a, cv, cl);
          EXPECT_NEAR(reference::anisotropicLobe(reference::anisotropicAlpha(a, 0.0), v, l), iso, 1e-9 * iso);
        }
  for (double r : {0.089, 0.3, 1.0})
    for (double k : {0.0, 0.7, 1.0}) {
      glm::dvec2 alpha = reference::anisotropicAlpha(r * r, k);
      // ∫ D n·h dω by the slope substitution: h = normalize(−x, −y, 1), dω n·h = dx dy / |(x, y, 1)|⁴ · (n·h)... in
      // closed form ∫∫ D(h) (n·h)⁴ dx dy with (n·h)⁴ = 1/(1 + x² + y²)², on a 2000² grid over ±40 α.
      const int n = 2000;
      double sum = 0, wx = 80.0 * alpha.x / n, wy = 80.0 * alpha.y / n;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          double x = -40.0 * alpha.x + (i + 0.5) * wx, y = -40.0 * alpha.y + (j + 0.5) * wy;
          double q = 1.0 + x * x + y * y, NoH = 1.0 / std::sqrt(q);
          sum += reference::distributionGgxAnisotropic(alpha.x, alpha.y, -x * NoH, -y * NoH, NoH) * NoH * NoH * NoH *
                 NoH * wx * wy;
        }
      EXPECT_NEAR(sum, 1.0, 2e-2) << "r=" << r << " k=" << k;
    }
}

// The white furnace of the anisotropic lobe (F = 1): its directional albedo is at most 1 over
// roughness, anisotropy, n·v and the view's azimuth about the tangent (single scattering loses
// energy, never gains it), and above 0.99 for a smooth lobe seen from the front (the quadrature
// sees all of it). Times the isotropic lobe's energy compensation 1/E(α) of the same α (Filament's
// form, which shading_standard.glsl does not apply to this lobe) it exceeds 1.7.
TEST(Reference, AnisotropicFurnaceIsAtMostOne) {
  double worst = 0, worstCompensated = 0, front = 0;
  for (double r : {0.089, 0.2, 0.4, 0.7, 1.0})
    for (double k : {-1.0, 0.0, 0.5, 1.0})
      for (double NoV : {1.0, 0.5, 0.2, 0.05, 0.01})
        for (double phiV : {0.0, kPi / 4, kPi / 2}) {
          glm::dvec2 alpha = reference::anisotropicAlpha(r * r, k);
          double albedo = reference::anisotropicAlbedo(alpha, NoV, phiV, 256);
          worst = std::max(worst, albedo);
          worstCompensated = std::max(worstCompensated, albedo / reference::albedoExact(r * r, NoV, 1.0));
          if (r == 0.089 && NoV == 1.0) front = std::max(front, albedo);
        }
  std::printf("anisotropic GGX/Smith white furnace: max albedo %.5f; x 1/E_iso(alpha): max %.5f\n", worst,
              worstCompensated);
  EXPECT_LE(worst, 1.0 + 1e-3);
  EXPECT_GT(front, 0.99);
  EXPECT_GT(worstCompensated, 1.7);
}

// chunks/ambient_occlusion.glsl against the double forms in eval/standard_model.h.
std::vector<std::string> ambientOcclusionChunks() { return chunks({"precision.glsl", "ambient_occlusion.glsl"}); }

const std::vector<double> kVisibility{0.0, 0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 1.0};

// Jimenez's cubic per channel over visibility × albedo: 1e-6 absolute (Horner terms ≤ 4.2 in fp32).
TEST(Chunks, MultiBounceAoMatchesReference) {
  GpuEvalRequest req;
  req.chunks = ambientOcclusionChunks();
  req.body = "result.xyz = multi_bounce_ao(in0.x, in1.xyz);";
  for (double v : kVisibility)
    for (double albedo : {0.0, 0.02, 0.1, 0.3, 0.5, 0.8, 0.95, 1.0})
      req.in0.push_back(glm::vec4(float(v), 0, 0, 0)), req.in1.push_back(glm::vec4(float(albedo), 0.5f, 1.0f, 0));
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    const double v = req.in0[i].x;
    for (int c = 0; c < 3; ++c)
      expectClose(result[c], reference::multiBounceAo(v, req.in1[i][c]), 0.0, 1e-6,
                  "V=" + std::to_string(v) + " albedo=" + std::to_string(req.in1[i][c]));
  });
}

// Lagarde's specular occlusion over n·v × visibility × roughness: 2e-6 absolute (exp2 and log2 of
// lavapipe's fp32, a few ulp each, on values ≤ 2).
TEST(Chunks, SpecularOcclusionLagardeMatchesReference) {
  GpuEvalRequest req;
  req.chunks = ambientOcclusionChunks();
  req.body = "result.x = specular_occlusion_lagarde(in0.x, in0.y, in0.z * in0.z);";
  for (double NoV : kCosines)
    for (double v : kVisibility)
      for (double r : kRoughness)
        req.in0.push_back(glm::vec4(float(NoV), float(v), float(r), 0)), req.in1.push_back({});
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    const glm::dvec4 a(req.in0[i]);
    expectClose(result.x, reference::specularOcclusionLagarde(a.x, a.y, a.z * a.z), 0.0, 2e-6,
                "NoV=" + std::to_string(a.x) + " V=" + std::to_string(a.y) + " r=" + std::to_string(a.z));
  });
}

// What a material relies on, on the GPU: with V = 1 both factors leave the ambient as it was
// (multi-bounce within 1e-4 above 1: the fit's 0.9996 + 0.0005ρ under the max), multi-bounce
// brightens an occluded bright albedo and not a dark one, and specular occlusion goes to 0 with V
// (at most (1 + e)·V ≤ 1.5·V) and never exceeds 1.
TEST(Chunks, AmbientOcclusionFactorsKeepTheirPromises) {
  GpuEvalRequest req;
  req.chunks = ambientOcclusionChunks();
  req.body = R"(
    result.xyz = multi_bounce_ao(in0.y, in1.xyz);
    result.w = specular_occlusion_lagarde(in0.x, in0.y, in0.z * in0.z);)";
  for (double NoV : kCosines)
    for (double v : kVisibility)
      for (double r : kRoughness)
        req.in0.push_back(glm::vec4(float(NoV), float(v), float(r), 0)),
            req.in1.push_back(glm::vec4(0.9f, 0.02f, 0.0f, 0));
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    const glm::dvec4 a(req.in0[i]);
    const std::string where = "NoV=" + std::to_string(a.x) + " V=" + std::to_string(a.y) + " r=" + std::to_string(a.z);
    if (a.y == 1.0) {
      EXPECT_EQ(result.w, 1.0f) << where;
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(result[c], 1.0f) << where;
        EXPECT_LE(result[c], 1.0001f) << where;
      }
    }
    if (a.y > 0.0 && a.y < 1.0) {
      // Bright albedo 0.9: at least 25 % more light than V alone where V ≤ 0.75 (the fit gives
      // 0.75 → 0.945, 0.5 → 0.855, 0.1 → 0.282); dark albedo 0.02: within 0.1 % of V (the fit
      // exceeds V by at most 0.08 %, near V = 0.9); black: exactly V.
      if (a.y <= 0.75) {
        EXPECT_GT(result.x, 1.25 * a.y) << where;
      }
      EXPECT_LE(result.y, 1.001 * a.y) << where;
      EXPECT_GE(result.y, float(a.y)) << where;
      EXPECT_EQ(result.z, float(a.y)) << where;
    }
    EXPECT_LE(result.w, 1.5 * a.y + 1e-6) << where;
    EXPECT_GE(result.w, 0.0f) << where;
    EXPECT_LE(result.w, 1.0f) << where;
  });
}

// The published fused V·F creates energy: for f0 = 1 and a smooth surface the mirror lobe's
// albedo tends to 1/(α + 0.5) → 2.
TEST(Zioma, PublishedFormCreatesEnergy) {
  double worst = 0.0;
  for (double r : {0.089, 0.1, 0.2})
    for (double NoV : {0.5, 0.8, 1.0})
      worst = std::max(worst, reference::albedoZioma(reference::kZiomaPublished, r * r, NoV, 1.0));
  EXPECT_GT(worst, 1.5);
}

// Facet's refit does not: directional albedo ≤ 1 for f0 = 1 over NoV ∈ [1e-4, 1] and
// r ∈ [0.089, 1] (31 × 31 grid, 4096 samples each), for the exact coefficients the chunk uses
// (Chunks.SpecularZiomaMatchesReference ties the chunk to reference::kZiomaFacet). The fit kept
// a 0.5 % margin (≤ 0.995 on its grid), larger than the quadrature error.
TEST(Zioma, FacetFormConservesEnergy) {
  double worst = 0.0, atR = 0, atV = 0;
  for (int j = 0; j <= 30; ++j) {
    double r = 0.089 + (1.0 - 0.089) * j / 30.0;
    for (int i = 0; i <= 30; ++i) {
      double NoV = i == 0 ? 1e-4 : i / 30.0;
      double a = reference::albedoZioma(reference::kZiomaFacet, r * r, NoV, 1.0, 4096);
      if (a > worst) worst = a, atR = r, atV = NoV;
    }
  }
  EXPECT_LE(worst, 1.0) << "at r=" << atR << " NoV=" << atV;
}

// The mid tier's fused lobe creates no energy: for f0 = 1 over NoV ∈ [1e-4, 1] and r ∈ [0.089, 1]
// (31 × 31 grid, 4096 samples each) its directional albedo is never above the exact
// single-scattering lobe's (GGX × height-correlated Smith, ≤ 1) by the same quadrature, and ≤ 1
// wherever the quadrature resolves the exact lobe to ≤ 1. (At n·v = 1e-4 the quadrature itself
// reads 1.0076 for the exact lobe; the fused one 1.0074 there.)
TEST(FusedHammon, ConservesEnergy) {
  for (int j = 0; j <= 30; ++j) {
    double r = 0.089 + (1.0 - 0.089) * j / 30.0, alpha = r * r;
    for (int i = 0; i <= 30; ++i) {
      double NoV = i == 0 ? 1e-4 : i / 30.0;
      double fused = reference::albedoFusedHammon(alpha, NoV, 1.0, 4096);
      double exact = reference::directionalAlbedo(
          alpha, NoV,
          [&](double nv, double nl, double, double) { return reference::visibilitySmithGgxCorrelated(alpha, nv, nl); },
          4096);
      EXPECT_LE(fused, exact + 1e-6) << "at r=" << r << " NoV=" << NoV;
      if (exact <= 1.0) {
        EXPECT_LE(fused, 1.0) << "at r=" << r << " NoV=" << NoV;
      }
    }
  }
}

// --- post pass chunks ---

namespace {

// Khronos PBR Neutral in double, from the formulas in chunks/tonemap_neutral.glsl's header.
glm::dvec3 khronosNeutral(glm::dvec3 c) {
  const double start = 0.76, knee = 0.24;
  c = glm::clamp(c, 0.0, 1024.0);
  const double low = std::min(c.r, std::min(c.g, c.b));
  c -= low < 0.08 ? low - 6.25 * low * low : 0.04;
  const double peak = std::max(c.r, std::max(c.g, c.b));
  if (peak < start) return c;
  const double compressed = 1.0 - knee * knee / (peak + knee - start);
  c *= compressed / peak;
  const double toWhite = 1.0 - 1.0 / (0.15 * (peak - compressed) + 1.0);
  return c * (1.0 - toWhite) + glm::dvec3(compressed) * toWhite;
}

}  // namespace

// The neutral curve keeps colours below its knee (hue and saturation as authored, minus the
// black-level offset) and compresses above it, continuously. Tolerance 2e-6 absolute: no
// cancellation beyond 1 − d²/(…) near 1, each op correctly rounded in fp32.
TEST(PostChunks, KhronosNeutralToneCurveMatchesReference) {
  GpuEvalRequest req;
  req.chunks = chunks({"tonemap_neutral.glsl"});
  req.body = "result.xyz = tonemap_khronos_neutral(in0.xyz);";
  for (double v : {0.0, 0.01, 0.05, 0.079, 0.081, 0.2, 0.5, 0.75, 0.77, 1.0, 2.0, 10.0, 100.0, 1e4})
    for (glm::dvec3 tint : {glm::dvec3(1, 1, 1), glm::dvec3(1, 0.5, 0.2), glm::dvec3(0.1, 0.3, 1)}) {
      req.in0.push_back(glm::vec4(glm::vec3(tint * v), 0));
      req.in1.push_back({});
    }
  checkAtBothPrecisions(req, [&](size_t i, const glm::vec4& result) {
    const glm::dvec3 ref = khronosNeutral(glm::dvec3(req.in0[i]));
    for (int c = 0; c < 3; ++c) expectClose(result[c], ref[c], 0.0, 2e-6, "in " + std::to_string(req.in0[i][c]));
  });
  // Below the knee, a colour keeps its ratios (after the 0.04 offset): what the curve is for.
  const glm::dvec3 mid = khronosNeutral({0.5, 0.25, 0.125});
  EXPECT_NEAR((mid.r) / (mid.g), (0.5 - 0.04) / (0.25 - 0.04), 1e-12);
}

// Dither noise: triangular over (−1, 1) 8-bit steps, zero mean; a gradient flatter than one step
// per pixel keeps its local mean (no bands) with it, and bands without it.
TEST(PostChunks, TriangularDitherRemovesBandingFromASlowGradient) {
  constexpr int kWidth = 256, kHeight = 64;
  GpuEvalRequest req;
  req.chunks = chunks({"dither.glsl"});
  // in0.x: the encoded value; in1.xy: the pixel. result.x: dithered, result.y: the noise in steps.
  req.body =
      "result.x = dither_triangular_8bit(vec3(in0.x), in1.xy).x;\n"
      "result.y = (dither_triangular_8bit(vec3(0.5), in1.xy).x - 0.5) * 255.0;";
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      // Four 8-bit steps over 256 pixels: 1/64 of a step per pixel.
      req.in0.push_back(glm::vec4(float((100.0 + 4.0 * x / kWidth) / 255.0), 0, 0, 0));
      req.in1.push_back(glm::vec4(x + 0.5f, y + 0.5f, 0, 0));
    }
  req.precision = FloatPrecision::Mediump;
  const auto out = run(req);
  ASSERT_EQ(out.size(), req.in0.size());
  double sum = 0, nearZero = 0;
  for (const glm::vec4& r : out) {
    EXPECT_GT(r.y, -1.0f);
    EXPECT_LT(r.y, 1.0f);
    sum += r.y;
    nearZero += std::abs(r.y) < 0.5f ? 1 : 0;
  }
  EXPECT_NEAR(sum / double(out.size()), 0.0, 0.02);
  EXPECT_NEAR(nearZero / double(out.size()), 0.75, 0.05) << "a triangular PDF puts 3/4 within half a step";
  // Each column's mean 8-bit value against the gradient: within 0.15 step with dither; without
  // it the columns between two levels are off by up to half a step (bands).
  double worstDithered = 0, worstPlain = 0;
  for (int x = 0; x < kWidth; ++x) {
    double dithered = 0, plain = 0;
    for (int y = 0; y < kHeight; ++y) {
      const size_t i = size_t(y) * kWidth + size_t(x);
      dithered += std::round(std::clamp(double(out[i].x), 0.0, 1.0) * 255.0);
      plain += std::round(double(req.in0[i].x) * 255.0);
    }
    const double exact = 100.0 + 4.0 * x / kWidth;
    worstDithered = std::max(worstDithered, std::abs(dithered / kHeight - exact));
    worstPlain = std::max(worstPlain, std::abs(plain / kHeight - exact));
  }
  EXPECT_LT(worstDithered, 0.15);
  EXPECT_GT(worstPlain, 0.45);
}

}  // namespace
}  // namespace facet
