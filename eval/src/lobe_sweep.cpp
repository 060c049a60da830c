#include "facet/eval/lobe_sweep.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "facet/compiler/assemble.h"
#include "facet/eval/standard_model.h"
#include "facet/ibl/bilinear_axis.h"
#include "facet/runtime/environment.h"
#include "sweep_support.h"

namespace facet::eval {
namespace {

using permutations::PrecisionPolicy;
using reference::kPi;

enum class Model { ClearCoat, Anisotropy, Sheen };

// A form must not create light: a directional albedo above 1 + 1e-3 fails (1e-3: the quadrature's
// and binary16's rounding, far below what a lost term gives; docs/eval.md, "The BRDF domain").
constexpr double kFurnaceBound = 1.0 + 1e-3;

// The chunks of one model's lobe form, with the minimal MaterialInputs (and, for the frame, the
// varyings) they read, as the compiler resolves them (compiler::chunkSource). The clear coat's
// environment is a white one: clear_coat_layer is run for the attenuation 1 − Fc(n·v) it leaves
// each light's base.
bool modelChunks(Model model, const std::string& defines, std::vector<std::string>* out, std::string* error) {
  std::string prelude, lobe, inputs;
  std::vector<std::string> names;
  switch (model) {
    case Model::ClearCoat:
      // FACET_CLEAR_COAT_LOBE: the shipped variants' form of the shared GGX denominator.
      inputs =
          "#define FACET_CLEAR_COAT_LOBE 1\n"
          "struct MaterialInputs { float clearCoat; float clearCoatRoughness; };\n"
          "vec3 prefiltered_radiance(vec3 direction, float perceptualRoughness) { return vec3(1.0); }\n";
      names = {"clear_coat_ambient.glsl", "clear_coat_ggx_kelemen.glsl"};
      break;
    case Model::Anisotropy:
      inputs =
          "#define FACET_ANISOTROPY_LOBE 1\n"
          "struct MaterialInputs { float anisotropy; vec3 anisotropyDirection; };\n"
          "vec3 v_normal;\nvec4 v_tangent;\n";
      names = {"brdf_ggx.glsl", "anisotropy_frame.glsl", "anisotropy_ggx_smith.glsl"};
      break;
    case Model::Sheen: names = {"sheen_charlie_neubelt.glsl"}; break;
  }
  if (!compiler::chunkSource({"precision.glsl", "math.glsl"}, &prelude, error)) return false;
  if (!compiler::chunkSource(names, &lobe, error)) return false;
  *out = {defines, prelude, inputs, lobe};
  return true;
}

// Inputs of every request: in0 = (n·v, n·l, φ, r), in1 = (f0, anisotropy k, φ_v, 0); n = +z, the
// tangent +x, v at azimuth φ_v about the tangent, l at φ_v + φ (φ = π: the mirror plane). The
// geometry is formed at highp, as the forward shader forms v, l and h (shading_standard.glsl,
// half_vector); the lobe runs at the default precision.
constexpr const char* kView = R"(
    highp float NoV = in0.x, phiV = in1.z;
    highp vec3 n = vec3(0.0, 0.0, 1.0);
    highp float sinV = sqrt(max(1.0 - NoV * NoV, 0.0));
    highp vec3 v = vec3(sinV * cos(phiV), sinV * sin(phiV), NoV);
    float r = in0.w;
)";

// Per invocation, after kView: what the lobe's chunks set once per pixel.
const char* setup(Model model) {
  switch (model) {
    case Model::ClearCoat:
      return R"(
    shading_clear_coat_normal = n;
    MaterialInputs m = MaterialInputs(1.0, r);
    clear_coat_layer(m, vec3(0.0), v);
)";
    case Model::Anisotropy:
      return R"(
    v_normal = n;
    v_tangent = vec4(1.0, 0.0, 0.0, 1.0);
    MaterialInputs m = MaterialInputs(in1.y, vec3(1.0, 0.0, 0.0));
    anisotropy_frame(m, n);
    anisotropy_setup(m, r * r, n, max(NoV, MIN_N_DOT_V), v);
)";
    case Model::Sheen: return "";
  }
  return "";
}

