#version 300 es
precision mediump float;
precision highp int;
layout(std140) uniform MaterialParams {
    highp mat4 clipToDirection;
    highp vec4 lodIntensity;
} params;
uniform mediump samplerCube facet_environment;
layout(location = 0) out vec4 fragColor;
// The environment background's fragment stage: the prefiltered environment's radiance seen along
// the pixel's direction, at the chosen level, times the chosen factor:
//   L = textureLod(facet_environment, d, lod) · intensity
// The environment is pre-exposed on the CPU like every light (docs/lighting-units.md), so L is
// what the forward pass's lit surfaces are lit by, and the post pass tone maps both alike.
// Precision: the direction is highp (interpolated, unnormalized; environment_cube.glsl has the
// lookup's bound); radiance is mediump, pre-exposed to O(1); intensity is at most 16 (scene.cpp),
// so L stays far from binary16's 65504 for any environment the forward pass shades finitely.
// Level lod is explicit: no derivative is taken (the face changes under a pixel at cube edges).
#ifdef FACET_VULKAN
layout(location = 0) in highp vec3 v_direction;
#else
in highp vec3 v_direction;
#endif

void main() {
    fragColor = vec4(textureLod(facet_environment, v_direction, params.lodIntensity.x).rgb * params.lodIntensity.y, 1.0);
}
