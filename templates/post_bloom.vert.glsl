// Bloom passes' vertex stage: the post pass's full-screen triangle with its texture coordinate,
// uv = the corner in [0, 2]: at a pixel's centre it is (x + 0.5, y + 0.5) / size of the target
// being drawn, which the fragment stage cannot know otherwise (the source image's size is not
// twice the target's for an odd size). Clip y = −1 is framebuffer row 0 in Vulkan and window row 0
// in GL, which is texture row 0 in both, so uv addresses the same texel in either API.
#ifdef FACET_VULKAN
#define FACET_VERTEX_ID gl_VertexIndex
layout(location = 0) out highp vec2 bloomUv;
#else
#define FACET_VERTEX_ID gl_VertexID
out highp vec2 bloomUv;
#endif

void main() {
    vec2 corner = vec2(float((FACET_VERTEX_ID << 1) & 2), float(FACET_VERTEX_ID & 2));
    bloomUv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
