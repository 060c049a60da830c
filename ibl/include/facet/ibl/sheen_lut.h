// ibl/sheen_lut.h
// The sheen's directional albedo: the cloth model's environment term and its energy correction
// (docs/material-models.md, "Cloth"). The lobe is Charlie's sheen distribution (A. Estevez and
// C. Kulla, "Production Friendly Microfacet Sheen BRDF", 2017) with Neubelt and Pettineo's
// visibility (D. Neubelt and M. Pettineo, "Crafting a Next-Gen Material Pipeline for The Order:
// 1886", 2013), in Filament's cloth form (R. Guy and M. Agopian, "Physically Based Rendering in
// Filament", §4.12 "Cloth model"), α = r² (r perceptual roughness), no Fresnel:
//   D(h) = (2 + 1/α) · sin(θ_h)^(1/α) / (2π),   V = 1 / (4 (n·l + n·v − n·l · n·v))
//   E(n·v, r) = ∫ D V n·l dω_l   (the albedo at sheenColor = 1)
// E exceeds 1 where the lobe is narrow and the view grazes (D's mass sits on microfacets
// perpendicular to n, which a grazing view sees head-on, and V → 1/(4 n·l) at n·v → 0): the
// correction divides the lobe by max(1, E(n·v, r)), so the corrected albedo is min(E, 1).
// The table is laid out as the DFG table (dfg_lut.h: texel centres at (i + 0.5)/size on both
// axes, n·v along the row); the runtime stores it as the DFG texture's B and A channels.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace facet::ibl {

/// Charlie's D at α (not clamped) and cos θ_h = n·h.
inline double charlieDistribution(double alpha, double NoH) {
  const double invAlpha = 1.0 / alpha;
  const double sin2h = NoH * NoH < 1.0 ? 1.0 - NoH * NoH : 0.0;
  return (2.0 + invAlpha) * std::pow(sin2h, 0.5 * invAlpha) / (2.0 * 3.14159265358979323846);
}
/// Neubelt and Pettineo's visibility.
inline double neubeltVisibility(double NoV, double NoL) { return 1.0 / (4.0 * (NoL + NoV - NoL * NoV)); }

/// E(n·v, r) by a midpoint grid over the hemisphere of l (cos θ_l × azimuth, mirror-symmetric
/// about the plane of v): `steps` cos θ_l intervals and steps/2 azimuths over [0, π].
/// n·v is clamped to [1e-4, 1] (MIN_N_DOT_V), r to [0.089, 1] (MIN_PERCEPTUAL_ROUGHNESS: the
/// shaders clamp r before reading the table, and below it Charlie's D needs ever finer grids).
double integrateSheenAlbedo(double NoV, double perceptualRoughness, int steps);

/// The correction's two numbers from E: the corrected albedo min(E, 1) (the environment's weight)
/// and the lobe's scale 1/max(E, 1). Both lie in [0, 1], so RG16F or two channels of RGBA16F hold them.
struct SheenTerms {
  double albedo = 0;  // min(E, 1)
  double scale = 1;   // 1 / max(E, 1)
};
inline SheenTerms correctedSheen(double E) { return {E < 1.0 ? E : 1.0, E > 1.0 ? 1.0 / E : 1.0}; }

struct SheenLut {
  int size = 0;
  // size × size raw albedos E (before the correction), row-major: [row][column], n·v =
  // (column + 0.5)/size, r = (row + 0.5)/size.
  std::vector<float> albedo;

  double at(int column, int row) const { return albedo[std::size_t(row) * std::size_t(size) + std::size_t(column)]; }
};

// 128 cos θ_l steps: within 0.4 % of a 1024-step grid, 5e-4 where E ≤ 1 (Sheen.AlbedoMatchesAFinerGrid);
// the 64² table takes about 2 s of one core at build time.
inline constexpr int kSheenLutSteps = 128;

/// The whole table at the DFG table's size. Deterministic.
SheenLut generateSheenLut(int size, int steps = kSheenLutSteps);

}  // namespace facet::ibl
