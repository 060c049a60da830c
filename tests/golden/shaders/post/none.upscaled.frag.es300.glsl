#version 300 es
#define FACET_POST_UPSCALE 1
precision mediump float;
precision highp int;
uniform mediump sampler2D hdrColor;
layout(location = 0) out vec4 fragColor;
layout(std140) uniform PostUniforms {
    mediump vec4 vignette;
    highp vec4 viewport;
    mediump vec4 bloom;
} post;
// sRGB transfer functions, IEC 61966-2-1:1999 (piecewise: linear toe below 0.0031308).
// fp16: inputs are in [0, 1]; pow of a value in [0.0031308, 1] is well conditioned in mediump
// and the 8-bit output step (1/255) is far above fp16's 2^-11 relative precision.
vec3 srgb_from_linear(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 lo = c * 12.92;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), c));
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
//   none of these                  separate path: texelFetch of the stored HDR texture at
//                                  gl_FragCoord (each API's window origin matches its own
//                                  texture row 0, so no flip is needed).
// All forms but the upscaled one read exactly the pixel being shaded, so the paths give the same
// image.
#if defined(FACET_POST_SUBPASS_INPUT)
#define FACET_POST_HDR() subpassLoad(hdrColor).rgb
#elif defined(FACET_POST_FRAMEBUFFER_FETCH)
#define FACET_POST_HDR() hdrColor.rgb
#elif defined(FACET_POST_UPSCALE)
#define FACET_POST_HDR() texture(hdrColor, gl_FragCoord.xy * post.viewport.xy).rgb
#else
#define FACET_POST_HDR() texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0).rgb
#endif

void main() {
    vec3 hdr = FACET_POST_HDR();
#if defined(FACET_POST_BLOOM)
    // The bloom chain's finest level (half the HDR image's size), bilinear at this pixel's centre.
    vec3 bloom = texture(facet_bloom, gl_FragCoord.xy * post.viewport.xy).rgb;
    hdr = bloom_composite(hdr, bloom, post.bloom);  // redistributes energy: see chunks/bloom.glsl
#endif
#if defined(FACET_POST_ACES)
    vec3 display = tonemap_aces_fitted(hdr);
#elif defined(FACET_POST_NEUTRAL)
    vec3 display = tonemap_khronos_neutral(hdr);
#else
    vec3 display = hdr;  // no tone curve: srgb_from_linear clamps to [0, 1]
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
