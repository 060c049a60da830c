#include "brdf_ggx.glsl"

// Specular lobe of the `ggx_smith` tiers (reference, high): the full Cook-Torrance product
//   f_s = D(h) · V(l, v) · F(l·h)
// with GGX D in its fp16-safe form, height-correlated Smith V and Schlick F (brdf_ggx.glsl,
// sources there). Two divisions (in D and V); fp16 bounds as stated in brdf_ggx.glsl.
vec3 specular_lobe(float perceptualRoughness, float alpha, float NoV, float NoL, float NoH, float LoH,
                   vec3 n, vec3 v, vec3 l, vec3 h, vec3 f0) {
    float D = distribution_ggx(alpha, NoH, n, h);
    float V = visibility_smith_ggx_correlated(alpha, NoV, NoL);
    return (D * V) * fresnel_schlick(f0, LoH);
}
