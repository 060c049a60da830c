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
// This file holds the material terms and the direct term; the ambient term is in
// shading_ambient.glsl. Needs: diffuse_lambert.glsl and the tier's specular_lobe. fp16: inputs
// are pre-exposed.
//
// With FACET_GAMMA_HACK (the low tier; R. Zioma, "Optimizing PBR", SIGGRAPH 2015, "Linear/Gamma"):
// lighting runs on gamma-encoded colours, gamma approximated by 2 (x_γ = √x). The runtime does not
// linearise colour parameters or sRGB textures for such variants, so baseColor arrives encoded.
//   diffuse_γ  = diffuseColor_γ · √(irradiance/π)        (√ per vertex with FACET_VERTEX_DIFFUSE)
//   f0_γ       = 0.4 · reflectance · (1 − metallic) + metallic · baseColor_γ    (√(0.16 r²) = 0.4 r)
//   specular   = f_s(f0_γ²) · E_light · n·l, linear, added to c = diffuse_γ² in linear
// so the specular intensity is computed in linear (roughness, the lobe, n·l and the light are
// linear quantities) and summed in linear after the encoded diffuse is squared back once
// (linear_from_shading_space in output_blending.glsl, add_light in shading_ambient.glsl): no √ at
// all, where the talk's form √(specIntensity_linear) · specColor_γ costs one per light, and
// without that form's cross term (a_γ + b_γ)² = a + b + 2√(ab), which made a lobe's faint tail
// over lit diffuse 2√(d s) bright (measured in docs/specular-tiers.md). Errors of the hack, by
// design: interpolation and surface arithmetic act on encoded values, and sRGB-encoded inputs are
// decoded with γ = 2 instead of the sRGB curve.

// With FACET_PRESHADED_DIFFUSE_COLOR, FACET_PRESHADED_F0 and FACET_PRESHADED_ROUGHNESS the
// inputs depend only on parameters: the preshader (compiler/preshader.h, Unreal's term) computes
// these same formulas once on the CPU when the parameters change, in fp32, and the runtime writes
// them into the parameter block (members facet_*, after the parameters). The forms below are then
// what the preshader implements, and what variants with per-pixel inputs (textures, vertex
// attributes) still run.
vec3 material_diffuse_color(MaterialInputs material) {
#if defined(FACET_PRESHADED_DIFFUSE_COLOR)
    return params.facet_diffuseColor;
#else
    return (1.0 - clamp(material.metallic, 0.0, 1.0)) * clamp(material.baseColor, 0.0, 1.0);
#endif
}

// f0 in linear, whatever the colour space (the lobes and the environment BRDFs work in linear).
vec3 material_f0(MaterialInputs material) {
#if defined(FACET_PRESHADED_F0)
    return params.facet_f0;
#else
    vec3 baseColor = clamp(material.baseColor, 0.0, 1.0);
    float metallic = clamp(material.metallic, 0.0, 1.0);
    float reflectance = clamp(material.reflectance, 0.0, 1.0);
#if defined(FACET_GAMMA_HACK)
    vec3 f0Gamma = vec3(0.4 * reflectance * (1.0 - metallic)) + metallic * baseColor;
    return f0Gamma * f0Gamma;
#else
    return vec3(0.16 * reflectance * reflectance * (1.0 - metallic)) + metallic * baseColor;
#endif
#endif
}

// With FACET_SPECULAR_AA the roughness is widened per pixel (specular_antialiasing.glsl, written
// back into material.roughness by main()): the preshaded value is not the one to shade with.
float material_perceptual_roughness(MaterialInputs material) {
#if defined(FACET_PRESHADED_ROUGHNESS) && !defined(FACET_SPECULAR_AA)
    return params.facet_perceptualRoughness;
#else
    return clamp(material.roughness, MIN_PERCEPTUAL_ROUGHNESS, 1.0);
#endif
}

// α = r² (Filament PBR document §4.8: perceptual roughness remapped to the lobes' α).
float material_alpha(MaterialInputs material) {
#if defined(FACET_PRESHADED_ROUGHNESS) && !defined(FACET_SPECULAR_AA)
    return params.facet_alpha;
#else
    float perceptualRoughness = material_perceptual_roughness(material);
    return perceptualRoughness * perceptualRoughness;
#endif
}

