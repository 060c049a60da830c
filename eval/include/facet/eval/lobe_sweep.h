// The material models' lobes (docs/material-models.md) over the BRDF domain, beside the standard
// lobes of brdf_sweep.h and on the same harness: the clear coat's (Kelemen's V, the coat's Fresnel)
// alone and layered over a base, the anisotropic GGX D and V, and the sheen's Charlie D × Neubelt V,
// each chunk as the compiler assembles it against its double model (standard_model.h), at every
// precision the measured configurations run it; its white furnace, the directional albedo
// E(n·v, r) = ∫ f · n·l dω by quadrature of the chunk's output on the GPU; and, for the mediump
// forms, the chunk's PSNR against its highp form over the model's hard cases.
#pragma once

#include <string>
#include <vector>

#include "facet/eval/brdf_sweep.h"
#include "facet/ir/module.h"

namespace facet::eval {

// The largest directional albedo of one lobe form at one precision over (n·v, r) (and anisotropy
// and the view's azimuth about the tangent for the anisotropic lobe), where it is, and the bound
// it is held to.
struct LobeFurnaceRow {
  std::string lobe;       // e.g. "clear_coat ggx_kelemen + white base"
  std::string precision;  // as BrdfSweepRow's
  std::vector<std::string> configurations;
  std::string integrand;  // what is integrated (the lobe's F, the base, the correction)
  double maxAlbedo = 0;
  double atNoV = 0, atRoughness = 0, atAnisotropy = 0;
  // 1 + 1e-3 where the form must not create light; 0 where the figure is reported only (the sheen
  // before its correction, which the correction exists for).
  double bound = 0;
  bool withinBound() const { return bound <= 0 || maxAlbedo <= bound; }
};

// Quadrature sizes: GGX-distributed half vectors (Hammersley) for the GGX lobes, whose estimator
// f n·l / pdf keeps no D; a midpoint grid over cos θ_l × azimuth for the sheen (Charlie's D is
// broad, its mass at grazing half vectors), as ibl/sheen_lut.h integrates its table.
struct LobeFurnaceDomain {
  // n·v: grazing views (MIN_N_DOT_V, the sheen table's first texel centre 1/128 and below) and the
  // sweep's cell centres (i + 0.5)/16.
  std::vector<double> cosines = {1e-4,    1.0 / 256, 1.0 / 128, 0.02,    0.03125, 0.09375, 0.15625,
                                 0.21875, 0.28125,   0.34375,   0.40625, 0.46875, 0.53125, 0.59375,
                                 0.65625, 0.71875,   0.78125,   0.84375, 0.90625, 0.96875};
  std::vector<double> anisotropies = {-1.0, -0.5, 0.0, 0.5, 1.0};
  std::vector<double> viewAzimuths = {0.0, 0.78539816339744830962, 1.57079632679489661923};  // of v about t
  int ggxSamples = 1024;
  int sheenSteps = 128;  // cos θ_l intervals; steps/2 azimuths over [0, π] (mirror-symmetric)
};

// The white furnace of the standard specular lobes (brdf_sweep.h's `specular_lobe`, F = 1; the lut
// lobe at the environment BRDF's albedo it is scaled by), one row per (lobe, precision) among
// `configurations`, appended to *furnace: GGX's D in fp16 must not gain light where the squares of
// n × h fall below binary16's normals, as the clear coat's did (docs/eval.md, "The BRDF domain").
bool furnaceStandardLobes(GpuEvaluator& gpu, const std::vector<Configuration>& configurations,
                          const BrdfSweepDomain& domain, const LobeFurnaceDomain& furnaceDomain,
                          std::vector<LobeFurnaceRow>* furnace, std::string* error);

// For each model the material writes (clearCoat, anisotropy, sheenColor or the cloth model) and
// each precision its lobe form runs at among `configurations` (clear coat `ggx_kelemen`,
// anisotropy `ggx_smith`, sheen `charlie_neubelt`; the other forms have no per-light lobe):
// sweep rows (appended to *rows) and furnace rows. Nothing for a material that writes none.
bool sweepModelLobes(GpuEvaluator& gpu, const ir::Material& material, const std::vector<Configuration>& configurations,
                     const BrdfSweepDomain& domain, const LobeFurnaceDomain& furnaceDomain,
                     std::vector<BrdfSweepRow>* rows, std::vector<LobeFurnaceRow>* furnace, std::string* error);

}  // namespace facet::eval
