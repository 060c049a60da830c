// Filament's standard (metallic-roughness) model under one directional light and a constant
// ambient term:
//   diffuseColor = (1 − metallic) · baseColor
//   f0           = 0.16 · reflectance² · (1 − metallic) + metallic · baseColor
//   α            = r², r = max(roughness, MIN_PERCEPTUAL_ROUGHNESS)
//   L_out = (diffuseColor · f_d + D V F) · E_light · n·l + diffuseColor · L_ambient · ao
// A constant ambient radiance L gives irradiance π·L; times f_d = 1/π this is diffuseColor·L.
// Source: Filament PBR document §4.8 (parameterization), §4.6 (reflectance remapping).
// Needs: brdf_ggx.glsl, diffuse_lambert.glsl. fp16: inputs are pre-exposed (precision.glsl).
mediump vec3 shade_standard(MaterialInputs material, mediump vec3 n, mediump vec3 v, mediump vec3 l,
                            mediump vec3 lightColor, mediump vec3 ambient) {
    mediump vec3 baseColor = clamp(material.baseColor, 0.0, 1.0);
    mediump float metallic = clamp(material.metallic, 0.0, 1.0);
    mediump float reflectance = clamp(material.reflectance, 0.0, 1.0);
    mediump vec3 diffuseColor = (1.0 - metallic) * baseColor;
    mediump vec3 f0 = vec3(0.16 * reflectance * reflectance * (1.0 - metallic)) + metallic * baseColor;
    mediump float perceptualRoughness = clamp(material.roughness, MIN_PERCEPTUAL_ROUGHNESS, 1.0);
    mediump float alpha = perceptualRoughness * perceptualRoughness;

    mediump vec3 h = normalize(v + l);
    mediump float NoV = max(dot(n, v), MIN_N_DOT_V);
    mediump float NoL = clamp(dot(n, l), 0.0, 1.0);
    mediump float NoH = clamp(dot(n, h), 0.0, 1.0);
    mediump float LoH = clamp(dot(l, h), 0.0, 1.0);

    mediump float D = distribution_ggx(alpha, NoH, n, h);
    mediump float V = visibility_smith_ggx_correlated(alpha, NoV, NoL);
    mediump vec3 F = fresnel_schlick(f0, LoH);

    mediump vec3 direct = (diffuseColor * diffuse_lambert() + (D * V) * F) * lightColor * NoL;
    mediump vec3 indirect = diffuseColor * ambient * clamp(material.ambientOcclusion, 0.0, 1.0);
    return direct + indirect;
}
