// The environment background's vertex stage (runtime/background.h): one triangle covering the
// screen at the far plane, the direction seen through each corner for the fragment stage.
// The mesh holds GL normalized device coordinates (-1, -1), (3, -1), (-1, 3) (decoded like any
// mesh's positions); clip z = w puts every pixel at depth 1 in both APIs (GL's window depth
// (z/w + 1)/2, Vulkan's z/w), where the pass's LEQUAL test against the cleared depth keeps it
// behind everything drawn. Vulkan's framebuffer y points down (vk_convert.h): its clip y is
// negated so a pixel keeps its GL coordinates, from which the direction is computed.
// The direction: a pixel at GL coordinates (x, y) sees along D · (x, y, 1, 1), D the CPU's
// clip-to-direction matrix (runtime/background.cpp). It is linear in (x, y) (for a perspective
// camera the homogeneous point of the far plane minus w times the eye; for an orthographic one a
// constant), and with w = 1 at every corner the rasterizer's interpolation is linear in screen
// space, so the interpolated highp varying is the exact per-pixel direction (up to fp32 rounding)
// at no arithmetic in the fragment stage. It is not normalized: the cube map lookup needs none.
#ifdef FACET_VULKAN
layout(location = 0) out highp vec3 v_direction;
#else
out highp vec3 v_direction;
#endif

void main() {
    highp vec2 ndc = a_position.xy * object.positionScale.xy + object.positionOffset.xy;
    v_direction = (params.clipToDirection * vec4(ndc, 1.0, 1.0)).xyz;
#ifdef FACET_VULKAN
    gl_Position = vec4(ndc.x, -ndc.y, 1.0, 1.0);
#else
    gl_Position = vec4(ndc, 1.0, 1.0);
#endif
}
