#version 310 es
// Test fragment shader for test_textures: a weighted sum of samples from a frame texture
// (binding 0), the environment's cube map slot (binding 2, its +Z face), a material texture (binding 8, with implicit
// and explicit level) and the vertex stage's sample. Twin of kTexturedFragment in
// test_textures.cpp (the GLSL ES 3.00 flavour).
precision highp float;

layout(std140, set = 0, binding = 2) uniform MaterialParams {
    vec4 weights;  // x: texture(materialTexture), y: textureLod(materialTexture, extra.x),
                   // z: texture(facet_dfgLut), w: texture(facet_environment)
    vec4 extra;    // x: level for weights.y, y: weight of the vertex stage's sample
} material;

layout(set = 1, binding = 0) uniform highp sampler2D facet_dfgLut;
layout(set = 1, binding = 2) uniform highp samplerCube facet_environment;
layout(set = 1, binding = 8) uniform highp sampler2D materialTexture;

layout(location = 0) in vec2 vUv;
layout(location = 1) in vec4 vVertexSample;
layout(location = 0) out vec4 fragColor;

void main() {
    fragColor = material.weights.x * texture(materialTexture, vUv) +
                material.weights.y * textureLod(materialTexture, vUv, material.extra.x) +
                material.weights.z * texture(facet_dfgLut, vUv) +
                material.weights.w * texture(facet_environment, vec3(2.0 * vUv - 1.0, 1.0)) +
                material.extra.y * vVertexSample;
}
