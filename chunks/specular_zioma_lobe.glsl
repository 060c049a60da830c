#include "specular_zioma.glsl"

// Specular lobe of the `zioma` option (no preset's: docs/specular-tiers.md): GGX D
// times Facet's energy-bounded fused V·F, one division for the whole scalar, specular colour
// applied at the end:
//   f_s = specular_zioma_nxh(α, n·h, n, h, l·h) · f0   (d by the Lagrange identity, fp16-safe)
// Ignores n·v and n·l inside the lobe, as the fused form does (Zioma 2015); see
// specular_zioma.glsl for the fit, its energy bound and its fp16 analysis.
//
// With FACET_PRESHADED_ROUGHNESS the preshader forms 2^12 α and X's roughness factor 4π (p α + q)
// once per instance (facet_ggxAlphaScaled, facet_ziomaRoughnessFactor; compiler/preshader.h), and
// k = 2^12 α / (d' X) with d' = 2^12 d unscaled (ggx_d_scaled): the same k, 3 FMA-pipe ops fewer
// per pixel (Mali-G57, docs/tune.md's mid ablation). fp16: d' X ∈ [2^12 α² X_min, 2^12 X_max] =
// [0.34, 5.2e4] at α ≥ 0.089², normal and finite; 2^12 α ≤ 4096; k, spec as specular_zioma.glsl.
#if defined(FACET_PRESHADED_ROUGHNESS) && !defined(FACET_SPECULAR_AA)
float specular_lobe_scalar(float alpha, float NoH, float LoH, vec3 n, vec3 h) {
    float x = max(LoH * LoH, ZIOMA_LOH2_MIN) * params.facet_ziomaRoughnessFactor;
    return specular_zioma_kkx(params.facet_ggxAlphaScaled, ggx_d_scaled(alpha, NoH, n, h), x);
}
#else
float specular_lobe_scalar(float alpha, float NoH, float LoH, vec3 n, vec3 h) {
    return specular_zioma_nxh(alpha, NoH, n, h, LoH);
}
#endif

// The lobe is a scalar times f0 (SPECULAR_LOBE_SCALAR: shade_standard_direct may take the scalar).
#define SPECULAR_LOBE_SCALAR 1
vec3 specular_lobe(float perceptualRoughness, float alpha, float NoV, float NoL, float NoH, float LoH,
                   vec3 n, vec3 v, vec3 l, vec3 h, vec3 f0) {
    return specular_lobe_scalar(alpha, NoH, LoH, n, h) * f0;
}
