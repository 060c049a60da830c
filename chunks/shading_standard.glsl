// Filament's standard (metallic-roughness) model, split into the ambient term every variant
// has and the direct term of one directional light (present in `dir1` variants only):
//   diffuseColor = (1 − metallic) · baseColor
//   f0           = 0.16 · reflectance² · (1 − metallic) + metallic · baseColor
//   α            = r², r = max(roughness, MIN_PERCEPTUAL_ROUGHNESS)
//   L_direct  = (diffuseColor · f_d + f_s · c_ms) · E_light · n·l      f_s: the tier's specular_lobe
//   L_ambient = (diffuseColor · E_env(n)/π + L_spec,ibl · c_ms) · ao
// E_env/π comes from SH (ambient_sh.glsl; a constant sky L gives exactly L), L_spec,ibl from the
// tier's image-based specular (ibl_split_sum.glsl, env_brdf_karis.glsl or ibl_two_mip.glsl), and
// c_ms is the multiple-scattering compensation (1 except with FACET_ENERGY_COMPENSATION, the
// reference tier). ao also scales the ambient specular: a cheap stand-in for specular occlusion
// (Filament derives a separate one from ao, n·v and roughness; not done).
// Source: Filament PBR document §4.8 (parameterization), §4.6 (reflectance remapping).
// With FACET_VERTEX_DIFFUSE (Zioma 2015's per-vertex diffuse for mid and low tiers), the diffuse
// irradiance arrives interpolated from the vertex stage and only specular is shaded per pixel.
// Needs: diffuse_lambert.glsl and the tier's specular_lobe. fp16: inputs are pre-exposed.
//
// With FACET_GAMMA_HACK (the low tier; R. Zioma, "Optimizing PBR", SIGGRAPH 2015, "Linear/Gamma"):
// lighting runs on gamma-encoded colours, gamma approximated by 2 (x_γ = √x). The runtime does not
// linearise colour parameters or sRGB textures for such variants, so baseColor arrives encoded.
//   diffuse_γ  = diffuseColor_γ · √(irradiance/π)        (√ per vertex with FACET_VERTEX_DIFFUSE)
//   f0_γ       = 0.4 · reflectance · (1 − metallic) + metallic · baseColor_γ    (√(0.16 r²) = 0.4 r)
//   specular_γ = √(f_s(f0_γ²) · E_light · n·l)
// so the specular intensity is computed in linear (roughness, the lobe, n·l and the light are
// linear quantities) and converted with a square root before it is added to the gamma-space
// diffuse. For a Fresnel-free lobe (lut) f_s(f0) = S·f0 and this is the talk's
// √(specIntensity_linear) · specColor_γ, written so that it stays right for lobes with Fresnel.
// The sum is squared back to linear once, in blend_output (output_blending.glsl), because the
// HDR target and the post pass expect linear values. Errors of the hack, by design: sums of
// encoded terms square to more than the sum ((a_γ + b_γ)² = a + b + 2√(ab): highlights over lit
// diffuse come out brighter), interpolation and surface arithmetic act on encoded values, and
// sRGB-encoded inputs are decoded with γ = 2 instead of the sRGB curve.

vec3 material_diffuse_color(MaterialInputs material) {
    return (1.0 - clamp(material.metallic, 0.0, 1.0)) * clamp(material.baseColor, 0.0, 1.0);
}

// f0 in linear, whatever the colour space (the lobes and the environment BRDFs work in linear).
vec3 material_f0(MaterialInputs material) {
    vec3 baseColor = clamp(material.baseColor, 0.0, 1.0);
    float metallic = clamp(material.metallic, 0.0, 1.0);
    float reflectance = clamp(material.reflectance, 0.0, 1.0);
#if defined(FACET_GAMMA_HACK)
    vec3 f0Gamma = vec3(0.4 * reflectance * (1.0 - metallic)) + metallic * baseColor;
    return f0Gamma * f0Gamma;
#else
    return vec3(0.16 * reflectance * reflectance * (1.0 - metallic)) + metallic * baseColor;
#endif
}

float material_perceptual_roughness(MaterialInputs material) {
    return clamp(material.roughness, MIN_PERCEPTUAL_ROUGHNESS, 1.0);
}

#if defined(FACET_ENERGY_COMPENSATION)
// Set once per pixel by shade_standard_ambient_specular (which reads the DFG terms it needs)
// before any light is shaded; multiplies every specular term.
vec3 shading_energy_compensation = vec3(1.0);
#endif

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

vec3 shade_standard_direct(MaterialInputs material, vec3 n, vec3 v, vec3 l,
                                   vec3 lightColor) {
    vec3 f0 = material_f0(material);
    float perceptualRoughness = material_perceptual_roughness(material);
    float alpha = perceptualRoughness * perceptualRoughness;

    vec3 h = normalize(v + l);
    float NoV = max(dot(n, v), MIN_N_DOT_V);
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    float LoH = clamp(dot(l, h), 0.0, 1.0);

    vec3 specular = specular_lobe(perceptualRoughness, alpha, NoV, NoL, NoH, LoH, n, v, l, h, f0);
#if defined(FACET_ENERGY_COMPENSATION)
    specular *= shading_energy_compensation;
#endif
#if defined(FACET_GAMMA_HACK)
    vec3 specularGamma = sqrt(specular * (lightColor * NoL));
#if defined(FACET_VERTEX_DIFFUSE)
    return specularGamma;
#else
    return material_diffuse_color(material) * sqrt(lightColor * (NoL * diffuse_lambert())) + specularGamma;
#endif
#elif defined(FACET_VERTEX_DIFFUSE)
    // Diffuse is lit per vertex (forward.vert.glsl): only specular remains per pixel.
    return specular * lightColor * NoL;
#else
    return (material_diffuse_color(material) * diffuse_lambert() + specular) * lightColor * NoL;
#endif
}
