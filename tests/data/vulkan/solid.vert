#version 310 es
// Test vertex shader for test_vulkan_backend: the ABI's vertex stream and uniform blocks
// (runtime/include/facet/abi/shader_abi.h), position transformed by viewProjection and the instance transform.
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

layout(location = 0) out vec2 vUv;

void main() {
    // normal is consumed (with weight 0) so every attribute of the ABI stream is read.
    vUv = uv0 * object.uv0ScaleOffset.xy + object.uv0ScaleOffset.zw + vec2(0.0 * normal.x);
    vec4 p = vec4(position * object.positionScale.xyz + object.positionOffset.xyz, 1.0);
    gl_Position = frame.viewProjection * vec4(dot(instanceRow0, p), dot(instanceRow1, p), dot(instanceRow2, p), 1.0);
}