// Per light direction l (h, n·l, n·h, l·h given): `lobe` = f · n·l for a unit light. The clear
// coat's is the coat alone (strength 1); the anisotropic lobe's Fresnel is Schlick's at f0 = in1.x.
const char* lobe(Model model) {
  switch (model) {
    case Model::ClearCoat: return "float lobe = clear_coat_direct(m, l, h, LoH, vec3(1.0)).x;\n";
    case Model::Anisotropy:
      return "float lobe = anisotropic_ggx_smith(max(NoV, MIN_N_DOT_V), NoL, NoH, l, h) *\n"
             "             fresnel_schlick(vec3(in1.x), LoH).x * NoL;\n";
    case Model::Sheen: return "float lobe = sheen_lobe_times_n_dot_l(r * r, max(NoV, MIN_N_DOT_V), NoL, NoH);\n";
  }
  return "";
}

// The sweep: one light per invocation. result.y, the clear coat's layered form over a white
// Lambertian base: (1/π) n·l · (1 − Fc(n·v)) + f_c n·l.
std::string sweepBody(Model model) {
  return std::string(kView) + setup(model) + R"(
    highp float NoL = in0.y, phi = in0.z;
    highp float sinL = sqrt(max(1.0 - NoL * NoL, 0.0));
    highp vec3 l = vec3(sinL * cos(phiV + phi), sinL * sin(phiV + phi), NoL);
    highp vec3 h = normalize(v + l);
    highp float NoH = clamp(h.z, 0.0, 1.0), LoH = clamp(dot(l, h), 0.0, 1.0);
    )" + lobe(model) +
         "    result.x = lobe;\n" +
         (model == Model::ClearCoat ? "    result.y = (INV_PI * NoL) * shading_clear_coat_attenuation + lobe;\n" : "");
}

// The white furnace of a GGX lobe: E = (1/N) Σ f n·l / pdf(l), h drawn from D(h) n·h by stretching
// the slopes of the isotropic GGX of α = 1 by (α_t, α_b) (Heitz 2014: the anisotropic GGX's slope
// distribution is the stretched isotropic one), N Hammersley points, l = reflect(−v, h),
// pdf(l) = D n·h / (4 v·h) at highp. D cancels in exact arithmetic, so the estimator stays small
// at the roughness floor. `setupCode` and `lobeCode` as setup() and lobe() give them; result.y of
// a layered lobe: the clear coat over a white Lambertian base, whose albedo ∫ (1/π) n·l dω is 1,
// so E_c + (1 − Fc(n·v)).
std::string ggxFurnaceBody(const std::string& setupCode, bool anisotropic, const std::string& lobeCode, bool layered,
                           int samples) {
  const char* alphas = anisotropic ? "highp vec2 a = clamp(r * r * vec2(1.0 + in1.y, 1.0 - in1.y), 0.007921, 1.0);\n"
                                   : "highp vec2 a = vec2(r * r);\n";
  return std::string(kView) + setupCode + "    " + alphas + "    const int N = " + std::to_string(samples) + ";\n" +
         R"(
    highp float sum = 0.0;
    for (int i = 0; i < N; ++i) {
        highp float u1 = (float(i) + 0.5) / float(N);
        highp float u2 = float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10;
        highp vec2 slope = a * (sqrt(u1 / (1.0 - u1)) * vec2(cos(2.0 * PI * u2), sin(2.0 * PI * u2)));
        highp vec3 h = normalize(vec3(-slope, 1.0));
        highp float VoH = dot(v, h);
        highp vec3 l = 2.0 * VoH * h - v;
        if (VoH <= 0.0 || l.z <= 0.0) continue;
        highp float NoL = l.z, NoH = h.z, LoH = clamp(VoH, 0.0, 1.0);
        highp vec2 x = h.xy / a;
        highp float s = dot(x, x) + NoH * NoH;
        highp float pdf = NoH / (PI * a.x * a.y * s * s * 4.0 * VoH);
        )" +
         lobeCode +
         R"(        sum += lobe / pdf;
    }
    result.x = sum / float(N);
)" + (layered ? "    result.y = result.x + shading_clear_coat_attenuation;\n" : "");
}

std::string ggxFurnaceBody(Model model, int samples) {
  return ggxFurnaceBody(setup(model), model == Model::Anisotropy, lobe(model), model == Model::ClearCoat, samples);
}

// A standard specular lobe (brdf_sweep.h's) times n·l for a unit light, with F = 1: f0 = in1.x is 1,
// or for the lut lobe the environment BRDF's albedo at f0 = 1, as the forward shader scales it
// (specularLobeColor). n·v is floored as shading_standard.glsl floors it.
constexpr const char* kStandardLobe =
    "float lobe = specular_lobe(r, r * r, max(NoV, MIN_N_DOT_V), NoL, NoH, LoH, n, v, l, h, vec3(in1.x)).x * NoL;\n";

