// Double-precision CPU evaluation of chunks/shading_standard.glsl and the chunks it calls, from
// the same formulas (not the same code): the ground truth the GPU images are checked against.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "facet/ibl/sheen_lut.h"

namespace facet::reference {

inline constexpr double kPi = 3.14159265358979323846;

struct Surface {
  glm::dvec3 baseColor{1.0};
  double metallic = 0;
  double roughness = 1;  // perceptual
  double reflectance = 0.5;
  double ambientOcclusion = 1;
  glm::dvec3 emissive{0.0};
  double clearCoat = 0;           // strength; 0: no coat
  double clearCoatRoughness = 0;  // perceptual
};

// GGX D in the textbook form (the GPU uses the Lagrange form; equal in exact arithmetic).
inline double distributionGgx(double alpha, double NoH) {
  double a2 = alpha * alpha;
  double d = NoH * NoH * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

inline double visibilitySmithGgxCorrelated(double alpha, double NoV, double NoL) {
  double a2 = alpha * alpha;
  double lambdaV = NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2);
  double lambdaL = NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2);
  return 0.5 / (lambdaV + lambdaL);
}

inline glm::dvec3 fresnelSchlick(glm::dvec3 f0, double LoH) { return f0 + (1.0 - f0) * std::pow(1.0 - LoH, 5.0); }

// The clear coat (chunks/clear_coat_ambient.glsl, clear_coat_ggx_kelemen.glsl): Schlick at
// f0 = 0.04 (IOR 1.5), f90 = 1, without the strength.
inline double fresnelClearCoat(double cosTheta) { return 0.04 + 0.96 * std::pow(1.0 - cosTheta, 5.0); }

// Kelemen and Szirmay-Kalos 2001: V = 1 / (4 (l·h)²), unclamped (the chunk's 2^-14 floor on (l·h)²
// is an fp16 bound that acts only where n·v + n·l < 2^-6).
inline double visibilityKelemen(double LoH) { return 0.25 / (LoH * LoH); }

// The coat's lobe f_c = D(α_c) · V_K · Fc(l·h) · strength, α_c = r_c², r_c clamped as the chunk does.
inline double clearCoatLobe(const Surface& s, double NoH, double LoH) {
  double r = std::clamp(s.clearCoatRoughness, 0.089, 1.0);
  return distributionGgx(r * r, NoH) * visibilityKelemen(LoH) * fresnelClearCoat(LoH) *
         std::clamp(s.clearCoat, 0.0, 1.0);
}

// Anisotropy (chunks/anisotropy_frame.glsl, anisotropy_ggx_smith.glsl). (α_t, α_b) for α and
// anisotropy k: Filament's mapping (from Kulla and Conty 2017), each clamped to [α_min, 1] as the chunk
// does, α_min = 0.089².
inline glm::dvec2 anisotropicAlpha(double alpha, double k) {
  k = std::clamp(k, -1.0, 1.0);
  return glm::clamp(alpha * glm::dvec2(1.0 + k, 1.0 - k), 0.089 * 0.089, 1.0);
}

// Burley 2012's anisotropic GGX D in the frame (t, b, n): 1 / (π α_t α_b ((t·h/α_t)² + (b·h/α_b)² + (n·h)²)²).
inline double distributionGgxAnisotropic(double at, double ab, double ToH, double BoH, double NoH) {
  double x = ToH / at, y = BoH / ab;
  double s = x * x + y * y + NoH * NoH;
  return 1.0 / (kPi * at * ab * s * s);
}

// Heitz 2014's height-correlated Smith visibility of the anisotropic GGX, G₂ / (4 n·l n·v).
inline double visibilitySmithGgxCorrelatedAnisotropic(double at, double ab, double ToV, double BoV, double NoV,
                                                      double ToL, double BoL, double NoL) {
  double lambdaV = NoL * glm::length(glm::dvec3(at * ToV, ab * BoV, NoV));
  double lambdaL = NoV * glm::length(glm::dvec3(at * ToL, ab * BoL, NoL));
  return 0.5 / (lambdaV + lambdaL);
}

// D_aniso · V_aniso for unit v, l in the frame t = +x, b = +y, n = +z (n·v clamped as the chunk does).
inline double anisotropicLobe(glm::dvec2 alpha, glm::dvec3 v, glm::dvec3 l) {
  glm::dvec3 h = glm::normalize(v + l);
  double NoV = std::max(v.z, 1e-4), NoL = std::clamp(l.z, 0.0, 1.0);
  return distributionGgxAnisotropic(alpha.x, alpha.y, h.x, h.y, std::clamp(h.z, 0.0, 1.0)) *
         visibilitySmithGgxCorrelatedAnisotropic(alpha.x, alpha.y, v.x, v.y, NoV, l.x, l.y, NoL);
}

