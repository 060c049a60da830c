// ibl/spherical_harmonics.h
// Diffuse image-based lighting from spherical harmonics: project radiance on the real SH basis of
// bands 0–1 (SH2, 4 coefficients), 0–2 (SH3, 9) or 0–4 (SH5, 25, of which band 3's 7 vanish
// under the clamped cosine), convolve with the clamped cosine to get
// irradiance (Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance
// Environment Maps"), and fold the constants so a shader evaluates a polynomial in n
// (Filament's form; Guy's Filament mobile talk, "Spherical harmonics": 2 or 3 bands).
//
// Basis (real, no Condon–Shortley phase), coefficient index k = l(l + 1) + m, d = (x, y, z) unit:
//   k 0: Y00  = 0.282095            = 1/(2√π)
//   k 1: Y1-1 = 0.488603 y          k 2: Y10 = 0.488603 z          k 3: Y11 = 0.488603 x
//           (0.488603 = √(3/4π))
//   k 4: Y2-2 = 1.092548 xy         k 5: Y2-1 = 1.092548 yz        k 7: Y21 = 1.092548 xz
//           (1.092548 = √(15/4π))
//   k 6: Y20  = 0.315392 (3z² − 1)  (√(5/16π))
//   k 8: Y22  = 0.546274 (x² − y²)  (√(15/16π))
//   band 3, k 9..15: y(3x² − y²), xyz, y(5z² − 1), z(5z² − 3), x(5z² − 1), z(x² − y²), x(x² − 3y²)
//   band 4, k 16..24: xy(x² − y²), yz(3x² − y²), xy(7z² − 1), yz(7z² − 3), 35z⁴ − 30z² + 3,
//           xz(7z² − 3), (x² − y²)(7z² − 1), xz(x² − 3y²), x²(x² − 3y²) − y²(3x² − y²)
//   (the standard real forms on the unit sphere; constants in spherical_harmonics.cpp)
// The basis is defined in world coordinates; +z being its polar axis (not +y, the world's up)
// changes nothing but which coefficients a given sky fills.
//
// What the shader receives (shaderIrradianceCoefficients): RGB c_k such that
//   irradiance(n) / π = max(0, Σ_k c_k p_k(n)),
//   p = (1, y, z, x, xy, yz, 3z² − 1, xz, x² − y²)   (first 4 for SH2)
// i.e. c_k = Â_l · K_k · L_k / π with the band factors Â = (π, 2π/3, π/4, 0, −π/24) and the basis constants
// K_k above. Lambert diffuse is then diffuseColor · Σ c_k p_k(n): no π, no constant in the
// shader. Radiance units are the caller's (Facet pre-exposes them on the CPU, docs/lighting-units.md).
#pragma once

#include <functional>
#include <vector>

#include "facet/ibl/equirect_image.h"
#include "facet/ibl/vec3.h"

namespace facet::ibl {

inline constexpr int kMaxShBands = 5;  // l = 0..4: SH3 and the clamped cosine's next non-zero band (Â_3 = 0)
inline constexpr int kMaxShCoefficients = kMaxShBands * kMaxShBands;

/// RGB coefficients of `bands` SH bands (bands² of them), in the k order above.
struct SphericalHarmonics {
  int bands = 0;
  std::vector<Vec3> coefficients;
};

/// Basis values Y_k(d) for k < bands², bands in [1, 5]; d a unit vector.
std::vector<double> shBasis(int bands, Vec3 d);

/// L_k = ∫ L(d) Y_k(d) dω by sphereQuadrature(quadratureOrder): exact for radiance that is a
/// polynomial of degree ≤ 2 · quadratureOrder − 3 in d (every SH3-representable one from order 3).
SphericalHarmonics projectRadiance(const std::function<Vec3(Vec3)>& radiance, int bands, int quadratureOrder = 64);

/// The same integral over an equirectangular image: each texel contributes its value times its
/// solid angle at its centre direction (midpoint rule; error O(1/height²) for smooth skies).
SphericalHarmonics projectRadiance(const EquirectImage& image, int bands);

/// Irradiance E(n) = ∫ L(d) max(0, n·d) dω in SH: band l scaled by Â_l = π, 2π/3, π/4, 0, −π/24.
/// Exact for the projected bands; the error of SH irradiance is only the truncation.
SphericalHarmonics radianceToIrradiance(const SphericalHarmonics& radiance);

/// Σ_k coefficients_k Y_k(d).
Vec3 evaluateSh(const SphericalHarmonics& sh, Vec3 d);

/// The c_k the shader receives (see the header comment), from radiance SH.
std::vector<Vec3> shaderIrradianceCoefficients(const SphericalHarmonics& radiance);

/// What the shader computes from them: max(0, Σ c_k p_k(n)) = irradiance(n)/π, per channel.
Vec3 evaluateShaderIrradiance(const std::vector<Vec3>& coefficients, Vec3 n);

}  // namespace facet::ibl
