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
}
