#include "environment_cube.glsl"

// Radiance of the prefiltered environment in a direction, at perceptual roughness r:
//   facet_environment at lod = (levels − 1) · r (2 − r), level m holding the r_m that solves
//   r (2 − r) = m / (levels − 1), r_m = 1 − √(1 − m / (levels − 1))
// (facet::ibl::prefilterEnvironment: GGX-prefiltered with n = v = R, Karis 2013). textureLod
// blends the two nearest levels (trilinear), and a blend of two lobes is not the lobe between
// them: the mapping puts levels where the lobe changes fastest, at low r (Guy, Filament on
// mobile, "Roughness mapping"): r_m = 0, 0.134, 0.293, 0.5, 1 with five levels instead of 0,
// 0.25, 0.5, 0.75, 1. Against the per-pixel ground truth under a 25× softbox it took brushed_gold
// from 13.8 % to 11.8 % relative RMSE (docs/eval.md, "The ground truth"). One FMA more than the
// linear mapping: lod = r · ((levels − 1)(2 − r)). The split-sum, analytic, clear-coat and sheen
// ambients share it.
// fp16: r ∈ [0.089, 1] gives lod ∈ [0.69, levels − 1], exact enough at 2^-11; radiance
// pre-exposed on the CPU; the direction in the tier's precision (environment_cube.glsl has the
// bound). Sampler: RGBA16F cube map, explicit lod.
// r is the perceptual roughness, named short: every byte ships, and brushed_metal's high.dir1
// sits at the 8 KB goal of MinifyGlsl.ExampleFragmentVariantsShipAtMostEightKilobytesWithoutComments.
vec3 prefiltered_radiance(vec3 direction, float r) {
    return textureLod(facet_environment, direction, r * (ENVIRONMENT_MAX_LOD * (2.0 - r))).rgb;
}

// The same read at a lod the preshader formed from a parameter-only r by the formula above
// (compiler/preshader.h; the clear coat's and the sheen's environments). A macro: the shipped
// source holds the read alone, no function (satin_plastic's high.dir1 is near the 8 KB goal above).
#define prefiltered_radiance_at_lod(direction, lod) textureLod(facet_environment, direction, lod).rgb
