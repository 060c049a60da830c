#version 300 es
precision mediump float;
precision highp int;
uniform mediump sampler2D toneMapped;
layout(location = 0) out vec4 fragColor;
// FXAA, the console form of T. Lottes's FXAA 3.11 (NVIDIA, "FXAA 3.11", Fxaa3_11.h, 2011,
// FXAA_PC_CONSOLE): a post-process anti-aliasing on the tone-mapped, sRGB-encoded LDR image.
// Chosen over the 3.11 quality form because it is a fixed 9 bilinear taps with no end-of-edge
// search (the quality form walks up to 12 step pairs per pixel, divergent branches a mobile
// GPU runs at the worst lane's cost); the quality form resolves long near-horizontal edges
// better.
//   luma L = Rec.601 weights of the encoded colour (perceptual: FXAA's thresholds assume it);
//   corners: four bilinear taps at ±0.5 texel (each averages a 2×2 block) give lumaNw..lumaSe;
//   skip:  max(L) − min(L) over the corners and the centre < max(kThresholdMin, kThreshold · max)
//          leaves the pixel exactly as it was (texelFetch of the centre);
//   dir:   (Sw − Ne + Se − Nw, Sw − Ne − (Se − Nw)), the gradient across the edge turned along it,
//          normalised; two taps at ±0.5 texel along it (A), two more at ±2 texels times
//          dir / (8 · min|dir|) clamped to ±2 (B = A/4 + outer/4: an edge nearly along an axis
//          reaches 4 texels out); B unless its luma leaves [min, max] of the
//          corners (then it crossed another edge: the two-tap A/2).
// Constants: Lottes's defaults (edge threshold 0.125, minimum 0.05, sharpness 8); Ne gets
// +1/384 so a flat 2×2 block cannot give dir = 0 (normalize(0) is undefined).
// Precision: lumas and colours live in [0, 1], where fp16's spacing is at most 2^-11 ≈ 0.0005:
// 8-bit input steps (1/255 ≈ 0.0039) stay distinct, and the thresholds (≥ 0.05) are 100 such
// spacings wide, so mediump flips a skip decision only for a contrast within 0.0005 of the
// threshold. Texture coordinates are highp: half a texel of a 4096-wide image is 2^-13, finer than
// fp16's spacing near 1. The early-out returns the fetched texel unchanged, and an 8-bit value
// survives fp16 (k / 255 is within 2^-12 of relative error), so pixels off edges are byte-identical.
const float kFxaaEdgeThreshold = 0.125;
const float kFxaaEdgeThresholdMin = 0.05;
const float kFxaaEdgeSharpness = 8.0;

float fxaa_luma(vec3 encoded) { return dot(encoded, vec3(0.299, 0.587, 0.114)); }

// image: the encoded LDR image, bilinear, clamped to edge; pixel: its integer texel; uv: the
// texel's centre in [0, 1]; texel: 1 / size.
vec3 fxaa_console(mediump sampler2D image, ivec2 pixel, highp vec2 uv, highp vec2 texel) {
    vec3 centre = texelFetch(image, pixel, 0).rgb;
    float lumaM = fxaa_luma(centre);
    highp vec2 half_texel = 0.5 * texel;
    float lumaNw = fxaa_luma(texture(image, uv + vec2(-half_texel.x, -half_texel.y)).rgb);
    float lumaSw = fxaa_luma(texture(image, uv + vec2(-half_texel.x, half_texel.y)).rgb);
    float lumaNe = fxaa_luma(texture(image, uv + vec2(half_texel.x, -half_texel.y)).rgb) + 1.0 / 384.0;
    float lumaSe = fxaa_luma(texture(image, uv + vec2(half_texel.x, half_texel.y)).rgb);
    float lumaMax = max(max(lumaNw, lumaSw), max(lumaNe, lumaSe));
    float lumaMin = min(min(lumaNw, lumaSw), min(lumaNe, lumaSe));
    float contrast = max(lumaMax, lumaM) - min(lumaMin, lumaM);
    if (contrast < max(kFxaaEdgeThresholdMin, lumaMax * kFxaaEdgeThreshold)) return centre;

    float swMinusNe = lumaSw - lumaNe;
    float seMinusNw = lumaSe - lumaNw;
    vec2 dir1 = normalize(vec2(swMinusNe + seMinusNw, swMinusNe - seMinusNw));
    vec3 n1 = texture(image, uv - dir1 * half_texel).rgb;
    vec3 p1 = texture(image, uv + dir1 * half_texel).rgb;
    float dirAbsMinTimesC = min(abs(dir1.x), abs(dir1.y)) * kFxaaEdgeSharpness;
    vec2 dir2 = clamp(dir1 / dirAbsMinTimesC, -2.0, 2.0);
    vec3 n2 = texture(image, uv - dir2 * 2.0 * texel).rgb;
    vec3 p2 = texture(image, uv + dir2 * 2.0 * texel).rgb;
    vec3 twoTap = n1 + p1;
    vec3 fourTap = (n2 + p2) * 0.25 + twoTap * 0.25;
    float lumaB = fxaa_luma(fourTap);
    return (lumaB < lumaMin || lumaB > lumaMax) ? twoTap * 0.5 : fourTap;
}
// FXAA pass fragment stage: the tone-mapped LDR image of the post pass, sampled (bilinear,
// clamped) because FXAA reads neighbouring pixels, anti-aliased by chunks/fxaa.glsl into the
// RGBA8 output. Assembled by the compiler's post domain (compiler/src/post.cpp), which declares
// `toneMapped` and `fragColor` from shader_abi.h. Each API's window origin matches its own
// texture row 0 (as in post_tonemap.frag.glsl), so gl_FragCoord addresses the texel it covers.
void main() {
    highp vec2 texel = 1.0 / vec2(textureSize(toneMapped, 0));
    highp vec2 uv = gl_FragCoord.xy * texel;
    fragColor = vec4(fxaa_console(toneMapped, ivec2(gl_FragCoord.xy), uv, texel), 1.0);
}
