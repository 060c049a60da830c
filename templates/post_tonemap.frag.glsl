// Post pass fragment stage: read the HDR colour of this pixel, tone map, encode sRGB, dither, for an
// RGBA8 UNORM target. Each effect is compiled in only when enabled (compiler/post.h PostEffects). Lights were pre-exposed on the CPU, so no exposure multiply happens here.
// Assembled by the compiler's post domain (compiler/src/post.cpp), which defines one way to read
// the pixel:
//   FACET_POST_SUBPASS_INPUT       merged path, Vulkan (and MSL [[color(0)]] via SPIRV-Cross):
//                                  subpassLoad of the input attachment of the same render pass,
//                                  LDR written to colour slot 1;
//   FACET_POST_FRAMEBUFFER_FETCH   merged path, GLES: GL_EXT_shader_framebuffer_fetch, HDR is
//                                  colour output 0 declared inout, LDR is output 1;
//   neither                        separate path: texelFetch of the stored HDR texture at
//                                  gl_FragCoord (each API's window origin matches its own
//                                  texture row 0, so no flip is needed).
// All forms read exactly the pixel being shaded, so the paths give the same image.
#if defined(FACET_POST_SUBPASS_INPUT)
layout(input_attachment_index = 0, set = 0, binding = 0) uniform mediump subpassInput hdrColor;
layout(location = 1) out vec4 fragColor;  // HDR is colour 0 of the pass (Metal: [[color(0)]])
#define FACET_POST_HDR() subpassLoad(hdrColor).rgb
#elif defined(FACET_POST_FRAMEBUFFER_FETCH)
layout(location = 0) inout mediump vec4 hdrColor;
layout(location = 1) out vec4 fragColor;
#define FACET_POST_HDR() hdrColor.rgb
#else
#if defined(FACET_VULKAN)
layout(set = 0, binding = 0) uniform mediump sampler2D hdrColor;
#else
uniform mediump sampler2D hdrColor;
#endif
layout(location = 0) out vec4 fragColor;
#define FACET_POST_HDR() texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0).rgb
#endif

void main() {
    vec3 hdr = FACET_POST_HDR();
#if defined(FACET_POST_ACES)
    vec3 display = tonemap_aces_fitted(hdr);
#elif defined(FACET_POST_NEUTRAL)
    vec3 display = tonemap_khronos_neutral(hdr);
#else
    vec3 display = hdr;  // no tone curve: srgb_from_linear clamps to [0, 1]
#endif
    vec3 encoded = srgb_from_linear(display);
#if defined(FACET_POST_DITHER)
    encoded = dither_triangular_8bit(encoded, gl_FragCoord.xy);  // last, on the value the target quantises
#endif
    fragColor = vec4(encoded, 1.0);
}
