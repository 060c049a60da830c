// The per-tier filter of a shadow receiver's depth-compare lookup in the shadow atlas
// (docs/shadows.md, "Filters per tier"), shared by the sun's receiver (chunks/shadow_sun.glsl) and
// the spot light's (chunks/shadow_spot.glsl): coord is (atlas u, atlas v, compare depth).
// Filters: one hardware compare tap (mid, low), which the texture unit filters bilinearly over 2×2
// texels where the device filters depth (2×2 PCF; one texel where it does not); or
// (FACET_SHADOW_FILTER_TENT: high, reference) a 3×3 tent, the bilinear-weighted PCF of Castaño
// ("Shadow Mapping Summary – Part 1", 2013): 4 such taps whose offsets and weights make the
// bilinear footprints sum to the tent. Per axis, with s the position's fraction past the texel
// corner base (s in [0, 1)): w0 = 3 − 2s, w1 = 1 + 2s, o0 = (2 − s) / w0 − 1, o1 = s / w1 + 1,
// taps at base − 0.5 + o texels, result = Σ w_u · w_v · tap / 16 (the weights sum to 16).
// Precision: everything that addresses the atlas is highp: an atlas coordinate needs steps of
// 1/8192 (fp16 has 1/2048 near 1) and the compare depth those of a D16 texel (1/65536); the
// visibility itself, in [0, 1], drops to the tier's precision (matc lint flags a mediump shadow
// coordinate).
#if defined(FACET_SHADOW_FILTER_TENT)
float shadow_filter(highp vec3 coord) {
    highp vec2 texel = coord.xy * shadow.fadeAtlas.z;
    highp vec2 base = floor(texel + 0.5);
    highp vec2 s = texel + 0.5 - base;
    highp vec2 w0 = 3.0 - 2.0 * s;
    highp vec2 w1 = 1.0 + 2.0 * s;
    highp vec2 o0 = (2.0 - s) / w0 - 1.0;
    highp vec2 o1 = s / w1 + 1.0;
    highp vec2 origin = base - 0.5;
    highp float inv = shadow.fadeAtlas.w;
    float sum = w0.x * w0.y * texture(facet_shadowAtlas, vec3((origin + vec2(o0.x, o0.y)) * inv, coord.z));
    sum += w1.x * w0.y * texture(facet_shadowAtlas, vec3((origin + vec2(o1.x, o0.y)) * inv, coord.z));
    sum += w0.x * w1.y * texture(facet_shadowAtlas, vec3((origin + vec2(o0.x, o1.y)) * inv, coord.z));
    sum += w1.x * w1.y * texture(facet_shadowAtlas, vec3((origin + vec2(o1.x, o1.y)) * inv, coord.z));
    return sum * (1.0 / 16.0);
}
#else
float shadow_filter(highp vec3 coord) { return texture(facet_shadowAtlas, coord); }
#endif
