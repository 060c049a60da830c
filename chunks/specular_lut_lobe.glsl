#include "specular_lut.glsl"

// Specular lobe of the `lut` option (the low tier): one texture read replaces D, V and F.
//   R   = reflect(−v, n) = 2 (n·v) n − v
//   f_s = S(R·L, r) · f0,   S(c, r) = D_GGX(α, n·h')/4 with n·h'² = (1 + c)/2   (specular_lut.glsl)
// The table is indexed by u = clamp(R·L, 0, 1)⁴ (the warped cosine) and the perceptual roughness r,
// and decoded as texel² · 16/π (√ encoding, SPECULAR_LUT_SCALE; measured in docs/specular-tiers.md).
// No Fresnel and an implicit geometric term (V = 1/4): f0 multiplies the intensity as it is, the
// cheap form of the talk. No half vector is needed (R·L instead of n·h), so the h, n·h and l·h the
// caller computes for other lobes are dead code here and the optimiser drops them. No division.
// Source: R. Zioma, "Optimizing PBR", SIGGRAPH 2015 (LUT specular for low-end GPUs with a low
// ALU:TEX ratio, intensity / 16 in 8 bits, R·L after B. Karis, axis warped with a 4th power).
// fp16: R is a unit vector from mediump n and v (|R| = 1 up to rounding), R·L ∈ [−1, 1] is clamped
// by specular_lut(); the decoded value is ≤ 5.09 · f0, far from the fp16 limit. The sampler
// `facet_specularLut` (R8 UNORM, linear filter, clamp to edge, shader_abi.h kSpecularLutBinding) is
// declared by the assembler in the variants that include this chunk.
vec3 specular_lobe(float perceptualRoughness, float alpha, float NoV, float NoL, float NoH, float LoH,
                   vec3 n, vec3 v, vec3 l, vec3 h, vec3 f0) {
    vec3 r = reflect(-v, n);
    return specular_lut(facet_specularLut, dot(r, l), perceptualRoughness) * f0;
}
