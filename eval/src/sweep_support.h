// What the BRDF-domain sweeps share (brdf_sweep.cpp, lobe_sweep.cpp): the request's precision and
// fp16 emulation, and the per-roughness-row errors of BrdfSweepRow.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "facet/eval/brdf_sweep.h"
#include "facet/eval/configurations.h"
#include "facet/permutations/tiers.h"

namespace facet::eval {

// The shading floor of chunks/precision.glsl (MIN_PERCEPTUAL_ROUGHNESS): the lobe never sees less.
inline constexpr double kMinPerceptualRoughness = 0.089;
// binary16's largest finite value (MEDIUMP_FLT_MAX of chunks/precision.glsl).
inline constexpr double kMediumpMax = 65504.0;

// The sweep's roughness rows: evenly from the floor to 1.
double sweepRoughness(const BrdfSweepDomain& domain, int row);

// The value of a configuration's axis (configurations.h), e.g. "ggx_smith" for "specular".
std::string axisValue(const char* axisName, const permutations::TierConfig& config);

// "highp (fp32)" or "mediump (fp16 emulated)".
std::string precisionName(permutations::PrecisionPolicy precision);

// The request at the tier's precision: highp compiles the chunks with FACET_PRECISION_HIGHP (their
// saturations identities); mediump runs with the fp16 emulation pass, which rounds every relaxed
// result to binary16 as a mobile GPU would (docs/fp16-emulation.md), since lavapipe computes
// mediump in fp32. The geometry inputs stay highp (the forward shader forms v, l and h at highp).
// Returns the defines to paste before the chunks.
std::string setPrecision(GpuEvalRequest* request, permutations::PrecisionPolicy precision);

// The request runs the tier's standard specular lobe (`specular_lobe`, compiler::specularLobeSource)
// at `precision`; the lut lobe's table is generated into *lut and bound (*lut outlives the run).
bool setSpecularLobe(GpuEvalRequest* request, permutations::SpecularModel model,
                     permutations::PrecisionPolicy precision, GpuR8Texture* lut, std::string* error);

// What the forward shader passes the lobe for f0: a lobe scaled by the environment BRDF's albedo
// (the lut lobe, SPECULAR_LOBE_SCALED_BY_ALBEDO in shading_standard.glsl) gets E(n·v, r, f0) from
// the runtime's DFG table, sampled as the GPU samples it; the others f0.
double specularLobeColor(permutations::SpecularModel model, double NoV, double perceptualRoughness, double f0);

// Squared errors per roughness row: [0] every sample alike, [1] weighed by n·v (a sphere's pixels
// per solid angle of view directions go as n·v, so grazing views cover few pixels).
class RowErrors {
 public:
  explicit RowErrors(size_t rows) : error_(rows, {0.0, 0.0}), reference_(rows, {0.0, 0.0}) {}
  // One sample of `row`: the GPU's value against the double model's. Non-finite values are counted
  // and left out; so are samples whose exact f_s exceeds binary16's range (`beyondHalf`: every
  // mediump lobe saturates there by design, far above a tone mapper's white).
  void add(size_t row, double value, double expected, double NoV, bool beyondHalf, BrdfSweepRow* out);
  // Fills the row's per-roughness, mean and worst figures.
  void finish(BrdfSweepRow* out) const;

 private:
  std::vector<std::array<double, 2>> error_, reference_;
};

}  // namespace facet::eval