// The sheen's white furnace: a midpoint grid over cos θ_l × azimuth ∈ [0, π] (mirror-symmetric
// about v's plane), dω = d cos θ_l dφ, as ibl/sheen_lut.h integrates the table.
std::string sheenFurnaceBody(int steps) {
  return std::string(kView) + "    const int STEPS = " + std::to_string(steps) + ";\n" + R"(
    highp float sum = 0.0;
    for (int i = 0; i < STEPS; ++i) {
        highp float NoL = (float(i) + 0.5) / float(STEPS);
        highp float sinL = sqrt(max(1.0 - NoL * NoL, 0.0));
        for (int j = 0; j < STEPS / 2; ++j) {
            highp float phi = PI * (float(j) + 0.5) / float(STEPS / 2);
            highp vec3 l = vec3(sinL * cos(phi), sinL * sin(phi), NoL);
            highp float NoH = clamp(normalize(v + l).z, 0.0, 1.0);
            )" +
         lobe(Model::Sheen) +
         R"(            sum += lobe;
        }
    }
    result.x = sum * (2.0 / float(STEPS)) * (PI / float(STEPS / 2));
)";
}

struct Sample {
  float NoV, NoL, phi, roughness, f0, anisotropy, phiV;
  int row;
};

void push(GpuEvalRequest* request, const Sample& s) {
  request->in0.push_back(glm::vec4(s.NoV, s.NoL, s.phi, s.roughness));
  request->in1.push_back(glm::vec4(s.f0, s.anisotropy, s.phiV, 0.0f));
}

// The double model at the inputs as the GPU sees them: f · n·l, and whether the chunk saturates
// there by design (its D · V beyond binary16's 65504: the grazing mirror at the roughness floor).
struct Exact {
  double value = 0;
  double layered = 0;  // the clear coat over a white Lambertian base
  bool beyondHalf = false;
};

Exact exactLobe(Model model, const Sample& s) {
  const double NoV = s.NoV, NoL = s.NoL, phiV = s.phiV, phiL = double(s.phiV) + double(s.phi);
  const double sinV = std::sqrt(std::max(1.0 - NoV * NoV, 0.0)), sinL = std::sqrt(std::max(1.0 - NoL * NoL, 0.0));
  const glm::dvec3 v(sinV * std::cos(phiV), sinV * std::sin(phiV), NoV);
  const glm::dvec3 l(sinL * std::cos(phiL), sinL * std::sin(phiL), NoL);
  const glm::dvec3 h = glm::normalize(v + l);
  const double NoH = std::clamp(h.z, 0.0, 1.0), LoH = std::clamp(glm::dot(l, h), 0.0, 1.0);
  const double r = s.roughness;
  Exact e;
  switch (model) {
    case Model::ClearCoat: {
      reference::Surface coat;
      coat.clearCoat = 1.0;
      coat.clearCoatRoughness = r;
      e.value = reference::clearCoatLobe(coat, NoH, LoH) * NoL;
      e.layered = NoL / kPi * (1.0 - reference::fresnelClearCoat(std::max(NoV, 1e-4))) + e.value;
      e.beyondHalf = reference::distributionGgx(r * r, NoH) * reference::visibilityKelemen(LoH) > kMediumpMax;
      break;
    }
    case Model::Anisotropy: {
      const glm::dvec2 a = reference::anisotropicAlpha(r * r, s.anisotropy);
      const double DV = reference::anisotropicLobe(a, v, l);
      const double V =
          reference::visibilitySmithGgxCorrelatedAnisotropic(a.x, a.y, v.x, v.y, std::max(NoV, 1e-4), l.x, l.y, NoL);
      e.value = DV * reference::fresnelSchlick(glm::dvec3(s.f0), LoH).x * NoL;
      e.beyondHalf = DV > kMediumpMax || V > kMediumpMax;
      break;
    }
    case Model::Sheen: e.value = reference::sheenLobeTimesNoL(r, NoV, NoL, NoH); break;
  }
  return e;
}

