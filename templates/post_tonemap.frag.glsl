// Post pass fragment stage: read the HDR colour of this pixel, tone map,
// encode sRGB for an RGBA8 UNORM target. Lights were pre-exposed on the CPU, so no exposure
// multiply happens here. texelFetch at gl_FragCoord reads the same pixel in both APIs (each
// API's window origin matches its own texture row 0), so no UV flip is needed.
// Two ways to read that pixel: FACET_POST_SUBPASS_INPUT (merged path, Vulkan) reads it from the
// input attachment of the same render pass, so HDR never leaves tile memory; otherwise (separate
// path) texelFetch reads the stored HDR texture.
#if defined(FACET_POST_SUBPASS_INPUT)
layout(input_attachment_index = 0, set = 0, binding = 0) uniform mediump subpassInput hdrColor;
#elif defined(FACET_VULKAN)
layout(set = 0, binding = 0) uniform mediump sampler2D hdrColor;
#else
uniform mediump sampler2D hdrColor;
#endif

layout(location = 0) out vec4 fragColor;

void main() {
#if defined(FACET_POST_SUBPASS_INPUT)
    vec3 hdr = subpassLoad(hdrColor).rgb;
#else
    vec3 hdr = texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0).rgb;
#endif
    fragColor = vec4(srgb_from_linear(tonemap_aces_fitted(hdr)), 1.0);
}
