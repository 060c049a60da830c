#include "environment_cube.glsl"

// Radiance of the prefiltered environment in a direction, at perceptual roughness r:
//   facet_environment at lod = r · (levels − 1), level m holding r_m = m / (levels − 1)
// (facet::ibl::prefilterEnvironment: GGX-prefiltered with n = v = R, Karis 2013). textureLod
// blends the two nearest levels (trilinear). The split-sum and analytic ambient models share it.
// fp16: radiance pre-exposed on the CPU; the direction in the tier's precision (environment_cube.glsl has the
// bound). Sampler: RGBA16F cube map, explicit lod.
vec3 prefiltered_radiance(vec3 direction, float perceptualRoughness) {
    return textureLod(facet_environment, direction, perceptualRoughness * ENVIRONMENT_MAX_LOD).rgb;
}
