// The clear coat's lobe for each light in one division (the `fused` clear coat of mid):
//   f_c = D(h; α_c) · V_K(l·h) · Fc(n_c·v) = α_c² / (d² · X),   X = 4π (l·h)²
//   d   = |n_c × h|² + (α_c n_c·h)²        (GGX's denominator by Lagrange's identity, brdf_ggx.glsl)
//   computed as k · (k · X) with k = α_c / (d X)
//   L   = L_base · (1 − Fc(n_c·v)) + f_c · E_light · n_c·l
// Sources: the lobe is the talk's (R. Guy and M. Agopian, "Physically Based Rendering in
// Filament", "Clear coat model": GGX D, Kelemen's V, f0 = 0.04), the single division is Zioma's
// fusion ("Optimizing PBR", SIGGRAPH 2015; specular_fused_hammon.glsl does the same for the base).
// What it drops against ggx_kelemen: Fresnel at l·h. It takes Fc(n_c·v), which the layer has
// already formed (1 − shading_clear_coat_attenuation, strength included): at the peak of a smooth
// coat's lobe (l the mirror of v) l·h = n_c·v, so the highlight's centre is exact and only its
// flanks and a rough coat's wide lobe see the wrong angle. Cost and error: docs/material-models.md.
// With the coat's normal equal to the base's, |n × h|², n·h and n·l are the base lobe's and
// spirv-opt shares them.
// fp16 (mediump), for α_c ≥ 0.089² (the coat's roughness floor) and d ∈ [α_c², 1]:
//   - (l·h)² is floored at 2^-14 as in clear_coat_ggx_kelemen.glsl (the same derivation: the
//     floor acts only where n·v + n·l < 2^-6), so X ≥ 4π · 2^-14 = 7.7e-4 is a normal number;
//   - d X can fall to 6.27e-5 · 7.7e-4 = 4.8e-8, subnormal: the division runs on 2^11 X with the
//     numerator 2^11 α_c, d · 2^11 X ≥ 9.9e-5 (normal; 2^10 would give 4.9e-5, below 2^-14),
//     ≤ 2^11 · 4π = 25736, and 2^11 α_c ≤ 2048;
//   - k · X = α_c / d ≤ 1/α_c ≤ 127, so k · (k · X) overflows only where the true value exceeds
//     65504, and saturateMediump returns 65504 (k may be +inf there; X > 0, so never NaN).
// Fp16Shading.ClearCoatFusedLobeStaysFiniteAtItsHazards runs it at the hazards: it fails without the
// scale (the mirror at c = 0.2: d X flushed, k = +inf, 65504 where the lobe is finite); 2^10 passes
// too, because where d · 2^10 X is subnormal the true lobe is beyond 65504 anyway, but only 2^11
// keeps the bound above without relying on that.
// Needs: math.glsl, precision.glsl, clear_coat_ambient.glsl.

const float CLEAR_COAT_FUSED_SCALE = 2048.0;  // 2^11: keeps d·X a normal fp16 number (above)

vec3 clear_coat_direct(MaterialInputs material, vec3 l, vec3 h, float LoH, vec3 lightColor) {
    vec3 n = shading_clear_coat_normal;
    float NoL = clamp(dot(n, l), 0.0, 1.0);
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    float r = clear_coat_perceptual_roughness(material);
    float alpha = r * r;
    vec3 NxH = cross(n, h);
    float a = NoH * alpha;
    float d = dot(NxH, NxH) + a * a;
    float x = (4.0 * PI) * max(LoH * LoH, 6.103515625e-5);  // 2^-14, clear_coat_ggx_kelemen.glsl
    float k = (CLEAR_COAT_FUSED_SCALE * alpha) / (d * (CLEAR_COAT_FUSED_SCALE * x));
    float DV = saturateMediump(k * (k * x));
    return DV * (1.0 - shading_clear_coat_attenuation) * (lightColor * NoL);
}
