// The `two_mip` ambient option's image-based specular: R. Zioma, "Optimizing PBR", SIGGRAPH 2015
// ("Environment reflections", for the low end): a lod computed per pixel is
// slow or missing on low-end GPUs, so read two fixed mips and lerp:
//   prefiltered ≈ mix(env(R, lod 0), env(R, lod levels − 1), r)
// with r the perceptual roughness, the mirror level and the r = 1 level of facet_environment
// (the talk's "2 extreme mips"; its 3-way variant with SH as the third step is not done here).
// Environment BRDF: Zioma's fit from the same talk, saturated (Facet's variant, a free clamp):
//   f0·A + B ≈ min((1 − max(r, n·v))³ + f0, 1)         (facet::ibl::envBrdfZiomaSaturated)
// It ignores roughness darkening of f0 (A = 1): rough metals read up to 0.68 too bright against
// the DFG table (docs/ibl.md). Two texture reads at constant lods and ~10 ALU ops, no division.
// fp16: as ibl_split_sum.glsl (pre-exposed radiance, mediump lookup direction). Needs environment_cube.glsl.

vec3 two_mip_radiance(vec3 direction, float perceptualRoughness) {
    vec3 sharp = textureLod(facet_environment, direction, 0.0).rgb;
    vec3 rough = textureLod(facet_environment, direction, ENVIRONMENT_MAX_LOD).rgb;
    return mix(sharp, rough, perceptualRoughness);
}

vec3 env_brdf_zioma_saturated(vec3 f0, float NoV, float perceptualRoughness) {
    float m = 1.0 - max(perceptualRoughness, NoV);
    return min(vec3(m * m * m) + f0, vec3(1.0));
}