#if defined(SPECULAR_LOBE_SCALED_BY_ALBEDO)
// The environment BRDF E(n·v, r, f0) (the specular's directional albedo, f0 and Fresnel in it),
// times the energy compensation c_ms where there is one, set once per pixel by
// shade_standard_ambient_specular before any light is shaded (the ambient specular multiplies by
// the same product, so it is formed once). A lobe chunk that defines SPECULAR_LOBE_SCALED_BY_ALBEDO
// (specular_lut_lobe.glsl) takes it in place of f0, and its result is not compensated again.
vec3 shading_specular_albedo = vec3(0.0);
#endif

#if defined(FACET_ENERGY_COMPENSATION)
// Set once per pixel by shade_standard_ambient_specular (which reads the DFG terms it needs)
// before any light is shaded; multiplies every specular term.
vec3 shading_energy_compensation = vec3(1.0);
#endif

// The half vector h = (v + l)/|v + l|, summed and normalized in highp where the lobe asks for it
// (SPECULAR_HALF_VECTOR_HIGHP: the GGX/Smith lobes of reference and high), returned at the tier's
// precision. Why: |v + l| = 2 l·h, so where the light faces the eye (a glint at grazing
// incidence, v ≈ −l) the sum cancels. With v and l rounded to binary16 (unit roundoff
// u = 2^-11, |δv|, |δl| ≤ u) the sum is off by up to 2u and h tilts by up to
// 2u / |v + l| = u / l·h radians. At the roughness floor (α = 0.089² = 0.0079) the GGX lobe
// falls to half its peak 0.64 α = 0.0051 rad from its axis ((α² + θ²)² = 2α⁴), so the tilt
// must stay well below that: l·h ≫ u / 0.0051 ≈ 0.1, i.e. v and l more than ~11° from
// opposite. In fp32 (u = 2^-24) the bound is l·h ≫ 1.2e-5, and the result rounded to binary16
// is a unit vector off by ≤ u = 4.9e-4 rad, a tenth of the lobe, as everywhere else
// (Fp16Shading.HalfVectorStaysExactWhereTheLightFacesTheEye: 0.04 at mediump, 2e-4 here).
// Filament keeps its view vector highp on mobile for the same reason (Filament PBR document
// §4.4's precision notes). Cost: the add, dot and scale in fp32 instead of fp16, +0.07
// estimated cycles (docs/eval.md's model). mid's Zioma lobe, whose fused V·F already misses a
// grazing glint by far more (26 dB on grazing_glint in fp32 and fp16 alike), keeps the mediump
// sum: measured no worse there (docs/fp16-emulation.md). The cloth model reads no GGX lobe, only
// Charlie's sheen, whose lobe is wide: D ∝ sin(θ_h)^(1/α) ≈ exp(−(π/2 − θ_h)² / 2α) about its
// peak falls to half of it 1.18 √α = 0.105 rad away at the floor, 20× GGX's. The tilt then needs
// only l·h ≫ u / 0.105 = 0.0047 (v and l more than ~0.5° from opposite), so cloth sums in
// mediump whatever the tier's lobe (Fp16Cloth.HighAbove50DbWhereTheViewGrazes holds it; on
// llvmpipe's true fp16, 3 rim pixels of examples/scenes/velvet.json move by 3–4 8-bit steps).
#if defined(SPECULAR_HALF_VECTOR_HIGHP) && !defined(FACET_SHADING_CLOTH)
vec3 half_vector(highp vec3 v, highp vec3 l) {
    return normalize(v + l);
}
#else
vec3 half_vector(vec3 v, vec3 l) {
    return normalize(v + l);
}
#endif

