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
    // on Mobile Platforms", 2023) instead of the rasteriser's: slopeBias times the depth the
    // surface changes over a texel, in clip depth. The depth is along the view's axis a
    // (frame.lightDirection.xyz, unit, towards the light), so a plane with unit normal n at distance
    // d = |n · v| from the light (v from the vertex to it) changes window depth per texel by
    // |n × a| / d × (the view's texel and depth scale): for the sun's orthographic view (v = a) that
    // is tan θ of the normal to the rays times texelSize / depthRange; for a spot's perspective view
    // (v = frame.lightColor.xyz − position, the light's position, frame.lightColor.w 1) it is
    // |n × a| / d × texelPerMetre · f·n / (f − n), and times w = v · a the same constant at every
    // distance. So the bias is frame.lightDirection.w × |n × a| (v · a) / |n · v|, the constant
    // the shadow pass writes per view (runtime/shadow_pass.cpp; twice it on GL's [-1, 1] clip
    // depth). The normal takes the forward vertex stage's cofactor rows (templates/forward.vert.glsl)
    // unnormalized: the quotient depends on neither its length nor a mirroring transform's sign.
    // Capped at 10 (for the sun, θ = 84.3°): past it the surface's own n · l is below 0.1, so acne
    // there is under a tenth of the light, while an uncapped bias at a silhouette vertex (n across
    // the rays, d → 0) pushes the caster's edge without bound away from the light and opens a gap
    // under it. 1e-30 keeps the quotient finite (a normal fp32 number).
    highp vec3 row0 = a_instanceRow0.xyz, row1 = a_instanceRow1.xyz, row2 = a_instanceRow2.xyz;
    highp vec3 n = a_normal * mat3(cross(row1, row2), cross(row2, row0), cross(row0, row1));
    highp vec3 axis = frame.lightDirection.xyz;
    highp vec3 toLight = mix(axis, frame.lightColor.xyz - worldPosition.xyz, frame.lightColor.w);
    highp float along = dot(n, axis);
    highp float across = sqrt(max(dot(n, n) - along * along, 0.0));
    highp float slope = min(across * max(dot(toLight, axis), 0.0) / max(abs(dot(n, toLight)), 1e-30), 10.0);
    gl_Position.z += frame.lightDirection.w * slope;
#endif
}
