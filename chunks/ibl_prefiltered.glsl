#include "equirect.glsl"

// Radiance of the prefiltered environment in a direction, at perceptual roughness r:
//   facet_environment at lod = r · (levels − 1), level m holding r_m = m / (levels − 1)
// (facet::ibl::prefilterEnvironment: GGX-prefiltered with n = v = R, Karis 2013). textureLod
// blends the two nearest levels (trilinear). The split-sum and analytic ambient models share it.
// fp16: radiance pre-exposed on the CPU; lookup coordinates highp (equirect.glsl); explicit lod,
// so no derivatives are taken across the equirect seam. Sampler: RGBA16F, repeat s, clamp t.
vec3 prefiltered_radiance(vec3 direction, float perceptualRoughness) {
    return textureLod(facet_environment, equirect_uv(direction), perceptualRoughness * ENVIRONMENT_MAX_LOD).rgb;
}
