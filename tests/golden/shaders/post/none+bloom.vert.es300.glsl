#version 300 es
#define FACET_POST_BLOOM 1
precision mediump float;
precision highp int;
// Post pass vertex stage: one triangle covering the screen, generated from the vertex index so
// the pass binds no vertex buffer. Corners (-1,-1), (3,-1), (-1,3) clip the rest away.
#ifdef FACET_VULKAN
#define FACET_VERTEX_ID gl_VertexIndex
#else
#define FACET_VERTEX_ID gl_VertexID
#endif

void main() {
    vec2 corner = vec2(float((FACET_VERTEX_ID << 1) & 2), float(FACET_VERTEX_ID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
