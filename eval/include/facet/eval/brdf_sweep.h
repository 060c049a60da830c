// `matc eval`'s BRDF-domain sweep: each specular lobe the measured configurations use, run on
// lavapipe in a compute shader over a grid of n·v × n·l × azimuth × roughness × f0, against the
// double-precision GGX / height-correlated Smith / Schlick product (standard_model.h). The images
// measure a lobe where the grid's spheres happen to put it; the sweep measures it everywhere,
// grazing angles and the roughness floor included, and at fp16 where the tier runs mediump.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "facet/eval/compute_evaluator.h"
#include "facet/eval/configurations.h"

namespace facet::eval {

// The sampled domain. Cosines are cell centres (i + 0.5)/n of [0, 1]; perceptual roughness is
// spaced evenly from the shading floor (MIN_PERCEPTUAL_ROUGHNESS = 0.089) to 1; the azimuth of l
// about n, measured from v's, takes π (the plane of the mirror direction), π/2 and 0 (towards
// the viewer).
struct BrdfSweepDomain {
  int cosines = 16;
  int roughnesses = 8;
  std::vector<double> azimuths = {3.14159265358979323846, 1.57079632679489661923, 0.0};
  std::vector<double> f0 = {0.04, 0.5, 1.0};
};

// One lobe at one precision. Errors are on f_s · n·l (the radiance a unit-illuminance light
// leaves towards v), per roughness row: relative RMSE = √(Σ (f − g)²) / √(Σ g²) over the row's
// samples, g the double reference (samples where g's f_s exceeds binary16's range are left out,
// see beyondHalf). Rows are weighed equally (the smooth rows' peaks would
// otherwise outweigh every rough one).
struct BrdfSweepRow {
  std::string lobe;       // "ggx_smith", "ggx_fastv", "zioma", "lut"; the material models' (lobe_sweep.h)
  std::string precision;  // "highp (fp32)" or "mediump (fp16 emulated)"
  std::vector<std::string> configurations;  // the measured configurations this row stands for
  std::vector<double> roughness;            // the rows' perceptual roughness
  std::vector<double> rowRelativeRmse;      // per row
  double meanRelativeRmse = 0;              // mean over rows
  // The same weighed by n·v: what a sphere on screen shows (its pixels per solid angle of view
  // directions go as n·v), so the grazing views, where the cheap lobes differ most, count less.
  std::vector<double> rowScreenRmse;
  double meanScreenRmse = 0;
  double worstRelativeRmse = 0;  // max over rows ...
  double worstRoughness = 0;     // ... and its roughness
  int nonFinite = 0;             // samples that came out inf or NaN
  // Samples left out of the errors: the exact lobe exceeds binary16's 65504 there (the roughness
  // floor near the grazing mirror), where every mediump lobe saturates by design.
  int beyondHalf = 0;
  // The material models' mediump lobes (lobe_sweep.h): PSNR of the fp16-emulated chunk against
  // its highp form over the model's hard cases, and what they are; NaN where not measured,
  // +infinity where identical.
  double hardCasePsnr = std::numeric_limits<double>::quiet_NaN();
  std::string hardCase;
};

// Sweeps every (lobe, precision) pair among `configurations` once, in configuration order.
// Fails with *error on a shader that does not compile or a Vulkan error.
bool sweepBrdfDomain(GpuEvaluator& gpu, const std::vector<Configuration>& configurations, const BrdfSweepDomain& domain,
                     std::vector<BrdfSweepRow>* rows, std::string* error);

}  // namespace facet::eval
