#include "brdf_ggx.glsl"
#include "brdf_ggx_fastv.glsl"

// Specular lobe of the `ggx_fastv` option: GGX D and Schlick F as in ggx_smith, with Hammon's
// approximation of height-correlated Smith visibility, V = 0.5 / mix(2·NoL·NoV, NoL + NoV, α):
// no square roots, still two divisions. Sources and fp16 notes: brdf_ggx.glsl, brdf_ggx_fastv.glsl
// (measured against the exact model in docs/specular-tiers.md).
// Resolves the roughness floor's narrow lobe, so its half vector is formed at highp
// (shading_standard.glsl, half_vector).
#define SPECULAR_HALF_VECTOR_HIGHP 1
vec3 specular_lobe(float perceptualRoughness, float alpha, float NoV, float NoL, float NoH, float LoH,
                   vec3 n, vec3 v, vec3 l, vec3 h, vec3 f0) {
    float D = distribution_ggx(alpha, NoH, n, h);
    float V = visibility_hammon(alpha, NoV, NoL);
    // fp16: D·V overflows at the grazing mirror as in specular_ggx_smith.glsl (Hammon's V ≈
    // 0.25 / (α c) there); saturated the same way.
    return saturateMediump(D * V) * fresnel_schlick(f0, LoH);
}
