// The clear coat's lobe for each light (the `ggx_kelemen` clear coat of reference and high):
//   f_c  = D(h; α_c) · V_K(l·h) · Fc(l·h)              α_c = r_c², Fc with the strength (clear_coat_ambient.glsl)
//   V_K  = 1 / (4 (l·h)²)                               Kelemen and Szirmay-Kalos 2001
//   L    = L_base · (1 − Fc(n_c·v)) + f_c · E_light · n_c·l
// (the base's attenuation is the view's, shading_clear_coat_attenuation: clear_coat_ambient.glsl
// has why, and the lobe's own Fc is at l·h as the talk's)
// Sources: R. Guy and M. Agopian, "Physically Based Rendering in Filament", "Clear coat model"
// (isotropic GGX, Kelemen's visibility: a smooth coat over a rough base needs no Smith term's
// cost, and f0 fixed at 0.04); Kelemen and Szirmay-Kalos, "A Microfacet Based Coupled
// Specular-Matte BRDF Model with Importance Sampling", Eurographics 2001 (V_K). GGX D is
// brdf_ggx.glsl's Lagrange form; h is the base lobe's half vector (l and v are shared, only the
// normal differs), formed in highp where the tier asks (shading_standard.glsl, half_vector).
// Energy: the layered directional albedo (coat lobe + base × (1 − Fc)) is integrated in double
// in tests/reference/clear_coat.h against 1 (docs/material-models.md, "Energy").
// fp16 (both hazards the talk names, each bounded here):
// - D at a smooth coat: α_c² = r_c⁴ in the textbook denominator underflows binary16 below
//   r_c = 0.0884; the clamp to MIN_PERCEPTUAL_ROUGHNESS (0.089, r⁴ = 6.27e-5 ≥ 2^-14) and the
//   Lagrange form keep D ≤ 1/(π α_c²) = 5075, finite (brdf_ggx.glsl has the derivation).
// - V_K at grazing: (l·h)² underflows binary16's smallest normal 2^-14 for l·h < 2^-7, and
//   0.25/(l·h)² then overflows (flushed to 0: +inf, then NaN times a 0 n·l). The floor
//   max((l·h)², 2^-14) bounds V_K ≤ 2^12 = 4096. Where it acts it changes nothing visible:
//   2 (n·h)(l·h) = n·v + n·l for the unit half vector, so l·h < 2^-7 means n_c·l < 2^-6 (with the
//   base normal equal to the coat's; a mapped coat normal tilts this by its angle), and the term
//   is multiplied by that n·l. D · V_K ≤ 5075 · 4096 can still pass 65504: the product is
//   saturated (saturateMediump) as the base lobe's D · V is (specular_ggx_smith.glsl), and the
//   light's product saturated by the caller. Measured: docs/material-models.md (the grazing-coat
//   hard case under fp16 emulation). highp (`reference`): the floor is 2^-14 there too, so both
//   tiers compute the same formula; saturateMediump is an identity.
#include "brdf_ggx.glsl"

float visibility_kelemen(float LoH) {
    return 0.25 / max(LoH * LoH, 6.103515625e-5);  // 2^-14, derivation above
}

// The coat's light for one light; lightColor is the pre-exposed illuminance at normal incidence.
vec3 clear_coat_direct(MaterialInputs material, vec3 l, vec3 h, float LoH, vec3 lightColor) {
    vec3 n = shading_clear_coat_normal;
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    float r = clear_coat_perceptual_roughness(material);
    float Fc = clear_coat_fresnel(LoH) * clear_coat_strength(material);
    float DV = saturateMediump(distribution_ggx(r * r, NoH, n, h) * visibility_kelemen(LoH));
    return DV * Fc * (lightColor * NoL);
}
