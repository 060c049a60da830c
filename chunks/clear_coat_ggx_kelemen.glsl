// The clear coat's lobe for each light (the `ggx_kelemen` clear coat of reference and high):
//   f_c = D(h; α_c) · V_K(l·h) · Fc(l·h)              α_c = r_c², Fc with the strength (clear_coat_ambient.glsl)
//   V_K = 1 / (4 (l·h)²)                               Kelemen and Szirmay-Kalos 2001
//   L   = L_base · (1 − Fc(n_c·v)) + f_c · E_light · n_c·l
// (the base's attenuation is the view's, shading_clear_coat_attenuation: clear_coat_ambient.glsl
// has why; the lobe's own Fresnel is at l·h, as the talk's).
// Sources: R. Guy and M. Agopian, "Physically Based Rendering in Filament", "Clear coat model"
// (isotropic GGX, Kelemen's visibility: a smooth coat needs no Smith term's cost, and f0 fixed at
// 0.04); Kelemen and Szirmay-Kalos, "A Microfacet Based Coupled Specular-Matte BRDF Model with
// Importance Sampling", Eurographics 2001 (V_K). h is the base lobe's half vector (l and v are
// shared, only the normal differs), formed in highp where the tier asks (shading_standard.glsl).
// D · V_K in one division (Zioma's fusion, "Optimizing PBR", SIGGRAPH 2015, as
// specular_fused_hammon.glsl does for the base; the same value, not an approximation):
//   D · V_K = α_c² / (d² · X),   d = |n_c × h|² + (α_c n_c·h)²  (GGX by Lagrange's identity,
//   brdf_ggx.glsl),   X = 4π (l·h)²,   computed as k · (k · X) with k = α_c / (d X)
// Why: it keeps high's fragment stage at four divisions (base D and V, the energy
// compensation, this one) where D and V_K apart need two.
// Energy: the layered directional albedo is integrated in double in tests/reference/clear_coat.h
// (docs/material-models.md, "Energy"), and this chunk's, fp16-emulated too, by `matc eval`'s
// white furnace (eval/include/facet/eval/lobe_sweep.h): ≤ 1 + 1e-3 over a white base.
// fp16 (mediump), for α_c ≥ 0.089² and d ∈ [α_c², 1] (sin² θ_h + α_c² cos² θ_h, α_c ≤ 1):
//   - D at a smooth coat: α_c² = r_c⁴ in the textbook denominator underflows binary16 below
//     r_c = 0.0884; the clamp to MIN_PERCEPTUAL_ROUGHNESS (0.089, r⁴ = 6.27e-5 ≥ 2^-14) and the
//     Lagrange form (no 1 − (n·h)² cancellation) keep d ≥ α_c².
//   - d's terms: the squares of n_c × h fall below 2^-14 and are flushed to 0 wherever a component
//     is below 2^-7, the whole core of a smooth coat's highlight (the coat reflected 1.48× its
//     light at normal incidence, 1.21 over a white base: measured by the furnace above). So d is
//     formed scaled, d' = 2^12 d ∈ [0.257, 4096] (ggx_denominator.glsl, shared with the base's D),
//     and k = 2^12 α_c / (d' X) is the same value.
//   - V_K at grazing: (l·h)² underflows binary16's smallest normal 2^-14 for l·h < 2^-7 and is
//     flushed: X = 0, k = +inf and k · (k · X) = inf · 0 = NaN. It is floored at 2^-14, so X ≥ 4π · 2^-14 =
//     7.7e-4. Where the floor acts it changes nothing visible: 2 (n·h)(l·h) = n·v + n·l for the
//     unit half vector, so l·h < 2^-7 means n_c·l < 2^-6 (with the base normal equal to the
//     coat's; a mapped coat normal tilts this by its angle), and the term is multiplied by n·l.
//   - d X alone can fall to 6.27e-5 · 7.7e-4 = 4.8e-8, subnormal; d' X ∈ [0.257 · 7.7e-4,
//     4096 · 4π] = [2.0e-4, 51472] is normal and finite, and the numerator 2^12 α_c ≤ 4096.
//   - k · X = α_c / d ≤ 1/α_c ≤ 127, so k · (k · X) overflows only where the true value exceeds
//     65504 (the grazing mirror of a smooth coat), and saturateMediump returns 65504 (k may be
//     +inf there; X > 0, so never NaN); the light's sum is saturated by the caller.
// Fp16Shading.ClearCoatLobeStaysFiniteAtItsHazards runs it at the hazards, fp16-emulated: it
// fails without the floor (where v and l graze nearly opposite: NaN, which lavapipe's min turns
// into a false glint of 65504 · E · n·l, 18 instead of 2e-5), without the scale (the mirror
// at n·v = 0.2: d X flushed, 65504 where the lobe is finite) and without the saturation (+inf at
// the mirror from n·v = 0.1); EvalLobeSweep.ModelLobesKeepTheirFurnaceAndHardCases fails without
// the 2^6 scale of t. highp (`reference`): the same formula, saturateMediump an identity.
// Needs: math.glsl, precision.glsl, clear_coat_ambient.glsl.

#include "ggx_denominator.glsl"

const float CLEAR_COAT_LOH2_MIN = 6.103515625e-5;  // 2^-14, the floor of (l·h)² (above)

// Where the coat's n_c·l is the base's n·l (neither the base's normal nor the coat's is written,
// so both are the interpolated one) and no sheen layer lies between them, shading_standard.glsl
// adds the coat's lobe to the base's, (f_base (1 − Fc(n_c·v)) + f_c) · E · n·l, one product with
// the light instead of two: car_paint's high.dir1 −0.03 Mali-G57 cycles (docs/material-models.md).
#if !defined(FACET_MATERIAL_NORMAL) && !defined(FACET_MATERIAL_CLEAR_COAT_NORMAL) && !defined(FACET_SHEEN_LOBE)
#define CLEAR_COAT_SHARES_THE_BASE_LIGHT 1
#endif

// The coat's lobe f_c = D · V_K · Fc(l·h) for one light (≤ 65504: D · V_K saturated, Fc ≤ 1).
float clear_coat_lobe(MaterialInputs material, vec3 h, float LoH) {
    vec3 n = shading_clear_coat_normal;
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    float alpha = clear_coat_alpha(material);
    float d = ggx_d_scaled(alpha, NoH, n, h);  // 2^12 (|n × h|² + (α n·h)²)
    float x = (4.0 * PI) * max(LoH * LoH, CLEAR_COAT_LOH2_MIN);
    float k = (GGX_D_SCALE2 * alpha) / (d * x);
    float DV = saturateMediump(k * (k * x));
    // Fc(l·h) (clear_coat_fresnel) with the strength s in its two constants: (1 − l·h)⁵ is then the
    // base's Schlick factor (brdf_ggx.glsl's fresnel_schlick, the same products), which the shader
    // compiler shares (−0.02 Mali-G57 cycles on car_paint's high.dir1; the same form at n_c·v, in
    // clear_coat_layer, costs mid and low +0.02).
    float s = clear_coat_strength(material);
    float f = 1.0 - LoH;
    float f2 = f * f;
    return DV * (0.04 * s + (0.96 * s) * (f2 * f2 * f));
}

// The coat's light for one light; lightColor is the pre-exposed illuminance at normal incidence.
vec3 clear_coat_direct(MaterialInputs material, vec3 l, vec3 h, float LoH, vec3 lightColor) {
    float NoL = clamp(dot(shading_clear_coat_normal, l), 0.0, 1.0);
    return clear_coat_lobe(material, h, LoH) * (lightColor * NoL);
}