// The sweep's samples of one model: n·v × n·l at the cell-centred cosines × the azimuths of l ×
// roughness rows; the anisotropic lobe also over the anisotropies and the view's azimuth about the
// tangent (the furnace's), and f0 at the ends of the standard sweep's (its Fresnel is Schlick's).
std::vector<Sample> sweepSamples(Model model, const BrdfSweepDomain& d, const LobeFurnaceDomain& f,
                                 std::vector<double>* roughness) {
  const std::vector<double> one = {0.0};
  const std::vector<double>& ks = model == Model::Anisotropy ? f.anisotropies : one;
  const std::vector<double>& phiVs = model == Model::Anisotropy ? f.viewAzimuths : one;
  const std::vector<double> f0s = model == Model::Anisotropy ? std::vector<double>{d.f0.front(), d.f0.back()} : one;
  std::vector<Sample> out;
  roughness->clear();
  for (int row = 0; row < d.roughnesses; ++row) {
    const double r = sweepRoughness(d, row);
    roughness->push_back(r);
    for (double k : ks)
      for (double phiV : phiVs)
        for (double f0 : f0s)
          for (double phi : d.azimuths)
            for (int i = 0; i < d.cosines; ++i)
              for (int j = 0; j < d.cosines; ++j)
                out.push_back({float((i + 0.5) / d.cosines), float((j + 0.5) / d.cosines), float(phi), float(r),
                               float(f0), float(k), float(phiV), row});
  }
  return out;
}

// The hard cases of each model's mediump form (docs/material-models.md's fp16 sections): the
// anisotropic lobe at anisotropy ±1 and the roughness floor around its mirror; the clear coat and
// the sheen at grazing views (n·v from MIN_N_DOT_V to 0.05), smooth to medium roughness.
std::vector<Sample> hardCases(Model model, std::string* what) {
  const std::vector<double> grazing = {1e-4, 1e-3, 5e-3, 0.01, 0.02, 0.05};
  std::vector<double> cosines = grazing;  // l at v's mirror and around it
  for (int i = 0; i < 16; ++i) cosines.push_back((i + 0.5) / 16);
  const std::vector<double> azimuths = {kPi, kPi - 0.01, kPi - 0.03, kPi + 0.1, kPi / 2, 0.0};
  std::vector<Sample> out;
  if (model == Model::Anisotropy) {
    *what = "anisotropy ±1 at r = 0.089, n·v × n·l × 6 azimuths about the mirror × 3 view azimuths";
    for (double k : {1.0, -1.0})
      for (double phiV : {0.0, kPi / 4, kPi / 2})
        for (double phi : azimuths)
          for (double cv : cosines)
            for (double cl : cosines)
              out.push_back({float(cv), float(cl), float(phi), 0.089f, 1.0f, float(k), float(phiV), 0});
    return out;
  }
  *what = model == Model::ClearCoat ? "grazing coat: n·v 1e-4…0.05, r_c 0.089, 0.2, 0.5"
                                    : "grazing sheen: n·v 1e-4…0.05, r 0.089, 0.2, 0.5, 1";
  std::vector<double> roughness = {0.089, 0.2, 0.5};
  if (model == Model::Sheen) roughness.push_back(1.0);
  for (double r : roughness)
    for (double phi : azimuths)
      for (double cv : grazing)
        for (double cl : cosines) out.push_back({float(cv), float(cl), float(phi), float(r), 0.0f, 0.0f, 0.0f, 0});
  return out;
}

// PSNR of `values` against `reference` (highp), peak the reference's largest value: what binary16
// costs the lobe where it is hardest. Samples `left` out: where the exact D · V exceeds binary16's
// 65504 (the grazing mirror of the floor roughness), where the mediump form saturates by design. A
// non-finite mediump value makes it −∞.
double hardCasePsnr(const std::vector<double>& values, const std::vector<double>& reference,
                    const std::vector<bool>& left) {
  double peak = 0, squared = 0;
  size_t count = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) return -std::numeric_limits<double>::infinity();
    if (left[i]) continue;
    peak = std::max(peak, reference[i]);
    squared += (values[i] - reference[i]) * (values[i] - reference[i]);
    ++count;
  }
  if (squared == 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(peak * peak / (squared / double(count)));
}

