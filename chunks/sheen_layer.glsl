// The sheen over a base: the cloth model's over its fabric (shading_cloth.glsl, where the lobe's
// formulas, its energy correction s and the table are derived), and the sheen layer over the
// standard model of a lit material that writes sheenColor (KHR_materials_sheen, the Khronos glTF
// extension's specification: "sheen layer", "Albedo scaling"; docs/material-models.md, "Sheen layer"):
//   L        = L_base · b + Σ_lights sheenColor · D · V · n·l · s · E_light + prefiltered(reflect(−v, n), r_s) · sheenColor · min(E, 1) · so
//   b        = 1 − max(sheenColor) · min(E(n·v, r_s), 1)
//   D, V     = Charlie's and Neubelt's (sheen_charlie_neubelt.glsl), α = r_s², s = 1/max(1, E(n·v, r_s))
// r_s is the cloth's roughness, or sheenRoughness on a lit material (the extension's: the sheen's own,
// independent of the base's). E, the sheen's directional albedo, and s come from the DFG texture's
// B and A channels (ibl/sheen_lut.h), one fetch at (n·v, r_s) per pixel, before any light.
// Energy: the sheen's albedo is max(sheenColor) · min(E, 1) at most (min(E, 1) for the lobe, the
// environment term the same fraction of a constant sky) and b leaves the base 1 − that, so a base
// that reflects ≤ 1 (the standard model's white furnace, docs/ibl.md) stays ≤ 1 under the layer:
// max(c) E + (1 − max(c) E) · 1 = 1. b is taken at the view only (the extension's form without its
// optional light term; as the clear coat's 1 − Fc(n·v), one per pixel, not per light). Under a
// clear coat the layer is part of the coated base: each light's sheen takes the coat's 1 − Fc
// (clear_coat_ambient.glsl, shading_standard.glsl), and the coat's layer is applied after this one.
// fp16: the lobe's bounds are sheen_charlie_neubelt.glsl's (≤ 5.2 × sheenColor per unit light); the
// light's product is saturated at 65504 as the standard model's. b, min(E, 1) and s lie in [0, 1].
// Needs: shading_standard.glsl (material terms, half_vector), shading_ambient.glsl (the specular
// occlusion), the prefiltered (or two-mip) environment, facet_dfgLut, and with FACET_SHEEN_LOBE
// sheen_charlie_neubelt.glsl.

// The sheen's colour in linear; under FACET_GAMMA_HACK colours arrive encoded with γ = 2, like
// baseColor (shading_standard.glsl). The cloth model's defaults to √baseColor (Filament's default: a
// two-tone sheen lighter than the fabric); a lit material's layer exists only where it is written.
// With FACET_PRESHADED_SHEEN_COLOR and FACET_PRESHADED_SHEEN_ROUGHNESS the sheen's inputs depend
// only on parameters: the preshader (compiler/preshader.h) forms these same values on the CPU (the
// colour, r_s, α_s and the environment's lod r_s (2 − r_s) · (levels − 1), prefiltered_radiance's in
// ibl_prefiltered.glsl; a cloth's r_s and α are the standard model's), and the forms below are what
// it implements. A cloth's r_s is widened per pixel with FACET_SPECULAR_AA: then its lod is formed here.
vec3 sheen_color(MaterialInputs material) {
#if defined(FACET_PRESHADED_SHEEN_COLOR)
    return params.facet_sheenColor;
#elif defined(FACET_MATERIAL_SHEEN_COLOR) && defined(FACET_GAMMA_HACK)
    vec3 sheen = clamp(material.sheenColor, 0.0, 1.0);
    return sheen * sheen;
#elif defined(FACET_MATERIAL_SHEEN_COLOR)
    return clamp(material.sheenColor, 0.0, 1.0);
#elif defined(FACET_GAMMA_HACK)
    return clamp(material.baseColor, 0.0, 1.0);  // √(linear baseColor) is the encoded baseColor
#else
    return sqrt(clamp(material.baseColor, 0.0, 1.0));
#endif
}

// r_s, clamped to the floor every lobe takes (MIN_PERCEPTUAL_ROUGHNESS, precision.glsl: the lobe's
// fp16 bounds assume it).
float sheen_perceptual_roughness(MaterialInputs material) {
#if defined(FACET_SHADING_CLOTH)
    return material_perceptual_roughness(material);
#elif defined(FACET_PRESHADED_SHEEN_ROUGHNESS)
    return params.facet_sheenRoughness;
#else
    return clamp(material.sheenRoughness, MIN_PERCEPTUAL_ROUGHNESS, 1.0);
#endif
}

#if defined(FACET_SHEEN_LOBE)
// α = r_s² (the cloth's preshaded α where the preshader has it, shading_standard.glsl).
float sheen_alpha(MaterialInputs material) {
#if defined(FACET_SHADING_CLOTH)
    return material_alpha(material);
#elif defined(FACET_PRESHADED_SHEEN_ROUGHNESS)
    return params.facet_sheenAlpha;
#else
    float perceptualRoughness = sheen_perceptual_roughness(material);
    return perceptualRoughness * perceptualRoughness;
#endif
}
#endif

// The sheen over the base lit so far (the ambient terms, and in mid and low the lights' per-vertex
// diffuse) × b, plus the sheen's environment; sets the sheen's terms for the lights
// (FACET_SHEEN_LOBE: sheen_charlie_neubelt.glsl, sheen_light). The environment is read from the GGX-prefiltered levels at r_s
// (Filament's approximation: the sheen's own lobe is wider at grazing views).
vec3 sheen_layer(MaterialInputs material, vec3 base, vec3 n, vec3 v) {
    float perceptualRoughness = sheen_perceptual_roughness(material);
    float NoV = max(dot(n, v), MIN_N_DOT_V);
    // (min(E, 1), 1/max(E, 1)): texel centres at (i + 0.5)/64 as the DFG terms' (ibl_split_sum.glsl).
    vec2 sheenTerms = textureLod(facet_dfgLut, vec2(NoV, perceptualRoughness), 0.0).ba;
    vec3 sheenColor = sheen_color(material);
    float baseScale = 1.0 - max(sheenColor.r, max(sheenColor.g, sheenColor.b)) * sheenTerms.x;
#if defined(FACET_SHEEN_LOBE)
    shading_sheen_color = sheenColor;
    shading_sheen_alpha = sheen_alpha(material);
    shading_sheen_scale = sheenTerms.y;
    shading_sheen_base_scale = baseScale;
#endif
#if defined(FACET_IBL_TWO_MIP)
    vec3 radiance = two_mip_radiance(reflect(-v, n), perceptualRoughness);
#elif defined(FACET_PRESHADED_SHEEN_ROUGHNESS) && !(defined(FACET_SHADING_CLOTH) && defined(FACET_SPECULAR_AA))
    vec3 radiance = prefiltered_radiance_at_lod(reflect(-v, n), params.facet_sheenLod);
#else
    vec3 radiance = prefiltered_radiance(reflect(-v, n), perceptualRoughness);
#endif
    vec3 specular = radiance * (sheenColor * sheenTerms.x);
#if defined(FACET_MATERIAL_AMBIENT_OCCLUSION)
    specular = apply_specular_occlusion(material, specular, NoV, perceptualRoughness);
#endif
    return base * baseScale + specular;
}