// Ambient occlusion (chunks/ambient_occlusion.glsl). Jimenez et al. 2016's multi-bounce visibility
// for visibility V and diffuse albedo ρ (one channel): max(V, ((a V + b) V + c) V).
inline double multiBounceAo(double visibility, double albedo) {
  const double a = 2.0404 * albedo - 0.3324, b = -4.7951 * albedo + 0.6417, c = 2.7552 * albedo + 0.6903;
  return std::max(visibility, ((a * visibility + b) * visibility + c) * visibility);
}

// Lagarde & de Rousiers 2014's specular occlusion: saturate((n·v + V)^(2^(−16α − 1)) − 1 + V).
inline double specularOcclusionLagarde(double NoV, double visibility, double alpha) {
  return std::clamp(std::pow(NoV + visibility, std::exp2(-16.0 * alpha - 1.0)) - 1.0 + visibility, 0.0, 1.0);
}

// The cloth model's sheen lobe (chunks/sheen_charlie_neubelt.glsl) times n·l, without its colour
// and correction: Charlie's D × Neubelt's V (ibl/sheen_lut.h) at α = r², r clamped to 0.089 as the
// chunk's caller does, n·v clamped to MIN_N_DOT_V.
inline double sheenLobeTimesNoL(double perceptualRoughness, double NoV, double NoL, double NoH) {
  const double r = std::clamp(perceptualRoughness, 0.089, 1.0);
  return ibl::charlieDistribution(r * r, NoH) * ibl::neubeltVisibility(std::max(NoV, 1e-4), NoL) * NoL;
}

// Outgoing pre-exposed radiance towards v, for one directional light (l towards the light,
// lightColor pre-exposed) and a constant ambient radiance. specularScale is the tier's
// multiple-scattering compensation, 1 + f0 (1/dfg.y − 1) (chunks/ibl_split_sum.glsl), or 1.
inline glm::dvec3 shadeStandard(const Surface& s, glm::dvec3 n, glm::dvec3 v, glm::dvec3 l, glm::dvec3 lightColor,
                                glm::dvec3 ambient, glm::dvec3 specularScale = glm::dvec3(1.0)) {
  glm::dvec3 baseColor = glm::clamp(s.baseColor, 0.0, 1.0);
  double metallic = glm::clamp(s.metallic, 0.0, 1.0);
  double reflectance = glm::clamp(s.reflectance, 0.0, 1.0);
  glm::dvec3 diffuseColor = (1.0 - metallic) * baseColor;
  glm::dvec3 f0 = glm::dvec3(0.16 * reflectance * reflectance * (1.0 - metallic)) + metallic * baseColor;
  double r = glm::clamp(s.roughness, 0.089, 1.0);
  double alpha = r * r;
  glm::dvec3 h = glm::normalize(v + l);
  double NoV = std::max(glm::dot(n, v), 1e-4);
  double NoL = glm::clamp(glm::dot(n, l), 0.0, 1.0);
  double NoH = glm::clamp(glm::dot(n, h), 0.0, 1.0);
  double LoH = glm::clamp(glm::dot(l, h), 0.0, 1.0);
  glm::dvec3 specular = distributionGgx(alpha, NoH) * visibilitySmithGgxCorrelated(alpha, NoV, NoL) *
                        fresnelSchlick(f0, LoH) * specularScale;
  glm::dvec3 direct = (diffuseColor / kPi + specular) * lightColor * NoL;
  glm::dvec3 ambientTerm = diffuseColor * ambient * glm::clamp(s.ambientOcclusion, 0.0, 1.0);
  if (s.clearCoat > 0) {
    // The ggx_kelemen form, coat normal = n: the base × (1 − Fc(n·v)), the coat's lobe per light
    // and, in a constant environment, the coat's prefiltered radiance is that constant.
    double Fc = fresnelClearCoat(NoV) * std::clamp(s.clearCoat, 0.0, 1.0);
    direct = direct * (1.0 - Fc) + clearCoatLobe(s, NoH, LoH) * lightColor * NoL;
    ambientTerm = ambientTerm * (1.0 - Fc) + ambient * Fc;
  }
  return direct + ambientTerm + s.emissive;
}

}  // namespace facet::reference
