#version 300 es
#define FACET_POST_NEUTRAL 1
#define FACET_POST_COLOR_GRADING 1
#define FACET_POST_VIGNETTE 1
precision mediump float;
precision highp int;
uniform mediump sampler2D hdrColor;
layout(location = 0) out vec4 fragColor;
#define FACET_COLOR_LUT_SIZE 32
uniform mediump sampler3D facet_colorLut;
layout(std140) uniform PostUniforms {
    mediump vec4 vignette;
    highp vec4 viewport;
    mediump vec4 bloom;
} post;
// Neutral tone curve for display: Khronos PBR Neutral (E. Lalish, Khronos 3D Formats WG, 2024,
// "Khronos PBR Neutral Tone Mapper"). Unlike a filmic curve it keeps hue and saturation of
// everything below the compression start: a base colour lit at 1.0 shows as authored, which is
// what product and e-commerce viewers (the mobile case the spec was written for) need.
//   toe:   x = min(r, g, b);  offset = x < 0.08 ? x − 6.25 x² : 0.04;  c −= offset
//          (a smooth black level: 6.25 = 1 / (4 · 0.04), so offset and its slope are continuous at 0.08)
//   knee:  peak = max(c); below s = 0.8 − 0.04 the colour is unchanged; above it the peak is
//          compressed to p' = 1 − d² / (peak + d − s), d = 1 − s (a hyperbola tangent to y = x at s,
//          approaching 1), every channel scaled by p' / peak;
//   fade:  mixed towards white by g = 1 − 1 / (0.15 · (peak − p') + 1), so very bright colours desaturate.
// fp16: the input is pre-exposed and clamped to 1024 first. At 1024, p' = 1 − 0.0576 / 1023.2 and
// g > 0.99, white to 8 bits, so a brighter input could not change the output; the clamp keeps
// peak + d − s and 0.15 · (peak − p') far inside mediump. x² only runs below 0.08.
vec3 tonemap_khronos_neutral(vec3 c) {
    const float kStart = 0.76;          // 0.8 − 0.04
    const float kKnee = 1.0 - kStart;   // d
    const float kDesaturation = 0.15;
    c = clamp(c, 0.0, 1024.0);
    float low = min(c.r, min(c.g, c.b));
    float offset = low < 0.08 ? low - 6.25 * low * low : 0.04;
    c -= offset;
    float peak = max(c.r, max(c.g, c.b));
    if (peak < kStart) return c;
    float compressed = 1.0 - kKnee * kKnee / (peak + kKnee - kStart);
    c *= compressed / peak;
    float toWhite = 1.0 - 1.0 / (kDesaturation * (peak - compressed) + 1.0);
    return mix(c, vec3(compressed), toWhite);
}
// sRGB transfer functions, IEC 61966-2-1:1999 (piecewise: linear toe below 0.0031308).
// fp16: inputs are in [0, 1]; pow of a value in [0.0031308, 1] is well conditioned in mediump
// and the 8-bit output step (1/255) is far above fp16's 2^-11 relative precision.
vec3 srgb_from_linear(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 lo = c * 12.92;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), c));
}
// Colour grading through a 3D lookup table of N³ texels (N = FACET_COLOR_LUT_SIZE, printed from
// shader_abi.h kColorLutSize), built on the CPU from the scene's settings (white balance,
// contrast, saturation, lift/gamma/gain) or loaded from an Adobe/Resolve .cube file
// (runtime/color_grading.h); HypeHype's mobile post stack grades the same way, one LUT built on
// the CPU whenever a slider moves (Aaltonen, "Transitioning HypeHype to Physically Based
// Rendering", SIGGRAPH 2024).
// Where: after the tone curve and the sRGB encoding, on display-referred values in [0, 1]. A
// lattice needs a bounded domain, which HDR is not; and the encoded values spread the lattice
// evenly in perceived lightness (on linear input half of the 32 points would go to the
// brightest stop and the shadows would get four), which is also how .cube files for SDR
// displays are authored (sRGB/Rec.709-encoded in and out).
// Texture: a sampler3D (core in GLES 3.0 and Vulkan), so the lookup is one hardware-trilinear
// fetch; a 2D strip of N slices would need two bilinear fetches and a blend between slices.
// Lookup: lattice point i lies at the texel centre (i + 0.5) / N,
// so [0, 1] maps onto [0.5/N, 1 − 0.5/N]: coord = c·(N − 1)/N + 0.5/N (J. Selan, "Using Lookup
// Tables to Accelerate Color Transformations", GPU Gems 2, ch. 24, 2005).
// fp16: the coordinate's error (2^-11 near 1 in mediump) is 1/64 of a texel at N = 32; texels are
// RGBA16F (2^-11 relative, 1/8 of an 8-bit step). Filtering weights have the GPU's fixed-point
// subTexelPrecisionBits (8 on lavapipe, queried; Vulkan guarantees 4): with 8, a linear LUT is
// interpolated to within 1/256 of a lattice step, 1/8000 of the range; with 4, 1/500 (half a step).
vec3 grade_color_lut(mediump sampler3D lut, vec3 encoded) {
    const float n = float(FACET_COLOR_LUT_SIZE);
    vec3 coord = clamp(encoded, 0.0, 1.0) * ((n - 1.0) / n) + 0.5 / n;
    return texture(lut, coord).rgb;
}
// Vignette: the frame darkens towards its corners, applied "on top at the end of the shader" (on
// the graded, encoded value, before dithering) as in HypeHype's single-pass mobile post stack
// (Aaltonen, "Transitioning HypeHype to Physically Based Rendering", SIGGRAPH 2024).
//   p = (2 · pixel / size − 1) · (mix(1, width / height, roundness), 1): the centre is 0, the top
//       and bottom edges are at |p.y| = 1; roundness 1 makes the falloff a circle on screen,
//       0 an ellipse fitting the frame (the side edges at |p.x| = 1 too);
//   factor = 1 − intensity · smoothstep(radius, radius + smoothness, |p|).
// Multiplying the encoded value scales perceived lightness (sRGB encoding is close to it), so
// intensity 0.5 reads as "half as light" in the corners whatever their colour.
// Precision: the pixel and the reciprocal size are highp (pixel coordinates reach 4096, beyond
// fp16's integers); |p| < 3 and the factor in [0, 1] are fine in mediump.
// params: x intensity, y radius, z smoothness, w roundness; viewport: x 1/width, y 1/height, z width/height.
float vignette_factor(highp vec2 pixel, highp vec4 viewport, vec4 params) {
    highp vec2 p = pixel * viewport.xy * 2.0 - 1.0;
    p.x *= mix(1.0, viewport.z, params.w);
    float d = length(vec2(p));
    return 1.0 - params.x * smoothstep(params.y, params.y + max(params.z, 1e-3), d);
}
// Post pass fragment stage: read the HDR colour of this pixel, add bloom, tone map, encode sRGB, grade
// through a 3D LUT, vignette, dither, for an RGBA8 UNORM target. Each effect is compiled in only
// when enabled (compiler/post.h PostEffects).
// Lights were pre-exposed on the CPU, so no exposure multiply happens here.
// Assembled by the compiler's post domain (compiler/src/post.cpp), which declares `hdrColor` and
// `fragColor` from shader_abi.h's attachment constants and defines one way to read the pixel:
//   FACET_POST_SUBPASS_INPUT       merged path, Vulkan (and MSL [[color(0)]] via SPIRV-Cross):
//                                  subpassLoad of the input attachment of the same render pass,
//                                  LDR written to colour slot 1;
//   FACET_POST_FRAMEBUFFER_FETCH   merged path, GLES: GL_EXT_shader_framebuffer_fetch, HDR is
//                                  colour output 0 declared inout, LDR is output 1;
//   FACET_POST_UPSCALE             render scale < 1 (separate path): the HDR texture is
//                                  smaller than the output; a bilinear sample at the output
//                                  pixel's centre, uv = gl_FragCoord.xy / output size (from
//                                  post.viewport), in highp: a mediump uv is 2^-11 relative, a
//                                  whole texel at 2048 texels;
//   FACET_POST_SUBPASS_SAMPLES     merged path under MSAA with multisampled attachments (Vulkan,
//                                  portable form): each of the facet_postSamples samples of a
//                                  subpassInputMS, tone-mapped, then averaged (below);
//   FACET_POST_SAMPLED_SAMPLES     the same order from a sampler2DMS (GLSL ES 3.10 text: what
//                                  Mesa's mobile compilers count for the per-sample form);
//   none of these                  separate path: texelFetch of the stored HDR texture at
//                                  gl_FragCoord (each API's window origin matches its own
//                                  texture row 0, so no flip is needed).
// All forms but the upscaled one read exactly the pixel being shaded, so the paths give the same
// image (the per-sample forms: the same samples, in the other order).
#if defined(FACET_POST_SUBPASS_SAMPLES)
#define FACET_POST_SAMPLE(i) subpassLoad(hdrColor, i).rgb
#elif defined(FACET_POST_SAMPLED_SAMPLES)
#define FACET_POST_SAMPLE(i) texelFetch(hdrColor, ivec2(gl_FragCoord.xy), i).rgb
#elif defined(FACET_POST_SUBPASS_INPUT)
#define FACET_POST_HDR() subpassLoad(hdrColor).rgb
#elif defined(FACET_POST_FRAMEBUFFER_FETCH)
#define FACET_POST_HDR() hdrColor.rgb
#elif defined(FACET_POST_UPSCALE)
#define FACET_POST_HDR() texture(hdrColor, gl_FragCoord.xy * post.viewport.xy).rgb
#else
#define FACET_POST_HDR() texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0).rgb
#endif

