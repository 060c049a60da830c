// The fragment output of every blending mode (the material header's `blending`):
//   opaque       rgb, alpha 1
//   masked       discard where alpha < cutoff, else opaque (alpha-tested foliage, fences); with
//                MSAA, alpha to coverage instead (below)
//   transparent  premultiplied (rgb·α, α): the blend unit computes src + (1 − α)·dst ("over")
//   additive     premultiplied (rgb·α, α): the blend unit adds src to dst
// Premultiplied output lets one blend function serve every alpha, and lets emissive surfaces
// add light while being see-through (Porter & Duff 1984; Filament's transparent mode).
// The colour arrives linear in every tier (with FACET_GAMMA_HACK, the low tier, what was formed on
// encoded colours was squared back by linear_from_shading_space below): the HDR target, blending
// and the post pass (tone map, sRGB encode) all work on linear values.

// With FACET_GAMMA_HACK the diffuse term is the one lit term formed on encoded colours (c_γ = √c);
// it is squared back to linear once, here, and every later term (the ambient specular, each
// light's direct term, the emissive) is added in linear (add_light, shading_ambient.glsl). The
// sum is the one re-encoding after each term, √(c_γ² + x), and squaring once at the end gave —
// (√(√(c + a)² + b))² = c + a + b — without the two square roots per term (a vec3 √ is three SFU pairs on Valhall,
// docs/eval.md's cost model), and like that form it has no cross term: adding encoded terms,
// (c_γ + √x)² = c + x + 2√(cx), brightened every pixel an environment lights (measured: low tier
// 19.0 dB instead of 27.7 dB against reference in test_punctual_lights' scene) and made a
// lobe's faint tail over lit diffuse visible (docs/specular-tiers.md). fp16: the diffuse
// c_γ = diffuseColor_γ · √(E/π) ≤ √65504 = 256 squares to a finite c; an emissive beyond that
// saturates in add_light, as the encoded sum saturated before its √.
vec3 linear_from_shading_space(vec3 color) {
#if defined(FACET_GAMMA_HACK)
    return color * color;
#else
    return color;
#endif
}

// Masked with MSAA (the backend sets frame.cameraPosition.w to 1 and turns alpha to coverage on):
// a discard would keep or drop all the samples of a pixel, so an alpha-tested edge stayed as
// aliased as without MSAA. Instead alpha is sharpened into a ramp one pixel wide centred on the
// cutoff, c = (α − cutoff) / fwidth(α) + 1/2 clamped to [0, 1] (Castaño's "sharpened alpha to
// coverage"), and written as alpha: the hardware keeps about c of the pixel's samples, so the
// edge resolves like a geometric one, and c ≥ 1/2 exactly where α ≥ cutoff (the alpha test's own
// edge). The 1e-4 floor: a constant α (fwidth 0) steps at the cutoff, as the alpha test did; it
// is above binary16's smallest normal (6.1e-5), so mediump keeps it. Only c = 0 is discarded (no
// sample would be written, and a discarded fragment writes no depth either).
vec4 blend_output(vec3 color, float alpha) {
#if defined(FACET_BLENDING_MASKED)
    if (frame.cameraPosition.w > 0.5) {
        float coverage = clamp((alpha - FACET_ALPHA_CUTOFF) / max(fwidth(alpha), 1e-4) + 0.5, 0.0, 1.0);
        if (coverage <= 0.0) discard;
        return vec4(color, coverage);
    }
    if (alpha < FACET_ALPHA_CUTOFF) discard;
    return vec4(color, 1.0);
#elif defined(FACET_BLENDING_TRANSPARENT) || defined(FACET_BLENDING_ADDITIVE)
    float a = clamp(alpha, 0.0, 1.0);
    return vec4(color * a, a);
#else
    return vec4(color, 1.0);
#endif
}
