#version 310 es
// Test vertex shader for test_textures: the ABI's vertex stream and uniform blocks, uv0 passed
// on, and one texture sampled in the vertex stage (set 1, binding 9, at its centre) so that the
// vertex stage's access to the texture set is exercised. Twin of kTexturedVertex in
// test_textures.cpp (the GLSL ES 3.00 flavour).
precision highp float;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv0;
// The instance's 4×3 transform (shader_abi.h InstanceTransform), one row each.
layout(location = 6) in vec4 instanceRow0;
layout(location = 7) in vec4 instanceRow1;
layout(location = 8) in vec4 instanceRow2;

layout(std140, set = 0, binding = 0) uniform FrameUniforms {
    mat4 viewProjection;
    vec4 cameraPosition;
    vec4 lightDirection;
    vec4 lightColor;
    vec4 ambient;
} frame;

layout(std140, set = 0, binding = 1) uniform ObjectUniforms {
    vec4 positionScale;  // the decode of the mesh's packed streams (shader_abi.h)
    vec4 positionOffset;
    vec4 uv0ScaleOffset;
    vec4 uv1ScaleOffset;
} object;

layout(set = 1, binding = 9) uniform highp sampler2D vertexTexture;

layout(location = 0) out vec2 vUv;
layout(location = 1) out vec4 vVertexSample;

void main() {
    vUv = uv0 * object.uv0ScaleOffset.xy + object.uv0ScaleOffset.zw + vec2(0.0 * normal.x);
    vVertexSample = textureLod(vertexTexture, vec2(0.5), 0.0);
    vec4 p = vec4(position * object.positionScale.xyz + object.positionOffset.xyz, 1.0);
    gl_Position = frame.viewProjection * vec4(dot(instanceRow0, p), dot(instanceRow1, p), dot(instanceRow2, p), 1.0);
}