// The sheen's two terms as the shaders read them: the DFG texture's B (min(E, 1)) and A
// (1/max(E, 1)) channels, RGBA16F, bilinear with clamp to edge at (n·v, r) (sheen_layer.glsl).
glm::dvec2 sheenTerms(double NoV, double perceptualRoughness) {
  const runtime::Texture& texture = runtime::dfgTexture();
  const int size = int(texture.width);
  const std::vector<uint8_t>& bytes = texture.levels.front();
  auto texel = [&](int column, int row) {
    const size_t at = (size_t(row) * size_t(size) + size_t(column)) * 8;
    auto half = [&](size_t c) {
      return double(glm::unpackHalf1x16(uint16_t(bytes[at + 2 * c] | bytes[at + 2 * c + 1] << 8)));
    };
    return glm::dvec2(half(2), half(3));
  };
  const ibl::BilinearAxis x = ibl::bilinearAxis(NoV, size), y = ibl::bilinearAxis(perceptualRoughness, size);
  return glm::mix(glm::mix(texel(x.i0, y.i0), texel(x.i1, y.i0), x.t),
                  glm::mix(texel(x.i0, y.i1), texel(x.i1, y.i1), x.t), y.t);
}

struct Key {
  Model model;
  PrecisionPolicy precision;
  std::vector<std::string> configurations;
};

const char* modelName(Model model) {
  switch (model) {
    case Model::ClearCoat: return "clear_coat ggx_kelemen";
    case Model::Anisotropy: return "anisotropy ggx_smith";
    case Model::Sheen: return "sheen charlie_neubelt";
  }
  return "";
}

bool runOrFail(GpuEvaluator& gpu, const GpuEvalRequest& request, const std::string& what, GpuEvalResult* result,
               std::string* error) {
  *result = gpu.run(request);
  if (result->ok()) return true;
  *error = what + ": " + result->error;
  return false;
}

// The sweep rows of one (model, precision): the lobe against its double model, and the clear
// coat's layered form too; for mediump, each row's hard-case PSNR against the highp chunk.
bool sweepRows(GpuEvaluator& gpu, const Key& key, const BrdfSweepDomain& domain, const LobeFurnaceDomain& furnaceDomain,
               std::vector<BrdfSweepRow>* rows, std::string* error) {
  GpuEvalRequest request;
  const std::string defines = setPrecision(&request, key.precision);
  if (!modelChunks(key.model, defines, &request.chunks, error)) return false;
  request.body = sweepBody(key.model);
  BrdfSweepRow lobeRow;
  lobeRow.lobe = modelName(key.model);
  lobeRow.precision = precisionName(key.precision);
  lobeRow.configurations = key.configurations;
  const std::vector<Sample> grid = sweepSamples(key.model, domain, furnaceDomain, &lobeRow.roughness);
  for (const Sample& s : grid) push(&request, s);
  GpuEvalResult result;
  if (!runOrFail(gpu, request, std::string("BRDF sweep of the ") + lobeRow.lobe + " lobe", &result, error))
    return false;
  BrdfSweepRow layeredRow = lobeRow;
  layeredRow.lobe += " + base";
  RowErrors lobeErrors(lobeRow.roughness.size()), layeredErrors(lobeRow.roughness.size());
  for (size_t i = 0; i < grid.size(); ++i) {
    const Exact e = exactLobe(key.model, grid[i]);
    const size_t row = size_t(grid[i].row);
    lobeErrors.add(row, result.values[i].x, e.value, grid[i].NoV, e.beyondHalf, &lobeRow);
    if (key.model == Model::ClearCoat)
      layeredErrors.add(row, result.values[i].y, e.layered, grid[i].NoV, e.beyondHalf, &layeredRow);
  }
  lobeErrors.finish(&lobeRow);
  layeredErrors.finish(&layeredRow);

  if (key.precision == PrecisionPolicy::Mediump) {
    std::string what;
    const std::vector<Sample> cases = hardCases(key.model, &what);
    GpuEvalRequest highp = request, mediump = request;
    highp.in0.clear(), highp.in1.clear();
    for (const Sample& s : cases) push(&highp, s);
    mediump.in0 = highp.in0, mediump.in1 = highp.in1;
    highp.chunks.front() = setPrecision(&highp, PrecisionPolicy::Highp);
    GpuEvalResult high, half;
    if (!runOrFail(gpu, highp, std::string("hard cases of the ") + lobeRow.lobe + " lobe", &high, error) ||
        !runOrFail(gpu, mediump, std::string("hard cases of the ") + lobeRow.lobe + " lobe", &half, error))
      return false;
    std::vector<bool> left;
    for (const Sample& s : cases) left.push_back(exactLobe(key.model, s).beyondHalf);
    for (int component = 0; component < (key.model == Model::ClearCoat ? 2 : 1); ++component) {
      std::vector<double> a, b;
      for (size_t i = 0; i < cases.size(); ++i)
        a.push_back(half.values[i][component]), b.push_back(high.values[i][component]);
      BrdfSweepRow& row = component == 0 ? lobeRow : layeredRow;
      row.hardCasePsnr = hardCasePsnr(a, b, left);
      row.hardCase = what;
    }
  }
  rows->push_back(std::move(lobeRow));
  if (key.model == Model::ClearCoat) rows->push_back(std::move(layeredRow));
  return true;
}

