#include "octahedral.glsl"

// Radiance of the prefiltered environment in a direction, at perceptual roughness r:
//   facet_environment at lod = r · (levels − 1), level m holding r_m = m / (levels − 1)
// (facet::ibl::prefilterEnvironment: GGX-prefiltered with n = v = R, Karis 2013). textureLod
// blends the two nearest levels (trilinear). The split-sum and analytic ambient models share it.
// fp16: radiance pre-exposed on the CPU; lookup coordinates in the tier's precision (octahedral.glsl); explicit lod,
// so no derivatives are taken across the map's folds. Sampler: RGBA16F octahedral, clamp to edge.
vec3 prefiltered_radiance(vec3 direction, float perceptualRoughness) {
    return textureLod(facet_environment, octahedral_uv(direction), perceptualRoughness * ENVIRONMENT_MAX_LOD).rgb;
}
