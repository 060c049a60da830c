// Shadow pass, vertex stage: the depth-only program of a material that casts (docs/shadows.md).
// The position goes through the forward vertex stage's own decode and instance transform
// (chunks/object_to_world.glsl), so the atlas's depths and the receivers' positions agree to the
// bit; frame.viewProjection is the cascade's (the shadow pass binds one frame block per cascade).
// A masked material also sends what its alpha reads (templates/depth.frag.glsl), nothing else.
void main() {
#include "object_to_world.glsl"
#if defined(FACET_VARYING_WORLD_POSITION)
    v_worldPosition = worldPosition.xyz;
#endif
#include "uv_color_varyings.glsl"
    gl_Position = frame.viewProjection * worldPosition;
#if defined(FACET_VERTEX_SLOPE_BIAS)
    // The slope-scaled bias in the vertex stage (Guo and Li, "Practical High-Performance Rendering
    // on Mobile Platforms", 2023) instead of the rasteriser's: a surface at angle θ between its
    // normal and the direction to the light changes depth by tan θ texels' width per texel, so the
    // bias is frame.lightDirection.w × tan θ in clip depth, the constant the shadow pass writes per
    // view: slopeBias × (a texel's width along the rays in window depth) × w, twice that on GL's
    // [-1, 1] clip depth (runtime/shadow_pass.h). The light is frame.lightDirection.xyz, a direction
    // towards the sun (frame.lightColor.w 0) or a spot's position (frame.lightColor.w 1).
    // The normal takes the forward vertex stage's cofactor rows (templates/forward.vert.glsl),
    // unnormalized: tan θ = |n × l| / |n · l| does not depend on either length, nor on a mirroring
    // transform's sign. tan θ is capped at 10 (θ = 84.3°): past it the surface's own n · l is below
    // 0.1, so acne there is under a tenth of the light, while an uncapped bias at a silhouette
    // vertex (n across the rays, tan θ → ∞) pushes the caster's edge without bound away from the
    // light and opens a gap under it. 1e-30 keeps the quotient finite (a normal fp32 number).
    highp vec3 row0 = a_instanceRow0.xyz, row1 = a_instanceRow1.xyz, row2 = a_instanceRow2.xyz;
    highp vec3 n = a_normal * mat3(cross(row1, row2), cross(row2, row0), cross(row0, row1));
    highp vec3 toLight = frame.lightDirection.xyz - worldPosition.xyz * frame.lightColor.w;
    highp float c = abs(dot(n, toLight));
    highp float tanTheta = min(sqrt(max(dot(n, n) * dot(toLight, toLight) - c * c, 0.0)) / max(c, 1e-30), 10.0);
    gl_Position.z += frame.lightDirection.w * tanTheta;
#endif
}
