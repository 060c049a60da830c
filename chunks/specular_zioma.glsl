// GGX D times a fused visibility·Fresnel term, the whole specular scalar with ONE division; f0 is
// applied by the caller (spec · f0), which suits scalar pipelines:
//   spec = α² / (4π d² · max(LoH², m) · (p α + q)),   d = NoH²(α² − 1) + 1
// Source: R. Zioma, "Optimizing PBR", SIGGRAPH 2015 — the fused V·F = 1/(LoH² (roughness + 0.5))
// replacing Hable's roughness-aware Kelemen V times Schlick F, fitted there for dielectrics.
//
// specular_zioma_published: m = 0.1, p = 1, q = 0.5 — the form as shipped (Unity BRDF2 / URP's
// "minimalist Cook-Torrance"): α = perceptual² in the (α + 0.5) factor and LoH² floored at 0.1.
// The slide writes (r + 0.5) with perceptual r and no floor; the shipped form is the one engines
// run, so it is Facet's "published" reference (both are measured in
// docs/specular-tiers.md). π is kept: Facet's lights are physical (URP drops it with its units).
// It creates energy: for f0 = 1 the mirror lobe of a smooth surface has directional albedo
// 1/(α + 0.5) → 2 (measured maximum 1.97 at r = 0.089).
//
// specular_zioma: Facet's form, the same ops with refitted coefficients (tools/fit_zioma.cpp):
// least squared tone-mapped error against GGX · Smith (height-correlated) · Schlick over sphere
// images (9 light directions, f0 ∈ {0.04, 1}, r ∈ [0.1, 1]) subject to directional albedo ≤ 0.995
// for f0 = 1 at every NoV and r ≥ 0.089 (smooth mirror limit: albedo → 1/q, hence q ≥ 1).
// Result m = 0.15, p = −0.3125, q = 1.0082: the smooth end is bounded (max albedo 0.995), rough
// lobes keep more energy (p α + q falls to 0.696 at r = 1), as the exact model's do relative to
// the 1/LoH² shape. Numbers and procedure: docs/specular-tiers.md.
//
// fp16: evaluated as k = α / (d · X), spec = k · k · X with X = 4π max(LoH², m)(p α + q) — equal to
// α²/(d² X) but never forms d² (≥ α⁴ = 3.9e-9 at the roughness floor: flushed to 0 in fp16, turning
// the peak into 0/0 or inf). With α ≥ 0.089² and X ∈ [X_min, X_max] (Facet: [1.31, 12.7] =
// 4π·0.15·0.696 … 4π·1·1.0082): d·X ≥ α² X_min ≥ 8.2e-5 (a normal fp16), k ≤ 1/(α X_min) ≤ 97 and
// spec ≤ 1/(α² X_min) ≤ 1.22e4 < 65504. Published: X ∈ [0.64, 18.8], so at the roughness floor
// with LoH² ≤ 0.1 the peak's d·X = 4.0e-5 is subnormal; flushed, k = inf and saturateMediump
// returns 65504 (far above the tone mapper's white either way). Results below 6.1e-5, far outside
// the lobe, flush to 0.
// d = NoH²(α² − 1) + 1 cancels for NoH within 2^-11 of 1 (the fp16 step), so the highlight core
// is quantised in NoH; specular_zioma_nxh (below, used by the zioma lobe) takes n and h and uses
// distribution_ggx's n × h form instead.
// Needs: math.glsl, precision.glsl.

#include "ggx_denominator.glsl"

// Facet's fitted coefficients (see above); m floors LoH², p α + q scales the fused V·F.
const float ZIOMA_LOH2_MIN = 0.15;
const float ZIOMA_ROUGH_SCALE = -0.3125;
const float ZIOMA_ROUGH_BIAS = 1.0082;

// spec = k · k · X with k = a / (d · X): α²/(d² X) for a = α and d unscaled, and the same for
// a = 2^12 α and d' = 2^12 d (specular_zioma_lobe.glsl's preshaded form). fp16 as above.
float specular_zioma_kkx(float a, float d, float x) {
    float k = a / (d * x);
    return saturateMediump(k * k * x);
}

// The shared form, given the GGX denominator d = NoH²(α² − 1) + 1 however the caller computed it.
float specular_zioma_form_d(float alpha, float d, float LoH, float loH2Min, float roughScale, float roughBias) {
    float x = (4.0 * PI) * max(LoH * LoH, loH2Min) * (roughScale * alpha + roughBias);
    return specular_zioma_kkx(alpha, d, x);
}

float specular_zioma_form(float alpha, float NoH, float LoH, float loH2Min, float roughScale, float roughBias) {
    return specular_zioma_form_d(alpha, NoH * NoH * (alpha * alpha - 1.0) + 1.0, LoH, loH2Min, roughScale, roughBias);
}

float specular_zioma_published(float alpha, float NoH, float LoH) {
    return specular_zioma_form(alpha, NoH, LoH, 0.1, 1.0, 0.5);
}

float specular_zioma(float alpha, float NoH, float LoH) {
    return specular_zioma_form(alpha, NoH, LoH, ZIOMA_LOH2_MIN, ZIOMA_ROUGH_SCALE, ZIOMA_ROUGH_BIAS);
}

// Facet's form with d by the Lagrange identity 1 − NoH² = |n × h|²: d = |n × h|² + (α NoH)², which
// keeps the bits the textbook d loses by cancellation for NoH within 2^-11 of 1. Measured: Mesa's
// GLSL ES path stores the mediump normal varying as fp16 (tests/runtime/test_gl_backend.cpp), and with the
// textbook d that quantised normal speckles the highlight core of the r = 0.35 example sphere by
// up to 29/255 against Vulkan; with this form the two agree within 1/255. Same single division.
// fp16: d is formed scaled by 2^12 (ggx_denominator.glsl: unscaled, the squares of n × h flush to
// 0 in a smooth lobe's highlight core, and F = 1 reflected 1.47× its light at r = 0.089), then
// scaled back exactly (a power of two) to d ∈ [α², 1], ≥ 6.27e-5: normal.
float specular_zioma_nxh(float alpha, float NoH, vec3 n, vec3 h, float LoH) {
    float d = ggx_d_scaled(alpha, NoH, n, h) * (1.0 / GGX_D_SCALE2);
    return specular_zioma_form_d(alpha, d, LoH, ZIOMA_LOH2_MIN, ZIOMA_ROUGH_SCALE, ZIOMA_ROUGH_BIAS);
}