// v and l arrive highp (the half vector may need them so, above); every other use is mediump.
vec3 shade_standard_direct(MaterialInputs material, vec3 n, highp vec3 viewHighp, highp vec3 lightHighp,
                                   vec3 lightColor) {
    vec3 f0 = material_f0(material);
    float perceptualRoughness = material_perceptual_roughness(material);
    float alpha = material_alpha(material);

    vec3 v = viewHighp;
    vec3 l = lightHighp;
    float NoV = max(dot(n, v), MIN_N_DOT_V);
    float NoL = clamp(dot(n, l), 0.0, 1.0);
#if defined(FACET_HALF_VECTOR_SCALED)
    // h' = 2^6 h (GGX_D_SCALE), the scale folded into the normalization, where the only reader of
    // h and n·h is the lobe's GGX denominator (ggx_denominator.glsl; the assembler's
    // halfVectorScaled): 2 FMA-pipe ops fewer on Mali-G57 (docs/tune.md's mid ablation). l·h is
    // l·h' / 2^6, exactly. fp16: for |v + l|² ≥ 2^-14 (a normal), 2^6 / |v + l| ≤ 2^13 and each
    // component of h' is ≤ 2^6, n·h' and l·h' too; below it, as normalize, the sum is lost.
    vec3 h = (v + l) * (GGX_D_SCALE * inversesqrt(dot(v + l, v + l)));
    float NoH = clamp(dot(n, h), 0.0, GGX_D_SCALE);
    float LoH = clamp(dot(l, h) * (1.0 / GGX_D_SCALE), 0.0, 1.0);
#else
#if defined(SPECULAR_HALF_VECTOR_HIGHP)
    vec3 h = half_vector(viewHighp, lightHighp);
#else
    vec3 h = half_vector(v, l);
#endif
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    float LoH = clamp(dot(l, h), 0.0, 1.0);
#endif

#if defined(FACET_ANISOTROPY_LOBE)
    // The anisotropic lobe replaces the tier's (anisotropy_ggx_smith.glsl), without the energy
    // compensation: the isotropic factor 1/E(α) on it (Filament's) reflects up to 1.74 of the
    // light in a white furnace (anisotropy_ggx_smith.glsl has the figures).
    vec3 specular = anisotropic_ggx_smith(NoV, NoL, NoH, l, h) * fresnel_schlick(f0, LoH);
#else
#if defined(SPECULAR_LOBE_SCALED_BY_ALBEDO)
    vec3 specular = specular_lobe(perceptualRoughness, alpha, NoV, NoL, NoH, LoH, n, v, l, h, shading_specular_albedo);
#else
    vec3 specular = specular_lobe(perceptualRoughness, alpha, NoV, NoL, NoH, LoH, n, v, l, h, f0);
#endif
#if defined(FACET_ENERGY_COMPENSATION) && !defined(SPECULAR_LOBE_SCALED_BY_ALBEDO)
    specular *= shading_energy_compensation;  // (an albedo-scaled lobe's albedo carries it already)
#endif
#endif
    // fp16: the lobe is ≤ 65504 (saturated) but the outgoing light need not be: at a grazing
    // sun glint (n = h, n·v = n·l = c; specular_ggx_smith.glsl) f_s · E · n·l ≈ 1269 E / c at the
    // roughness floor, 3.6e4 at c = 0.1 and 4.6e5 as c → 0.001 with E = 2.86 (the 110 000 lux
    // sun pre-exposed for f/16 1/125 s ISO 100) — beyond fp16 and the RGBA16F target in every
    // tier. E · n·l ≤ E is formed first, so a lobe saturated at a grazing n·l = 0
    // gives 65504 · 0 = 0, not (65504 · E = +inf) · 0 = NaN; the product, at worst +inf, is then
    // clamped to 65504. That clamp is the RGBA16F target's limit, so it applies in every tier
    // (saturateMediump is an identity in the highp `reference`).
    vec3 irradiance = lightColor * NoL;
#if defined(FACET_SHEEN_LAYER) && defined(FACET_SHEEN_LOBE)
    // Under a sheen layer (sheen_layer.glsl): the base × b, the sheen's lobe over it.
    vec3 sheen = sheen_light(NoV, NoL, NoH) * lightColor;
    irradiance *= shading_sheen_base_scale;
#endif
#if defined(FACET_CLEAR_COAT_LOBE) && defined(CLEAR_COAT_SHARES_THE_BASE_LIGHT)
    // Under a clear coat whose n·l is the base's (clear_coat_ggx_kelemen.glsl): its lobe joins the
    // base's, × (1 − Fc(n_c·v)), before the light multiplies them (below).
    float coatLobe = clear_coat_lobe(material, h, LoH);
#elif defined(FACET_CLEAR_COAT_LOBE)
    // Under a clear coat (clear_coat_ggx_kelemen.glsl): the base is lit through it, × (1 − Fc(n_c·v)),
    // and the coat adds its own lobe (finite: ≤ 65504 · E · n·l, saturated with the sum below).
    vec3 coat = clear_coat_direct(material, l, h, LoH, lightColor);
    irradiance *= shading_clear_coat_attenuation;
#endif
    // `coat`: what lies over the base's lobes, the coat's and, under it, the sheen's.
#if defined(FACET_SHEEN_LAYER) && defined(FACET_SHEEN_LOBE) && defined(FACET_CLEAR_COAT_LOBE)
    coat += sheen * shading_clear_coat_attenuation;
#elif defined(FACET_SHEEN_LAYER) && defined(FACET_SHEEN_LOBE)
    vec3 coat = sheen;
#endif
    // Linear in every colour space: with FACET_GAMMA_HACK the caller adds it to the linear sum
    // with add_light (shading_ambient.glsl), as the ambient specular.
#if defined(FACET_CLEAR_COAT_LOBE) && defined(CLEAR_COAT_SHARES_THE_BASE_LIGHT)
    // The lobes' sum is saturated before E · n·l: the base's and the coat's may both be 65504 at a
    // grazing mirror, where n·l = 0 (65504 · 0 = 0, where inf · 0 is NaN).
#if defined(FACET_VERTEX_DIFFUSE)
    vec3 lobes = specular;
#else
    vec3 diffuseColor = material_diffuse_color(material);
#if defined(FACET_GAMMA_HACK)
    diffuseColor *= diffuseColor;  // encoded with γ = 2: back to linear
#endif
    vec3 lobes = diffuseColor * diffuse_lambert() + specular;
#endif
    return min(min(lobes * shading_clear_coat_attenuation + coatLobe, MEDIUMP_FLT_MAX) * irradiance, MEDIUMP_FLT_MAX);
#elif defined(FACET_VERTEX_DIFFUSE)
    // Diffuse is lit per vertex (forward.vert.glsl): only specular remains per pixel.
#if defined(FACET_CLEAR_COAT_LOBE) || (defined(FACET_SHEEN_LAYER) && defined(FACET_SHEEN_LOBE))
    return min(specular * irradiance + coat, MEDIUMP_FLT_MAX);
#elif defined(SPECULAR_LOBE_SCALAR) && !defined(FACET_ENERGY_COMPENSATION) && !defined(FACET_ANISOTROPY_LOBE)
    // A scalar lobe s (times f0) as (s · n·l) · (f0 · E): the same product, one FMA-pipe op fewer
    // on Mali-G57 than (s f0)(E n·l), which the shader compiler does not reassociate itself
    // (docs/tune.md's mid ablation). fp16: s ≤ 65504 (saturated) and n·l ∈ [0, 1], so s · n·l is
    // finite and 0 where n·l = 0; f0 · E is finite; their product, at worst +inf, is clamped.
    return min((specular_lobe_scalar(alpha, NoH, LoH, n, h) * NoL) * (f0 * lightColor), MEDIUMP_FLT_MAX);
#else
    return min(specular * irradiance, MEDIUMP_FLT_MAX);
#endif
#else
    vec3 diffuseColor = material_diffuse_color(material);
#if defined(FACET_GAMMA_HACK)
    diffuseColor *= diffuseColor;  // encoded with γ = 2: back to linear
#endif
#if defined(FACET_CLEAR_COAT_LOBE) || (defined(FACET_SHEEN_LAYER) && defined(FACET_SHEEN_LOBE))
    return min((diffuseColor * diffuse_lambert() + specular) * irradiance + coat, MEDIUMP_FLT_MAX);
#else
    return min((diffuseColor * diffuse_lambert() + specular) * irradiance, MEDIUMP_FLT_MAX);
#endif
#endif
}
