#version 310 es
// Test fragment shader for test_vulkan_backend: outputs the colour stored in MaterialParams.
precision highp float;

layout(std140, set = 0, binding = 2) uniform MaterialParams {
    vec4 baseColor;
} material;

layout(location = 0) in vec2 vUv;
layout(location = 0) out vec4 fragColor;

void main() {
    fragColor = material.baseColor + vec4(0.0 * vUv.x);
}
