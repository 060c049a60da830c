// Clear coat: a thin dielectric layer over the standard model (car paint, lacquer, varnish), the
// layering and the coat's image-based light. Source: R. Guy and M. Agopian, "Physically Based
// Rendering in Filament", "Clear coat model" (the mobile form: a second specular lobe, no
// refraction, no absorption, a fixed coat IOR).
//   Fc(c)      = (0.04 + 0.96 (1 − c)⁵) · clearCoat      Schlick, f0 = ((1.5 − 1)/(1.5 + 1))² = 0.04, f90 = 1
//   L          = L_base · (1 − Fc) + L_coat · Fc
//   L_coat,ibl = prefiltered(reflect(−v, n_c), r_c)         the split sum's radiance at the coat's roughness
// with n_c the coat's normal (clearCoatNormal, else the interpolated normal: a base normal map does
// not roughen the coat above it) and r_c = clamp(clearCoatRoughness, MIN_PERCEPTUAL_ROUGHNESS, 1).
// The environment term is weighted by Fc(n_c·v), not by the coat's DFG albedo: then the layered
// sum is Fc · L_env + (1 − Fc) · L_base, a convex mix, and in a white furnace (L_env = 1,
// L_base ≤ 1, the base's own furnace) it is ≤ 1 for any Fc ∈ [0, 1]: energy-conserving by
// construction (Filament weights it the same way). The 1 − Fc on the base stands for light that
// crossed the coat twice, in and out, to first order: the second crossing is not counted (as
// Filament).
// Every light's base is attenuated by the same 1 − Fc(n_c·v), not by Filament's 1 − Fc(l·h) per
// light. Why: with Fc(l·h) the layered directional albedo (coat lobe + a white base under it)
// reaches 1.30 at n·v = 0.2 and 1.66 at n·v = 0.05 for a smooth coat (the coat reflects Fc(n·v) of
// a grazing view while most of the base's light directions see l·h far from grazing, so the base
// keeps 0.91–0.96), where with Fc(n_c·v) it stays ≤ 1 + 1e-5 over n·v and r_c: the coat lobe's
// albedo never exceeds Fc(n_c·v) by more than that (tests/reference/clear_coat.h integrates both;
// Reference.ClearCoatLayeredFurnaceIsAtMostOne). It is also one Fresnel per pixel instead of one
// per light. Needs shading_standard.glsl's inputs and ibl_prefiltered.glsl.
//
// Two tiers' forms share this file (docs/material-models.md):
//   ggx_kelemen (reference, high): clear_coat_layer over the ambient terms only; each light adds
//     its own lobe and attenuates its base by Fc(l·h) (clear_coat_ggx_kelemen.glsl).
//   ambient (mid, low): clear_coat_layer over the whole base, lights included: one Fresnel at
//     n_c·v and one environment read, no lobe per light (the coat's sharp highlight of the sun is
//     lost; its error and cost against the other forms are in docs/material-models.md).
// fp16: every factor is in [0, 1] and the radiance is pre-exposed (precision.glsl): the mix
// cannot overflow where its inputs do not. (1 − c)⁵ by multiplications (pow costs exp2 + log2).

// The coat's normal in world space, set once per pixel by the template before shading.
vec3 shading_clear_coat_normal;
// 1 − Fc(n_c·v), set by clear_coat_layer before any light is shaded (the ggx_kelemen form: each
// light's base is multiplied by it, shading_standard.glsl).
float shading_clear_coat_attenuation = 1.0;

// With FACET_PRESHADED_CLEAR_COAT and FACET_PRESHADED_CLEAR_COAT_ROUGHNESS the coat's inputs depend
// only on parameters: the preshader (compiler/preshader.h) forms these same values on the CPU, the
// strength, α_c = r_c² and the environment's lod r_c (2 − r_c) · (levels − 1) (prefiltered_radiance's,
// ibl_prefiltered.glsl), and the forms below are what it implements.
float clear_coat_strength(MaterialInputs material) {
#if defined(FACET_PRESHADED_CLEAR_COAT)
    return params.facet_clearCoat;
#else
    return clamp(material.clearCoat, 0.0, 1.0);
#endif
}

#if !defined(FACET_PRESHADED_CLEAR_COAT_ROUGHNESS)
float clear_coat_perceptual_roughness(MaterialInputs material) {
    return clamp(material.clearCoatRoughness, MIN_PERCEPTUAL_ROUGHNESS, 1.0);
}
#endif

// α_c = r_c² (the lobe's, clear_coat_ggx_kelemen.glsl).
float clear_coat_alpha(MaterialInputs material) {
#if defined(FACET_PRESHADED_CLEAR_COAT_ROUGHNESS)
    return params.facet_clearCoatAlpha;
#else
    float r = clear_coat_perceptual_roughness(material);
    return r * r;
#endif
}

// Fc without the strength: Schlick at f0 = 0.04, f90 = 1.
float clear_coat_fresnel(float cosTheta) {
    float f = 1.0 - cosTheta;
    float f2 = f * f;
    return 0.04 + 0.96 * (f2 * f2 * f);
}

// L_base · (1 − Fc(n_c·v)) + prefiltered(R_c, r_c) · Fc(n_c·v).
vec3 clear_coat_layer(MaterialInputs material, vec3 base, vec3 v) {
    vec3 n = shading_clear_coat_normal;
    float Fc = clear_coat_fresnel(max(dot(n, v), MIN_N_DOT_V)) * clear_coat_strength(material);
    shading_clear_coat_attenuation = 1.0 - Fc;
#if defined(FACET_PRESHADED_CLEAR_COAT_ROUGHNESS)
    vec3 coat = prefiltered_radiance_at_lod(reflect(-v, n), params.facet_clearCoatLod);
#else
    vec3 coat = prefiltered_radiance(reflect(-v, n), clear_coat_perceptual_roughness(material));
#endif
    return mix(base, coat, Fc);
}
