// The ambient term of Filament's standard model (shading_standard.glsl has the model and its
// symbols):
//   L_ambient = (diffuseColor · E_env(n)/π + L_spec,ibl · c_ms) · ao
// E_env/π comes from SH (ambient_sh.glsl), L_spec,ibl from the tier's image-based specular:
// the split sum (ibl_split_sum.glsl: prefiltered environment × DFG table, reference and high),
// the prefiltered environment × Karis's analytic environment BRDF (env_brdf_karis.glsl, mid), or
// two fixed mips × Zioma's fit (ibl_two_mip.glsl, low). With FACET_ENERGY_COMPENSATION it also
// sets shading_energy_compensation from the DFG terms it reads, before any light is shaded.
// Needs: shading_standard.glsl and the tier's IBL chunks. fp16: radiance is pre-exposed.

// Diffuse ambient lit per pixel: irradiance / π from SH at the shading normal.
vec3 shade_standard_ambient(MaterialInputs material, vec3 irradianceOverPi) {
#if defined(FACET_GAMMA_HACK)
    irradianceOverPi = sqrt(irradianceOverPi);  // encoded like the colours it multiplies (γ = 2)
#endif
    return material_diffuse_color(material) * irradianceOverPi * clamp(material.ambientOcclusion, 0.0, 1.0);
}

// Specular ambient: the environment reflected about n, weighted by the tier's environment BRDF.
vec3 shade_standard_ambient_specular(MaterialInputs material, vec3 n, vec3 v) {
    vec3 f0 = material_f0(material);
    float perceptualRoughness = material_perceptual_roughness(material);
    float NoV = max(dot(n, v), MIN_N_DOT_V);
    vec3 r = reflect(-v, n);
#if defined(FACET_IBL_SPLIT_SUM)
    vec2 dfg = dfg_terms(NoV, perceptualRoughness);
    vec3 specular = ibl_specular_split_sum(prefiltered_radiance(r, perceptualRoughness), dfg, f0);
#if defined(FACET_ENERGY_COMPENSATION)
    shading_energy_compensation = energy_compensation(dfg, f0);
    specular *= shading_energy_compensation;
#endif
#elif defined(FACET_IBL_ANALYTIC)
    vec3 specular = prefiltered_radiance(r, perceptualRoughness) * env_brdf_karis(f0, NoV, perceptualRoughness);
#else
    vec3 specular = two_mip_radiance(r, perceptualRoughness) * env_brdf_zioma_saturated(f0, NoV, perceptualRoughness);
#endif
    return specular * clamp(material.ambientOcclusion, 0.0, 1.0);
}

// Adds the ambient specular (linear) to the ambient diffuse. With FACET_GAMMA_HACK the diffuse is
// encoded (d_γ = √d) and the sum is formed in linear before encoding again: √(d_γ² + s) costs the
// same square root as encoding s alone, and avoids the hack's cross term ((d_γ + √s)² = d + s +
// 2√(ds)), which for an environment lighting every pixel both ways would brighten the whole
// surface, not just highlights (measured: low tier 19.0 dB instead of 27.7 dB against reference in
// test_punctual_lights' scene).
vec3 add_ambient_specular(vec3 diffuse, vec3 specular) {
#if defined(FACET_GAMMA_HACK)
    return sqrt(diffuse * diffuse + specular);
#else
    return diffuse + specular;
#endif
}
