// The sheen lobe without its colour, times n·l (the cloth model's, shading_cloth.glsl, where the
// formulas, sources and the energy correction are):
//   D · V · n·l,   D = (2 + 1/α) · sin(θ_h)^(1/α) / (2π)   (Charlie: A. Estevez and C. Kulla,
//   "Production Friendly Microfacet Sheen BRDF", 2017),   V = 1 / (4 (n·l + n·v − n·l · n·v))
//   (D. Neubelt and M. Pettineo, "Crafting a Next-Gen Material Pipeline for The Order: 1886", 2013)
// The double model: eval/include/facet/eval/standard_model.h (sheenLobeTimesNoL).
// fp16 (mediump): α ≥ 0.089² (MIN_PERCEPTUAL_ROUGHNESS, clamped by the caller), so 1/α ≤ 126.6 and
// D ≤ (2 + 126.6)/(2π) = 20.5; pow(x, y) with x = sin² θ_h ∈ [0, 1] and y = 0.5/α > 0 is defined
// at x = 0 (GLSL: undefined only for x < 0, or x = 0 with y ≤ 0) and underflows to 0, not NaN.
// V is formed with n·l folded in, n·l / (4 (n·l + n·v (1 − n·l))) ≤ 1/4 (its denominator is
// ≥ 4 n·v ≥ 4e-4, MIN_N_DOT_V, where n·l = 0), so no V that overflows at n·v → 0 (V alone reaches
// 2500 there). The product is ≤ 20.5 · 0.25 = 5.2: no
// saturation needed. Rounding: 1 − (n·h)² carries binary16's 2^-12 relative error near 1, which
// the power 0.5/α ≤ 63.3 turns into ≤ 1.5 % of D at the floor roughness, where D peaks
// (Fp16Cloth.* measures the images at ≥ 50 dB, n·v → 0 included).

// D and V in one division (divisions are the mobile tiers' scarcest budget: examples/lint/budgets.json):
//   k = 1 / (α · q'),  q' = 2^11 q,  q = 4 (n·l + n·v − n·l n·v)   →   1/α = k q',   V · n·l = n·l · k · (2^11 α)
// The 2^11 scale keeps the divisor normal in fp16: α q ≥ 0.0079 · 4e-4 = 3.2e-6 is below 2^-14, α q'
// ≥ 6.5e-3; α q' ≤ 1 · 4 · 2^11 = 8192, so k ∈ [1.2e-4, 154], and k q' = 1/α ≤ 126.6. The two
// extra products add 2^-11 relative rounding each to 1/α; through the power that is ≤ 0.5 % of D
// where sin² θ_h ≥ 0.95 (where D is within e^-3 of its peak at the floor roughness).
float sheen_lobe_times_n_dot_l(float alpha, float NoV, float NoL, float NoH) {
    float scaledQ = 8192.0 * (NoL + NoV - NoL * NoV);  // 2^11 · 4 (n·l + n·v − n·l n·v)
    float k = 1.0 / (alpha * scaledQ);
    float invAlpha = k * scaledQ;
    float visibilityTimesNoL = NoL * (k * (2048.0 * alpha));
    float sin2h = max(1.0 - NoH * NoH, 0.0);
    return (2.0 + invAlpha) * pow(sin2h, 0.5 * invAlpha) * (0.5 * INV_PI) * visibilityTimesNoL;
}

// The sheen's colour, α, s(n·v, r) = 1/max(1, E) (the lobe's energy correction) and
// b(n·v, r) = 1 − max(sheenColor) · min(E, 1) (the scale of the base under the sheen; sheen_layer.glsl
// has both), set once per pixel by sheen_layer before any light is shaded. Declared with the lobe:
// the lights read them (shading_cloth.glsl, and shading_standard.glsl before sheen_layer.glsl).
vec3 shading_sheen_color = vec3(0.0);
float shading_sheen_alpha = 1.0;
float shading_sheen_scale = 1.0;
float shading_sheen_base_scale = 1.0;

// One light's sheen per unit of its light, sheenColor · D · V · n·l · s: ≤ 5.2 (above), the
// caller's product with the light saturated as the base's.
vec3 sheen_light(float NoV, float NoL, float NoH) {
    return shading_sheen_color * (sheen_lobe_times_n_dot_l(shading_sheen_alpha, NoV, NoL, NoH) * shading_sheen_scale);
}