// Bloom and the tone curve: pre-exposed HDR to display-referred linear values.
vec3 post_display(vec3 hdr) {
#if defined(FACET_POST_BLOOM)
    // The bloom chain's finest level (half the HDR image's size), bilinear at this pixel's centre.
    vec3 bloom = texture(facet_bloom, gl_FragCoord.xy * post.viewport.xy).rgb;
    hdr = bloom_composite(hdr, bloom, post.bloom);  // redistributes energy: see chunks/bloom.glsl
#endif
#if defined(FACET_POST_ACES)
    return tonemap_aces_fitted(hdr);
#elif defined(FACET_POST_NEUTRAL)
    return tonemap_khronos_neutral(hdr);
#else
    // No tone curve: the display clips each sample, so a sample averaged with others is clipped
    // first (with one sample srgb_from_linear's own clamp gives the same).
    return clamp(hdr, 0.0, 1.0);
#endif
}

void main() {
#if defined(FACET_POST_SUBPASS_SAMPLES) || defined(FACET_POST_SAMPLED_SAMPLES)
    // The display shows each sample's tone-mapped light, so the samples are averaged after the
    // tone curve, in display-referred linear light (before sRGB encoding), as a box filter of the
    // displayed image would: a highlight of HDR 50 on one sample of four adds a quarter of white,
    // where averaged first (12.5) it would tone map to white. Each term is weighted as it is added,
    // so the mediump sum stays in [0, 1] (fp16 spacing at most 2^-11 there, under 0.1 of an 8-bit
    // step after encoding).
    vec3 display = vec3(0.0);
    float weight = 1.0 / float(facet_postSamples);
    for (int i = 0; i < facet_postSamples; ++i) display += post_display(FACET_POST_SAMPLE(i)) * weight;
#else
    vec3 display = post_display(FACET_POST_HDR());
#endif
    vec3 encoded = srgb_from_linear(display);
#if defined(FACET_POST_COLOR_GRADING)
    encoded = grade_color_lut(facet_colorLut, encoded);  // display-referred, encoded: see the chunk
#endif
#if defined(FACET_POST_VIGNETTE)
    encoded *= vignette_factor(gl_FragCoord.xy, post.viewport, post.vignette);
#endif
#if defined(FACET_POST_DITHER)
    encoded = dither_triangular_8bit(encoded, gl_FragCoord.xy);  // last, on the value the target quantises
#endif
    fragColor = vec4(encoded, 1.0);
}
