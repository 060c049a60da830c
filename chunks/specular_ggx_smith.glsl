#include "brdf_ggx.glsl"

// Specular lobe of the `ggx_smith` tiers (reference, high): the full Cook-Torrance product
//   f_s = D(h) · V(l, v) · F(l·h)
// with GGX D in its fp16-safe form, height-correlated Smith V and Schlick F (brdf_ggx.glsl,
// sources there). Two divisions (in D and V); fp16 bounds as stated in brdf_ggx.glsl.
// fp16: D and V are each finite, but not their product. At the grazing mirror (n = h, a sun
// glint seen near a smooth surface's horizon) n·v = n·l = c gives D = 1/(π α²) and
// V ≈ 0.25 / c² (c ≫ α; 0.25 / (α c) for c ≪ α), so at the roughness floor (α = 0.089²,
// D = 5075) D·V passes 65504 for c < √(5075 · 0.25 / 65504) ≈ 0.14: +inf, and NaN once a later
// factor is 0 (measured: tests/compiler/test_fp16.cpp, Fp16Shading). D, V ≥ 0 are finite, so their
// product is at worst +inf and saturateMediump brings it back to 65504, far above the tone
// mapper's white.
// Resolves the roughness floor's narrow lobe, so its half vector is formed at highp
// (shading_standard.glsl, half_vector).
#define SPECULAR_HALF_VECTOR_HIGHP 1
vec3 specular_lobe(float perceptualRoughness, float alpha, float NoV, float NoL, float NoH, float LoH,
                   vec3 n, vec3 v, vec3 l, vec3 h, vec3 f0) {
    float D = distribution_ggx(alpha, NoH, n, h);
    float V = visibility_smith_ggx_correlated(alpha, NoV, NoL);
    return saturateMediump(D * V) * fresnel_schlick(f0, LoH);
}
