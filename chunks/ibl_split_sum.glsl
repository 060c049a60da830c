// Split-sum image-based specular (Karis 2013, "Real Shading in Unreal Engine 4"), in Filament's
// form (Guy's Filament mobile talk, multiple-scattering slides; docs/ibl.md):
//   L_spec ≈ prefiltered(R, r) · (f0 · A + B),   f0·A + B = mix(dfg.x, dfg.y, f0)   (f90 = 1)
//   prefiltered: facet_environment at lod = (levels − 1) · r (2 − r), R = reflect(−v, n)
//   dfg = (B, A + B) from facet_dfgLut at (n·v, r)
// Energy compensation (multiple scattering, same slides; every preset): single-scattering GGX
// loses the energy of light bouncing between microfacets, up to 68 % for rough metals; scaling
// every specular term by 1 + f0 · (1/dfg.y − 1) restores it (for f0 = 1 the factor is 1/albedo,
// so a white metal in a white furnace reflects exactly the environment).
// Needs ibl_prefiltered.glsl. Textures: facet_environment (RGBA16F cube map, kEnvironmentLevels levels),
// facet_dfgLut (RG16F 64 × 64, clamp), declared by the assembler in the variants using them.
// fp16: radiance is pre-exposed on the CPU (the lights' contract), so RGBA16F and mediump hold it;
// dfg ∈ [0, 1] and dfg.y ≥ 0.316 (docs/ibl.md), so 1/dfg.y ≤ 3.2 needs no clamp. The lookup
// direction and coordinates are mediump (environment_cube.glsl has the bound); both reads use
// textureLod, so no derivatives are taken (the DFG table needs none).

// (B, A + B): texel centres sit at (i + 0.5)/64 on both axes, so no remapping (docs/ibl.md).
vec2 dfg_terms(float NoV, float perceptualRoughness) {
    return textureLod(facet_dfgLut, vec2(NoV, perceptualRoughness), 0.0).rg;
}

// f0 · A + B: the specular's directional albedo at this n·v (the environment BRDF), which the
// ambient term multiplies the prefiltered radiance by, and the `lut` lobe takes in place of f0.
vec3 split_sum_albedo(vec2 dfg, vec3 f0) {
    return mix(dfg.xxx, dfg.yyy, f0);
}

vec3 energy_compensation(vec2 dfg, vec3 f0) {
    return 1.0 + f0 * (1.0 / dfg.y - 1.0);
}
