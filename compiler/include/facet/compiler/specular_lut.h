// compiler/specular_lut.h
// The 2D table of specular intensity sampled by chunks/specular_lut.glsl (the `lut` tier).
//
// What a texel stores: the GGX lobe with the implicit geometric term (G = n·l n·v, so V = 1/4) and
// no Fresnel (the shader multiplies by f0 and by n·l), written as a function of the cosine between
// the reflected view vector R and the light L instead of n·h:
//   S(R·L, r) = D_GGX(α, n·h') / 4,   n·h'² = (1 + R·L) / 2,   α = max(r, 0.089)²
// n·h' is exact when v = n (then R = n and the angle R–L is twice the angle n–h) and a close
// match near the highlight otherwise (Karis 2014, "Physically Based Shading on Mobile", via
// Zioma 2015, "Optimizing PBR", SIGGRAPH: index by R·L, warp the axis, store intensity / 16).
//
// Mapping (the chunk inverts it): texel (i, j) of a W × H table holds, quantised to 8 bits,
//   round(255 · √min(S(c_i, r_j) / scale, 1)),  u_i = i / (W − 1),  r_j = j / (H − 1),
// (the default Sqrt encoding; Linear drops the √),
// with c_i = u_i^(1/4) (axis ReflectedCosine4: u = (R·L)⁴) or c_i = u_i (axis HalfCosine, the
// n·h table of the talk, kept to measure against; S is then D(α, n·h)/4 with c = n·h).
// The texel centres sit at (i + 0.5)/W, so the chunk samples at u·(W − 1)/W + 0.5/W to hit u_i
// exactly at the table's ends (the peak R·L = 1 is the last column, not half a texel short).
#pragma once

#include <cstdint>
#include <vector>

#include "facet/abi/shader_abi.h"

namespace facet::compiler {

enum class SpecularLutAxis {
  ReflectedCosine4,  // u = max(R·L, 0)⁴ — what chunks/specular_lut.glsl samples
  HalfCosine,        // u = n·h — Zioma's first table; measured in docs/specular-tiers.md only
};

// How a texel's 8 bits hold min(S / scale, 1) = s: linearly (round(255 s)), or as √s
// (round(255 √s), decoded as the square of the filtered value), which spends the steps where
// the lobe's tail is: the step at s is 2√s/255 instead of 1/255, so the tail's steps no longer
// show as rings. Shipped (the chunk decodes Sqrt); measured in docs/specular-tiers.md, "The
// low tier's table".
enum class SpecularLutEncoding {
  Linear,
  Sqrt,
};

struct SpecularLutOptions {
  uint32_t width = 128;  // along u (the warped cosine)
  uint32_t height = 64;  // along perceptual roughness
  SpecularLutAxis axis = SpecularLutAxis::ReflectedCosine4;
  // Decoded intensity = (texel / 255)² · scale (Sqrt; texel / 255 · scale with Linear). 16/π
  // (π folded into the /16 of the talk): a ceiling of 5.09, reached only inside highlights that
  // tone-map to white anyway; 16 measured no better with the √ encoding (docs/specular-tiers.md).
  double scale = 16.0 / 3.14159265358979323846;
  SpecularLutEncoding encoding = SpecularLutEncoding::Sqrt;
  // Each row divided by its lobe's albedo at normal incidence (specularLutAlbedo): the shader
  // scales the lobe by the environment BRDF's albedo E(n·v, r, f0) instead of f0.
  bool normalized = true;
};

// The default table size (the shader ABI's, which the runtime checks packages against) and
// scale; chunks/specular_lut.glsl hard-codes the same numbers.
inline constexpr uint32_t kSpecularLutWidth = abi::kSpecularLutWidth;
inline constexpr uint32_t kSpecularLutHeight = abi::kSpecularLutHeight;
inline constexpr double kSpecularLutScale = 16.0 / 3.14159265358979323846;

struct SpecularLut {
  uint32_t width = 0;
  uint32_t height = 0;
  double scale = 0;
  SpecularLutEncoding encoding = SpecularLutEncoding::Sqrt;
  std::vector<uint8_t> texels;  // row-major, row j = roughness r_j, R8 UNORM
};

/// The unquantised intensity S a texel approximates, for a cosine c on the given axis (R·L or
/// n·h, clamped to [0, 1]) and perceptual roughness r (clamped to [0.089, 1]).
double specularLutIntensity(SpecularLutAxis axis, double cosine, double perceptualRoughness);

/// The directional albedo of the table's lobe S(R·L, r) at normal incidence (v = n, so R·L = n·l):
/// A(r) = ∫ S n·l dω over the hemisphere, in closed form. 1 for a mirror, 1/4 at r = 1: the
/// implicit geometric term (V = 1/4) gives rough lobes a quarter of the light.
double specularLutAlbedo(double perceptualRoughness);

/// Deterministic: the same options give the same bytes on every platform (the only
/// floating-point operations are +, −, ×, ÷ and sqrt, correctly rounded by IEEE 754, and
/// pow(x, 0.25) is taken as sqrt(sqrt(x))).
SpecularLut generateSpecularLut(const SpecularLutOptions& options = {});

}  // namespace facet::compiler