// The furnace's points: the 8 roughness rows × (anisotropies × view azimuths, for the anisotropic
// lobe) × the furnace's n·v, with f0 = 1.
std::vector<Sample> furnacePoints(const LobeFurnaceDomain& d, const BrdfSweepDomain& sweep, bool anisotropic) {
  const std::vector<double> one = {0.0};
  const std::vector<double>& ks = anisotropic ? d.anisotropies : one;
  const std::vector<double>& phiVs = anisotropic ? d.viewAzimuths : one;
  std::vector<Sample> points;
  for (int row = 0; row < sweep.roughnesses; ++row)
    for (double k : ks)
      for (double phiV : phiVs)
        for (double NoV : d.cosines)
          points.push_back(
              {float(NoV), 0.0f, 0.0f, float(sweepRoughness(sweep, row)), 1.0f, float(k), float(phiV), row});
  return points;
}

LobeFurnaceRow furnaceRow(const std::string& lobe, PrecisionPolicy precision,
                          const std::vector<std::string>& configurations, const std::string& integrand, double bound) {
  LobeFurnaceRow r;
  r.lobe = lobe;
  r.precision = precisionName(precision);
  r.configurations = configurations;
  r.integrand = integrand;
  r.bound = bound;
  r.maxAlbedo = -std::numeric_limits<double>::infinity();
  return r;
}

void note(LobeFurnaceRow* r, double albedo, const Sample& p) {
  // A NaN albedo is the worst of all.
  if (std::isnan(albedo)) albedo = std::numeric_limits<double>::infinity();
  if (albedo <= r->maxAlbedo) return;
  r->maxAlbedo = albedo;
  r->atNoV = p.NoV, r->atRoughness = p.roughness, r->atAnisotropy = p.anisotropy;
}

// The furnace rows of one (model, precision).
bool furnaceRows(GpuEvaluator& gpu, const Key& key, const LobeFurnaceDomain& d, const BrdfSweepDomain& sweep,
                 std::vector<LobeFurnaceRow>* rows, std::string* error) {
  GpuEvalRequest request;
  const std::string defines = setPrecision(&request, key.precision);
  if (!modelChunks(key.model, defines, &request.chunks, error)) return false;
  request.body = key.model == Model::Sheen ? sheenFurnaceBody(d.sheenSteps) : ggxFurnaceBody(key.model, d.ggxSamples);
  const std::vector<Sample> points = furnacePoints(d, sweep, key.model == Model::Anisotropy);
  for (const Sample& p : points) push(&request, p);
  GpuEvalResult result;
  if (!runOrFail(gpu, request, std::string("white furnace of the ") + modelName(key.model) + " lobe", &result, error))
    return false;

  auto row = [&](const std::string& lobe, const std::string& integrand, double bound) {
    return furnaceRow(lobe, key.precision, key.configurations, integrand, bound);
  };
  const std::string name = modelName(key.model);
  std::vector<LobeFurnaceRow> out;
  if (key.model == Model::ClearCoat) {
    out = {row(name, "D V_K Fc(l.h) n.l, strength 1", kFurnaceBound),
           row(name + " + white base", "the coat + a white Lambertian base x (1 - Fc(n.v))", kFurnaceBound)};
    for (size_t i = 0; i < points.size(); ++i) {
      note(&out[0], result.values[i].x, points[i]);
      note(&out[1], result.values[i].y, points[i]);
    }
  } else if (key.model == Model::Anisotropy) {
    out = {row(name, "D V n.l, F = 1, r >= 0.089, anisotropy -1..1", kFurnaceBound)};
    for (size_t i = 0; i < points.size(); ++i) note(&out[0], result.values[i].x, points[i]);
  } else {
    out = {row(name, "D V n.l, before the correction", 0.0),
           row(name + " x s", "the lobe x s = 1/max(1, E over the texel's footprint), the DFG texture's A channel",
               kFurnaceBound),
           row(name + " layer + white base", "the corrected lobe + a white base x b = 1 - min(E, 1) (B channel)",
               kFurnaceBound)};
    for (size_t i = 0; i < points.size(); ++i) {
      const double E = result.values[i].x;
      const glm::dvec2 terms = sheenTerms(points[i].NoV, points[i].roughness);
      note(&out[0], E, points[i]);
      note(&out[1], E * terms.y, points[i]);
      note(&out[2], E * terms.y + (1.0 - terms.x), points[i]);
    }
  }
  for (LobeFurnaceRow& r : out) rows->push_back(std::move(r));
  return true;
}

}  // namespace

