// The `sampled` ambient option: the environment integrated per pixel by Monte Carlo with
// importance sampling, the ground truth the other ambient models approximate. It is for
// measurement (`matc eval --ground-truth`): no tier's preset and no material can ask for it, and
// its cost (FACET_IBL_SAMPLES environment reads per term per pixel) is not a mobile one.
//   specular  ∫ L(l) f_s(v, l) (n·l) dl ≈ 1/N Σ L(l_i) f_s(v, l_i) (n·l_i) / p(l_i),
//             h_i drawn with density D(h)(n·h) (GGX: Walter et al. 2007, "Microfacet Models for
//             Refraction through Rough Surfaces", eqs. 35–36), l_i = reflect(−v, h_i), and
//             p(l) = D(h)(n·h) / (4 v·h) (the Jacobian of the reflection, eq. 14 there);
//             f_s is the tier's own lobe (specular_lobe, or the anisotropic lobe that replaces
//             it), so a tier's ambient is measured against the integral of the lobe it lights
//             its sun with; the isotropic GGX density stays positive wherever either lobe is.
//   diffuse   E(n)/π = 1/π ∫ L(l)(n·l) dl ≈ 1/N Σ L(l_j), l_j with density (n·l)/π
// Points: the Hammersley set, the same for every pixel, so what error remains varies smoothly
// over the image instead of as noise; eval reports the change from N to 4N samples.
// Environment: level 0 of facet_environment, the radiance as the renderer holds it (64² a face,
// docs/ibl.md): the ground truth of Facet's model under that environment; what level 0 itself
// loses of the source image is not measured here.
// Precision: highp throughout (the `reference` tier; a mediump build would still sum in highp).
// Needs: math.glsl, shading_standard.glsl (the material functions), the tier's specular lobe,
// environment_cube.glsl.
#if defined(SPECULAR_LOBE_SCALED_BY_ALBEDO)
#error "the sampled ambient integrates a lobe of f0; an albedo-scaled lobe (specular_lut_lobe.glsl) has none"
#endif

// Point i of the n-point Hammersley set: ((i + 1/2)/n, the base-2 radical inverse of i). The bit
// reversal by hand: GLSL ES 3.00 has no bitfieldReverse.
highp vec2 hammersley(highp uint i, highp uint n) {
    highp uint b = (i << 16u) | (i >> 16u);
    b = ((b & 0x55555555u) << 1u) | ((b & 0xAAAAAAAAu) >> 1u);
    b = ((b & 0x33333333u) << 2u) | ((b & 0xCCCCCCCCu) >> 2u);
    b = ((b & 0x0F0F0F0Fu) << 4u) | ((b & 0xF0F0F0F0u) >> 4u);
    b = ((b & 0x00FF00FFu) << 8u) | ((b & 0xFF00FF00u) >> 8u);
    return vec2((float(i) + 0.5) / float(n), float(b) * 2.3283064365386963e-10);  // b / 2^32
}

// An orthonormal frame with n as its third column.
highp mat3 sampling_frame(highp vec3 n) {
    highp vec3 up = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    highp vec3 t = normalize(cross(up, n));
    return mat3(t, cross(n, t), n);
}

// irradiance / π at n: the mean radiance over cosine-distributed directions.
highp vec3 sampled_irradiance_over_pi(highp vec3 n) {
    highp mat3 frame = sampling_frame(n);
    highp vec3 sum = vec3(0.0);
    for (highp uint i = 0u; i < uint(FACET_IBL_SAMPLES); ++i) {
        highp vec2 u = hammersley(i, uint(FACET_IBL_SAMPLES));
        highp float phi = 2.0 * PI * u.x;
        highp float sinTheta = sqrt(u.y);
        highp vec3 l = frame * vec3(sinTheta * cos(phi), sinTheta * sin(phi), sqrt(1.0 - u.y));
        sum += textureLod(facet_environment, l, 0.0).rgb;
    }
    return sum / float(FACET_IBL_SAMPLES);
}

// ∫ L f_s (n·l) dl of the tier's lobe, without the energy compensation (the caller applies it).
highp vec3 sampled_specular_radiance(MaterialInputs material, highp vec3 n, highp vec3 v) {
    vec3 f0 = material_f0(material);
    float perceptualRoughness = material_perceptual_roughness(material);
    highp float alpha = material_alpha(material);
    highp float a2 = alpha * alpha;
    highp float NoV = max(dot(n, v), MIN_N_DOT_V);
    highp mat3 frame = sampling_frame(n);
    highp vec3 sum = vec3(0.0);
    for (highp uint i = 0u; i < uint(FACET_IBL_SAMPLES); ++i) {
        highp vec2 u = hammersley(i, uint(FACET_IBL_SAMPLES));
        highp float phi = 2.0 * PI * u.x;
        highp float cosTheta = sqrt((1.0 - u.y) / (1.0 + (a2 - 1.0) * u.y));
        highp float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
        highp vec3 h = frame * vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
        highp vec3 l = reflect(-v, h);
        highp float NoL = dot(n, l);
        highp float VoH = dot(v, h);
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        highp float NoH = cosTheta;
        highp float k = (NoH * NoH) * (a2 - 1.0) + 1.0;
        highp float pdfOverNoH = a2 / (PI * k * k);  // D(h); p(l) = D (n·h) / (4 v·h)
#if defined(FACET_ANISOTROPY_LOBE)
        highp vec3 lobe = anisotropic_ggx_smith(NoV, NoL, NoH, l, h) * fresnel_schlick(f0, VoH);
#else
        highp vec3 lobe = specular_lobe(perceptualRoughness, alpha, NoV, NoL, NoH, VoH, n, v, l, h, f0);
#endif
        sum += textureLod(facet_environment, l, 0.0).rgb * lobe * (NoL * 4.0 * VoH / (pdfOverNoH * NoH));
    }
    return sum / float(FACET_IBL_SAMPLES);
}
