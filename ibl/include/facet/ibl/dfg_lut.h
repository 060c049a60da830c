// ibl/dfg_lut.h
// The split-sum DFG table: the BRDF half of Karis's split-sum image-based lighting (Karis 2013,
// "Real Shading in Unreal Engine 4"), in the layout Filament uses for multiple-scattering energy
// compensation (Guy's Filament mobile talk, the slides after Lagarde & Golubev 2018; Guy &
// Agopian, "Physically Based Rendering in Filament", energy compensation).
//
// BRDF: GGX D (α = r², r = perceptual roughness), height-correlated Smith V, Schlick F with
// f90 = 1 unless the caller passes one. With Fc = (1 − v·h)⁵ the specular environment integral
// for a white environment splits into two numbers that do not depend on f0:
//   ∫ D V F n·l dl = f0 · (albedo − fresnelWeighted) + f90 · fresnelWeighted
//   fresnelWeighted = ∫ D V Fc n·l dl   (Karis's B; texture channel R)
//   albedo          = ∫ D V    n·l dl   (Karis's A + B: the single-scattering albedo at f0 = 1; G)
// so a shader does  specular = mix(dfg.rrr, dfg.ggg, f0)  (for f90 = 1), and the same G channel
// gives the multiple-scattering compensation below.
//
// Sampling. The textbook sampler (h ~ D n·h) is unbiased but at grazing view it wastes most
// samples below the horizon and weighs the rest by up to 4 v·h / n·h: with 1024 Hammersley
// points it reads albedo = 0.9956 at n·v = 1/64, r = 0.5, where the true value is 0.97371
// (tests/ibl/test_ibl.cpp integrates it by brute force). Sampling visible normals instead (Heitz
// 2018) makes each sample's weight F · G2/G1(v) ≤ 1, so the estimate converges fast and can never
// exceed 1 for f0 = 1 (white furnace) by construction.
#pragma once

#include <vector>

namespace facet::ibl {

struct DfgTerms {
  double fresnelWeighted = 0;  // ∫ D V (1 − v·h)⁵ n·l: the f90 coefficient (R)
  double albedo = 0;           // ∫ D V n·l: the f0 = f90 = 1 directional albedo (G)

  double f0Scale() const { return albedo - fresnelWeighted; }  // Karis's A
  double f90Scale() const { return fresnelWeighted; }          // Karis's B
};

enum class DfgSampling {
  VisibleNormals,  // Heitz 2018 VNDF: what the table is built with
  GgxNormals,      // h ~ D n·h: kept to measure the grazing-angle error against (docs/ibl.md)
};

/// The two DFG terms at one (n·v, perceptual roughness) by `samples` Hammersley points.
/// n·v is clamped to [1e-4, 1] (MIN_N_DOT_V of chunks/precision.glsl; at 0 the integral has no
/// view direction) and r to [0, 1]. At r = 0 the result is exactly (Fc(n·v), 1).
DfgTerms integrateDfg(double NoV, double perceptualRoughness, int samples,
                      DfgSampling sampling = DfgSampling::VisibleNormals);

/// Texel (column, row) of a size × size table holds the terms at its centre:
///   n·v = (column + 0.5) / size,   r = (row + 0.5) / size
/// so a shader samples texture(dfgLut, vec2(NoV, perceptualRoughness)) with no remapping, with
/// linear filtering and clamp-to-edge: a texel centre returns exactly its stored value, and below
/// n·v = 0.5/size the edge column is held. Row 0 is the first row uploaded (texture coordinate
/// t = 0 in both GL and Vulkan).
inline double dfgLutNoV(int column, int size) { return (column + 0.5) / size; }
inline double dfgLutRoughness(int row, int size) { return (row + 0.5) / size; }

struct DfgLut {
  int size = 0;
  // size × size × 2 floats, row-major, RG interleaved: [row][column] = {fresnelWeighted, albedo}.
  // Every value lies in [0, 1], so RG16F (filterable in GLES 3.0) keeps it to 2^-11 relative.
  std::vector<float> texels;

  DfgTerms at(int column, int row) const;
  // Bilinear between texel centres ((i + 0.5) / size), clamped at the edges: what
  // texture(facet_dfgLut, vec2(NoV, r)) returns with linear filtering and clamp-to-edge.
  DfgTerms sampleBilinear(double NoV, double perceptualRoughness) const;
};

// 2048 VNDF samples per texel: the integration error (max 2.7e-4 against a brute-force grid,
// tools/measure_ibl) is then below the rounding of RG16F storage (2.4e-4 just under 1), and a
// 64² table takes about a second on one core. Measured numbers in docs/ibl.md.
inline constexpr int kDfgLutSize = 64;
inline constexpr int kDfgLutSamples = 2048;

/// The whole table. Deterministic: the same arguments give the same floats on every run.
DfgLut generateDfgLut(int size = kDfgLutSize, int samplesPerTexel = kDfgLutSamples);

/// Specular environment BRDF for a white environment: f0 · A + f90 · B.
inline double specularEnvironmentBrdf(const DfgTerms& dfg, double f0, double f90 = 1.0) {
  return f0 * dfg.f0Scale() + f90 * dfg.f90Scale();
}

/// Multiple-scattering energy compensation (Filament, after Lagarde & Golubev / Kulla & Conty):
/// the single-scattering lobe loses 1 − albedo of a white furnace; a scaled copy of the same lobe
/// restores it, f_r = f_ss · (1 + f0 (1/albedo − 1)). Multiply both the direct specular and the
/// IBL specular by it. The albedo is smallest at r = 1, n·v = 1 (1 − ln 2 = 0.307: α = 1 makes D
/// = 1/π and V = 1/(2(1 + n·l))), so the factor stays ≤ 3.3 and needs no fp16 clamp.
inline double multiScatterCompensation(const DfgTerms& dfg, double f0) { return 1.0 + f0 * (1.0 / dfg.albedo - 1.0); }

}  // namespace facet::ibl
