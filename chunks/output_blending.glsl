// The fragment output of every blending mode (the material header's `blending`):
//   opaque       rgb, alpha 1
//   masked       discard where alpha < cutoff, else opaque (alpha-tested foliage, fences)
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

vec4 blend_output(vec3 color, float alpha) {
#if defined(FACET_BLENDING_MASKED)
    if (alpha < FACET_ALPHA_CUTOFF) discard;
    return vec4(color, 1.0);
#elif defined(FACET_BLENDING_TRANSPARENT) || defined(FACET_BLENDING_ADDITIVE)
    float a = clamp(alpha, 0.0, 1.0);
    return vec4(color * a, a);
#else
    return vec4(color, 1.0);
#endif
}
