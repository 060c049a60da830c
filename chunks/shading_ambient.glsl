// The ambient term of Filament's standard model (shading_standard.glsl has the model and its
// symbols):
//   L_ambient = (diffuseColor · E_env(n)/π + L_spec,ibl · c_ms) · ao
// E_env/π comes from SH (ambient_sh.glsl), L_spec,ibl from the tier's image-based specular:
// the split sum (ibl_split_sum.glsl: prefiltered environment × DFG table, every tier's preset),
// or the options `matc eval` measures: the prefiltered environment × Karis's
// analytic environment BRDF (env_brdf_karis.glsl), two fixed mips × Zioma's fit (ibl_two_mip.glsl),
// or, for measurement, both integrals sampled (ibl_sampled.glsl: the albedo is then 1). With FACET_ENERGY_COMPENSATION it also
// sets shading_energy_compensation from the DFG terms it reads, and for a lobe scaled by the
// albedo (SPECULAR_LOBE_SCALED_BY_ALBEDO) shading_specular_albedo, before any light is shaded.
// Needs: shading_standard.glsl and the tier's IBL chunks. fp16: radiance is pre-exposed.

// ao scales the ambient terms. A material that does not write ambientOcclusion has ao = 1, and
// then the multiply is left out: glslang and spirv-opt fold the clamp of the constant but keep
// the vector × 1.0 (OpVectorTimesScalar has no folding rule): two vec3 multiplies at mediump, 3 FMA
// slots per pixel in the cost model (docs/eval.md; red_plastic high.dir1 1.63 → 1.59 cycles).
// With FACET_AO_MULTI_BOUNCE the diffuse ambient takes Jimenez's multi-bounce visibility in the
// diffuse albedo (ambient_occlusion.glsl) instead of ao itself.
vec3 apply_ambient_occlusion(MaterialInputs material, vec3 ambient) {
#if defined(FACET_AO_MULTI_BOUNCE)
    return ambient * multi_bounce_ao(clamp(material.ambientOcclusion, 0.0, 1.0), material_diffuse_color(material));
#elif defined(FACET_MATERIAL_AMBIENT_OCCLUSION)
    return ambient * clamp(material.ambientOcclusion, 0.0, 1.0);
#else
    return ambient;
#endif
}

#if defined(FACET_MATERIAL_AMBIENT_OCCLUSION)
// The specular ambient's occlusion: Lagarde's specular occlusion from ao, n·v and α with
// FACET_SPECULAR_OCCLUSION_LAGARDE (ambient_occlusion.glsl), else ao itself.
vec3 apply_specular_occlusion(MaterialInputs material, vec3 specular, float NoV, float perceptualRoughness) {
    float visibility = clamp(material.ambientOcclusion, 0.0, 1.0);
#if defined(FACET_SPECULAR_OCCLUSION_LAGARDE)
    return specular * specular_occlusion_lagarde(NoV, visibility, perceptualRoughness * perceptualRoughness);
#else
    return specular * visibility;
#endif
}
#endif

// Diffuse ambient lit per pixel: irradiance / π from SH at the shading normal.
vec3 shade_standard_ambient(MaterialInputs material, vec3 irradianceOverPi) {
#if defined(FACET_GAMMA_HACK)
    irradianceOverPi = sqrt(irradianceOverPi);  // encoded like the colours it multiplies (γ = 2)
#endif
    return apply_ambient_occlusion(material, material_diffuse_color(material) * irradianceOverPi);
}

// The direction the prefiltered environment is read along. The split sum prefilters each level
// with the lobe seen head-on (n = v = r), where the lobe's axis is the mirror direction r; off
// normal incidence the GGX lobe times n·l leans from r towards n, the more the rougher (Lagarde &
// de Rousiers 2014, "Moving Frostbite to Physically Based Rendering", §4.9.3, their fit of that
// dominant direction, α = r²):
//   d = mix(n, r, (1 − α)(√(1 − α) + α))
// Not normalized: environment_cube.glsl's lookup takes any length (a cube face and its ratios).
// fp16: α ∈ [0.0079, 1], the factor in [0, 1]; a mix of two unit vectors is finite.
// FACET_IBL_DOMINANT_DIRECTION (an option `matc eval` measures against its ground truth).
#if defined(FACET_IBL_DOMINANT_DIRECTION)
vec3 specular_dominant_direction(vec3 n, vec3 r, float perceptualRoughness) {
    float alpha = perceptualRoughness * perceptualRoughness;
    return mix(n, r, (1.0 - alpha) * (sqrt(1.0 - alpha) + alpha));
}
#endif

