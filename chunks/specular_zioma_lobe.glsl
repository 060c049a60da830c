#include "specular_zioma.glsl"

// Specular lobe of the `zioma` option (no preset's: docs/specular-tiers.md): GGX D
// times Facet's energy-bounded fused V·F, one division for the whole scalar, specular colour
// applied at the end:
//   f_s = specular_zioma_nxh(α, n·h, n, h, l·h) · f0   (d by the Lagrange identity, fp16-safe)
// Ignores n·v and n·l inside the lobe, as the fused form does (Zioma 2015); see
// specular_zioma.glsl for the fit, its energy bound and its fp16 analysis.
vec3 specular_lobe(float perceptualRoughness, float alpha, float NoV, float NoL, float NoH, float LoH,
                   vec3 n, vec3 v, vec3 l, vec3 h, vec3 f0) {
    return specular_zioma_nxh(alpha, NoH, n, h, LoH) * f0;
}
