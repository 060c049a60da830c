#version 300 es
#define FACET_POST_UPSCALE 1
#define FACET_POST_ACES 1
#define FACET_POST_DITHER 1
#define FACET_POST_COLOR_GRADING 1
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
// ACES filmic tone curve, fitted: f(x) = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14)
// Source: K. Narkowicz, "ACES Filmic Tone Mapping Curve" (2015), a rational fit of the ACES
// RRT+ODT; Filament offers it among its mobile tone mappers.
// fp16: the input is pre-exposed (≈1 at middle grey × 5), so x² stays far below 65504 for any
// x < 160; the clamp keeps a stray very bright value from overflowing the product in mediump.
// 160 = sqrt(65504 / 2.51), rounded down.
vec3 tonemap_aces_fitted(vec3 x) {
    x = clamp(x, 0.0, 160.0);
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
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
// Dithering before 8-bit quantisation: noise of triangular distribution over (−1, 1) output steps
// added to the encoded colour, so a gradient flatter than one 8-bit step per pixel is drawn as a
// mix of its two neighbouring levels in proportion instead of as bands, and the error it leaves
// is independent of the signal (a triangular PDF of 2 LSB width makes the error's mean and
// variance independent of the value: Lipshitz, Wannamaker & Vanderkooy, "Quantization and
// Dither: A Theoretical Survey", JAES 1992).
// Noise: interleaved gradient noise, fract(52.9829189 · fract(dot(p, (0.06711056, 0.00583715))))
// (J. Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH
// 2014): uniform over a pixel's neighbours, no texture fetch. The second sample reads the pattern
// transposed (and shifted), which is uncorrelated with the first, so their sum minus 1 is
// triangular over (−1, 1); a sample at a mere offset is not (its sum stays within ±0.55).
// Precision: highp. Pixel coordinates reach 4096 and the products need 2^-12 of fraction after
// it, beyond fp16's 11 significant bits; on mediump the noise would collapse into a few values.
highp float interleaved_gradient_noise(highp vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// `encoded` in [0, 1], to be stored in an 8-bit UNORM target.
vec3 dither_triangular_8bit(vec3 encoded, highp vec2 pixel) {
    highp float n = interleaved_gradient_noise(pixel) + interleaved_gradient_noise(pixel.yx + vec2(17.0, 31.0)) - 1.0;
    return encoded + vec3(n / 255.0);
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