// The prefiltered environment along r at the material's roughness: with FACET_PRESHADED_ROUGHNESS
// the preshader forms ibl_prefiltered.glsl's lod r (2 − r) · (levels − 1) once per instance
// (facet_environmentLod, compiler/preshader.h), 3 FMA-pipe ops fewer per pixel (Mali-G57,
// docs/tune.md's mid ablation); per pixel otherwise. A macro, as prefiltered_radiance_at_lod.
#if defined(FACET_PRESHADED_ROUGHNESS) && !defined(FACET_SPECULAR_AA)
#define material_prefiltered_radiance(r, perceptualRoughness) prefiltered_radiance_at_lod(r, params.facet_environmentLod)
#else
#define material_prefiltered_radiance(r, perceptualRoughness) prefiltered_radiance(r, perceptualRoughness)
#endif

// Specular ambient: the environment reflected about n, weighted by the tier's environment BRDF.
vec3 shade_standard_ambient_specular(MaterialInputs material, vec3 n, vec3 v) {
    vec3 f0 = material_f0(material);
    float perceptualRoughness = material_perceptual_roughness(material);
    float NoV = max(dot(n, v), MIN_N_DOT_V);
#if defined(FACET_ANISOTROPY)
    vec3 r = anisotropic_reflection(material, n, v, NoV, perceptualRoughness);  // anisotropy_frame.glsl
#else
    vec3 r = reflect(-v, n);
#if defined(FACET_IBL_DOMINANT_DIRECTION)
    r = specular_dominant_direction(n, r, perceptualRoughness);
#endif
#endif
#if defined(FACET_IBL_SPLIT_SUM)
    vec2 dfg = dfg_terms(NoV, perceptualRoughness);
    vec3 albedo = split_sum_albedo(dfg, f0);
#if defined(FACET_ENERGY_COMPENSATION)
    shading_energy_compensation = energy_compensation(dfg, f0);
#endif
    vec3 specular = material_prefiltered_radiance(r, perceptualRoughness);
#elif defined(FACET_IBL_ANALYTIC)
    vec3 albedo = env_brdf_karis(f0, NoV, perceptualRoughness);
    vec3 specular = material_prefiltered_radiance(r, perceptualRoughness);
#elif defined(FACET_IBL_SAMPLED)
    // The integral has f0 and Fresnel in it; the table gives only the compensation.
    vec3 albedo = vec3(1.0);
#if defined(FACET_ENERGY_COMPENSATION)
    shading_energy_compensation = energy_compensation(dfg_terms(NoV, perceptualRoughness), f0);
#endif
    vec3 specular = sampled_specular_radiance(material, n, v);
#else
    vec3 albedo = env_brdf_zioma_saturated(f0, NoV, perceptualRoughness);
    vec3 specular = two_mip_radiance(r, perceptualRoughness);
#endif
#if defined(FACET_ENERGY_COMPENSATION)
    albedo *= shading_energy_compensation;
#endif
#if defined(SPECULAR_LOBE_SCALED_BY_ALBEDO)
    shading_specular_albedo = albedo;  // compensated: the lobe takes it as it is
#endif
#if defined(FACET_MATERIAL_AMBIENT_OCCLUSION)
    return apply_specular_occlusion(material, specular * albedo, NoV, perceptualRoughness);
#else
    return apply_ambient_occlusion(material, specular * albedo);
#endif
}

// Adds linear radiance to the linear sum (with FACET_GAMMA_HACK the encoded diffuse was decoded
// first: linear_from_shading_space, output_blending.glsl). fp16: each term is ≤ 65504; the gamma
// hack's sum keeps the saturation its earlier encoded form had (min before its √).
vec3 add_light(vec3 color, vec3 radiance) {
#if defined(FACET_GAMMA_HACK)
    return min(color + radiance, MEDIUMP_FLT_MAX);
#else
    return color + radiance;
#endif
}
