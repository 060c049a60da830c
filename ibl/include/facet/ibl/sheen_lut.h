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
// The shaders read those channels bilinearly with clamp to edge, so a texel's value reaches every
// point of its footprint: the cells between it and its neighbours' centres, and for an edge texel
// the strip out to the domain's edge that clamp-to-edge gives it alone. Where E changes fast (a
// smooth sheen at grazing views) the blend of 1/E at the corners exceeds 1/E at the point, and
// below the first column the texel holds E(1/128) while E keeps growing to n·v = 1e-4: the lobe
// then reflected up to 1.25. A convex blend of values each ≤ 1/E(p) is ≤ 1/E(p), so each texel
// stores 1/max(1, E) of the largest E over its footprint (sheenTexelTerms).
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
  // Raw albedos E (before the correction) on (size + 2)² nodes, row-major: the size × size texel
  // centres (n·v = (column + 0.5)/size, r = (row + 0.5)/size) and around them the points where
  // clamp-to-edge stops: column −1 at n·v = MIN_N_DOT_V, column size at n·v = 1, row −1 at
  // r = 0 (clamped to 0.089 like every row below it), row size at r = 1.
  std::vector<float> albedo;

  /// E at a node, column and row in [−1, size].
  double at(int column, int row) const {
    return albedo[std::size_t(row + 1) * std::size_t(size + 2) + std::size_t(column + 1)];
  }
};

/// The n·v and r of a node of SheenLut (column or row in [−1, size]).
double sheenLutNoV(int column, int size);
double sheenLutRoughness(int row, int size);

// 128 cos θ_l steps: within 0.4 % of a 1024-step grid, 5e-4 where E ≤ 1 (Sheen.AlbedoMatchesAFinerGrid);
// the table takes about 2 s of one core at build time.
inline constexpr int kSheenLutSteps = 128;

/// The whole table at the DFG table's size. Deterministic.
SheenLut generateSheenLut(int size, int steps = kSheenLutSteps);

/// What texel (column, row) of the DFG texture's B and A channels holds. s = 1/max(1, E) of the
/// largest E over the texel's footprint, the 3 × 3 nodes around it: the bilinear blend of s at any
/// point p is then ≤ 1/max(1, E(p)) wherever E is monotonic within a cell (its corners bound it),
/// and s = 1 wherever E ≤ 1 over the footprint (every n·v ≥ 0.112). min(E, 1), the environment's
/// weight and the base's b = 1 − B, is the texel's own, except that an edge texel takes the largest
/// over the strip clamp-to-edge gives it alone: elsewhere the blend of B is E's own interpolation
/// (the layer over a white base within 1.5e-4 of 1), while the footprint's largest E would raise
/// the sheen's environment by up to 0.22 beside grazing views, where E crosses 1
/// (docs/material-models.md, "Cloth").
SheenTerms sheenTexelTerms(const SheenLut& lut, int column, int row);

}  // namespace facet::ibl
