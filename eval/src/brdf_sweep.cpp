#include "facet/eval/brdf_sweep.h"

#include <algorithm>
#include <cmath>

#include "facet/eval/standard_model.h"
#include "sweep_support.h"

namespace facet::eval {
namespace {

using permutations::PrecisionPolicy;
using permutations::SpecularModel;

// The geometry is built at highp from the sampled cosines, as the forward shader forms v, l and
// h at highp (shading_standard.glsl, half_vector); the lobe runs at the default precision.
// n = +z, v in the xz plane, l at azimuth φ from v's.
constexpr const char* kSweepBody = R"(
    highp float NoV = in0.x, NoL = in0.y, phi = in0.z;
    highp vec3 n = vec3(0.0, 0.0, 1.0);
    highp vec3 v = vec3(sqrt(max(1.0 - NoV * NoV, 0.0)), 0.0, NoV);
    highp float sinL = sqrt(max(1.0 - NoL * NoL, 0.0));
    highp vec3 l = vec3(sinL * cos(phi), sinL * sin(phi), NoL);
    highp vec3 h = normalize(v + l);
    float r = in0.w;
    result.xyz = specular_lobe(r, r * r, NoV, NoL, clamp(h.z, 0.0, 1.0), clamp(dot(l, h), 0.0, 1.0), n, v, l, h,
                               vec3(in1.x)) * NoL;
)";

struct Sample {
  float NoV, NoL, phi, roughness, f0;
  int row;
};

// f_s of the exact single-scattering lobe, in double, at the inputs as the GPU sees them.
double referenceLobe(const Sample& s) {
  double NoV = s.NoV, NoL = s.NoL, phi = s.phi;
  glm::dvec3 v(std::sqrt(std::max(1.0 - NoV * NoV, 0.0)), 0.0, NoV);
  double sinL = std::sqrt(std::max(1.0 - NoL * NoL, 0.0));
  glm::dvec3 l(sinL * std::cos(phi), sinL * std::sin(phi), NoL);
  glm::dvec3 h = glm::normalize(v + l);
  double alpha = double(s.roughness) * double(s.roughness);
  double LoH = std::clamp(glm::dot(l, h), 0.0, 1.0);
  return reference::distributionGgx(alpha, std::clamp(h.z, 0.0, 1.0)) *
         reference::visibilitySmithGgxCorrelated(alpha, NoV, NoL) * reference::fresnelSchlick(glm::dvec3(s.f0), LoH).x;
}

std::vector<Sample> samples(const BrdfSweepDomain& d, std::vector<double>* roughness) {
  std::vector<Sample> out;
  roughness->clear();
  for (int k = 0; k < d.roughnesses; ++k) {
    double r = sweepRoughness(d, k);
    roughness->push_back(r);
    for (double f0 : d.f0)
      for (double phi : d.azimuths)
        for (int i = 0; i < d.cosines; ++i)
          for (int j = 0; j < d.cosines; ++j)
            out.push_back(
                {float((i + 0.5) / d.cosines), float((j + 0.5) / d.cosines), float(phi), float(r), float(f0), k});
  }
  return out;
}

bool sweepOne(GpuEvaluator& gpu, SpecularModel model, PrecisionPolicy precision, const BrdfSweepDomain& domain,
              BrdfSweepRow* row, std::string* error) {
  GpuEvalRequest request;
  GpuR8Texture lut;
  if (!setSpecularLobe(&request, model, precision, &lut, error)) return false;
  request.body = kSweepBody;
  std::vector<Sample> grid = samples(domain, &row->roughness);
  for (const Sample& s : grid) {
    request.in0.push_back(glm::vec4(s.NoV, s.NoL, s.phi, s.roughness));
    const double color = specularLobeColor(model, s.NoV, s.roughness, s.f0);
    request.in1.push_back(glm::vec4(float(color), 0.0f, 0.0f, 0.0f));
  }
  GpuEvalResult result = gpu.run(request);
  if (!result.ok()) {
    *error = "BRDF sweep of the " + row->lobe + " lobe: " + result.error;
    return false;
  }
  RowErrors errors(row->roughness.size());
  for (size_t i = 0; i < grid.size(); ++i) {
    const double exactLobe = referenceLobe(grid[i]);
    // Beyond binary16's range (the roughness floor near the grazing mirror: D·V ≈ 1.4e6 at
    // n·v = n·l = 0.03): every mediump lobe saturates at 65504 there by design
    // (specular_ggx_smith.glsl). Left out of every row alike, and counted.
    errors.add(size_t(grid[i].row), result.values[i].x, exactLobe * double(grid[i].NoL), double(grid[i].NoV),
               exactLobe > kMediumpMax, row);
  }
  errors.finish(row);
  return true;
}

}  // namespace

bool sweepBrdfDomain(GpuEvaluator& gpu, const std::vector<Configuration>& configurations, const BrdfSweepDomain& domain,
                     std::vector<BrdfSweepRow>* rows, std::string* error) {
  rows->clear();
  struct Key {
    SpecularModel specular;
    PrecisionPolicy precision;
  };
  std::vector<Key> keys;
  for (const Configuration& c : configurations) {
    auto same = [&](const Key& k) { return k.specular == c.config.specular && k.precision == c.config.precision; };
    auto it = std::find_if(keys.begin(), keys.end(), same);
    if (it != keys.end()) {
      (*rows)[size_t(it - keys.begin())].configurations.push_back(c.name);
      continue;
    }
    BrdfSweepRow row;
    row.lobe = axisValue("specular", c.config);
    row.precision = precisionName(c.config.precision);
    row.configurations.push_back(c.name);
    if (!sweepOne(gpu, c.config.specular, c.config.precision, domain, &row, error)) return false;
    keys.push_back({c.config.specular, c.config.precision});
    rows->push_back(std::move(row));
  }
  return true;
}

}  // namespace facet::eval
