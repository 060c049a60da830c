#include "specular_lut.glsl"

// Specular lobe of the `lut` option (the low tier): one texture read replaces D and V, and the
// environment BRDF the ambient term already read replaces F and sets the lobe's energy.
//   R   = reflect(−v, n) = 2 (n·v) n − v
//   f_s = S(R·L, r) / A(r) · E(n·v, r, f0)
//   S(c, r) = D_GGX(α, n·h')/4 with n·h'² = (1 + c)/2   (specular_lut.glsl)
//   A(r)    = ∫ S n·l dω at v = n: the table lobe's albedo (1 for a mirror, 1/4 at r = 1)
//   E       = f0 · A_dfg + B_dfg, the split-sum (or Karis, or Zioma) environment BRDF
// The table is indexed by u = clamp(R·L, 0, 1)⁴ (the warped cosine) and the perceptual roughness r,
// stores S/A (each row normalised, compiler/specular_lut.h) and is decoded as texel² · 16/π.
// Why E and not f0 (the talk's form, f_s = S · f0): S has no Fresnel and an implicit geometric
// term V = 1/4, so a rough lobe kept a quarter of its light (A(1) = 1/4 where GGX · Smith
// reflects 0.32 of it at n·v = 1, and the energy compensation restores the rest) and a dark
// dielectric's rims lost their Fresnel rise. E is the exact lobe's directional albedo at this
// n·v (with f0 and Fresnel), so the cheap lobe keeps the cheap shape but reflects what GGX ·
// Smith · Schlick reflects; at the lobe's peak (l = R) l·h = n·v, so F(n·v) inside E is the
// Fresnel the exact lobe has there. Costs nothing per pixel: E is the ambient specular's weight
// (shading_ambient.glsl sets shading_specular_albedo) and replaces the multiply by f0. Measured
// (docs/eval.md): low +2.8 dB on red_plastic, +3.4 dB on brushed_gold; the BRDF sweep's roughest
// row 0.56 → 0.35 rel. RMSE.
// Source: R. Zioma, "Optimizing PBR", SIGGRAPH 2015 (LUT specular for low-end GPUs with a low
// ALU:TEX ratio, intensity / 16 in 8 bits, R·L after B. Karis, axis warped with a 4th power); the
// E scale is the split-sum idea (Karis 2013) applied to the punctual lobe.
// fp16: R is a unit vector from mediump n and v (|R| = 1 up to rounding), R·L ∈ [−1, 1] is clamped
// by specular_lut(); the decoded value is ≤ 5.09 and E ≤ 1, far from the fp16 limit. The sampler
// `facet_specularLut` (R8 UNORM, linear filter, clamp to edge, shader_abi.h kSpecularLutBinding) is
// declared by the assembler in the variants that include this chunk.
#define SPECULAR_LOBE_SCALED_BY_ALBEDO 1
vec3 specular_lobe(float perceptualRoughness, float alpha, float NoV, float NoL, float NoH, float LoH,
                   vec3 n, vec3 v, vec3 l, vec3 h, vec3 albedo) {
    vec3 r = reflect(-v, n);
    return specular_lut(facet_specularLut, dot(r, l), perceptualRoughness) * albedo;
}