bool furnaceStandardLobes(GpuEvaluator& gpu, const std::vector<Configuration>& configurations,
                          const BrdfSweepDomain& domain, const LobeFurnaceDomain& furnaceDomain,
                          std::vector<LobeFurnaceRow>* furnace, std::string* error) {
  std::vector<LobeFurnaceRow> out;
  std::vector<std::pair<permutations::SpecularModel, PrecisionPolicy>> keys;
  for (const Configuration& c : configurations) {
    const auto key = std::make_pair(c.config.specular, c.config.precision);
    auto it = std::find(keys.begin(), keys.end(), key);
    if (it != keys.end()) {
      out[size_t(it - keys.begin())].configurations.push_back(c.name);
      continue;
    }
    const std::string lobeName = axisValue("specular", c.config);
    GpuEvalRequest request;
    GpuR8Texture lut;
    if (!setSpecularLobe(&request, key.first, key.second, &lut, error)) return false;
    request.body = ggxFurnaceBody("", false, kStandardLobe, false, furnaceDomain.ggxSamples);
    const std::vector<Sample> points = furnacePoints(furnaceDomain, domain, false);
    for (Sample p : points) {
      p.f0 = float(specularLobeColor(key.first, p.NoV, p.roughness, 1.0));
      push(&request, p);
    }
    GpuEvalResult result;
    if (!runOrFail(gpu, request, "white furnace of the " + lobeName + " lobe", &result, error)) return false;
    LobeFurnaceRow row = furnaceRow(lobeName, key.second, {c.name}, "f_s n.l, F = 1", kFurnaceBound);
    for (size_t i = 0; i < points.size(); ++i) note(&row, result.values[i].x, points[i]);
    keys.push_back(key);
    out.push_back(std::move(row));
  }
  for (LobeFurnaceRow& r : out) furnace->push_back(std::move(r));
  return true;
}

bool sweepModelLobes(GpuEvaluator& gpu, const ir::Material& material, const std::vector<Configuration>& configurations,
                     const BrdfSweepDomain& domain, const LobeFurnaceDomain& furnaceDomain,
                     std::vector<BrdfSweepRow>* rows, std::vector<LobeFurnaceRow>* furnace, std::string* error) {
  auto applies = [&](const char* axisName) {
    for (const Axis& axis : axes())
      if (std::string(axis.name) == axisName) return !axis.appliesToMaterial || axis.appliesToMaterial(material);
    return false;
  };
  const bool coat = applies("clear_coat"), anisotropy = applies("anisotropy"), sheen = applies("sheen");
  std::vector<Key> keys;
  for (const Configuration& c : configurations) {
    std::vector<Model> models;
    if (coat && c.config.clearCoat == permutations::ClearCoatModel::GgxKelemen) models.push_back(Model::ClearCoat);
    if (anisotropy && c.config.anisotropy == permutations::AnisotropyModel::GgxSmith)
      models.push_back(Model::Anisotropy);
    if (sheen && c.config.sheen == permutations::SheenModel::CharlieNeubelt) models.push_back(Model::Sheen);
    for (Model m : models) {
      auto it = std::find_if(keys.begin(), keys.end(),
                             [&](const Key& k) { return k.model == m && k.precision == c.config.precision; });
      if (it == keys.end()) it = keys.insert(keys.end(), Key{m, c.config.precision, {}});
      it->configurations.push_back(c.name);
    }
  }
  std::stable_sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.model < b.model; });
  for (const Key& key : keys)
    if (!sweepRows(gpu, key, domain, furnaceDomain, rows, error) ||
        !furnaceRows(gpu, key, furnaceDomain, domain, furnace, error))
      return false;
  return true;
}

}  // namespace facet::eval
