// The fragment output of every blending mode (the material header's `blending`):
//   opaque       rgb, alpha 1
//   masked       discard where alpha < cutoff, else opaque (alpha-tested foliage, fences)
//   transparent  premultiplied (rgb·α, α): the blend unit computes src + (1 − α)·dst ("over")
//   additive     premultiplied (rgb·α, α): the blend unit adds src to dst
// Premultiplied output lets one blend function serve every alpha, and lets emissive surfaces
// add light while being see-through (Porter & Duff 1984; Filament's transparent mode).
// With FACET_GAMMA_HACK (low tier) the colour arrives gamma-encoded with γ = 2 and is squared back
// to linear first: the HDR target, blending and the post pass (tone map, sRGB encode) all work on
// linear values, for every tier alike. One multiply per pixel (see shading_standard.glsl).
vec4 blend_output(vec3 color, float alpha) {
#if defined(FACET_GAMMA_HACK)
    color *= color;
#endif
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
