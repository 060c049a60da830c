// Post pass fragment stage (separate-pass form): read the HDR colour of this pixel, tone map,
// encode sRGB for an RGBA8 UNORM target. Lights were pre-exposed on the CPU, so no exposure
// multiply happens here. texelFetch at gl_FragCoord reads the same pixel in both APIs (each
// API's window origin matches its own texture row 0), so no UV flip is needed.
#ifdef FACET_VULKAN
layout(set = 0, binding = 0) uniform mediump sampler2D hdrColor;
#else
uniform mediump sampler2D hdrColor;
#endif

layout(location = 0) out vec4 fragColor;

void main() {
    vec3 hdr = texelFetch(hdrColor, ivec2(gl_FragCoord.xy), 0).rgb;
    fragColor = vec4(srgb_from_linear(tonemap_aces_fitted(hdr)), 1.0);
}
