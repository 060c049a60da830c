// A casting spot light's visibility from its perspective view in the shadow atlas (docs/shadows.md,
// "Spot shadows"), fragment stage of `.sp1` receivers (shader_abi.h ShadowUniforms, sampler
// facet_shadowAtlas); the light is light slot 0. The vertex stage sends v_spotShadowPosition =
// spotAtlasFromWorld · (p + n · offset) = (u·w, v·w, depth·w, w), w the distance along the light's
// axis: affine in the position, so interpolated exactly, and divided here, per pixel (the divide is
// not affine). Normal offset (Holbein, "Normal Offset Shadows", 2011): normalBias texels of the
// view at the receiver's distance (templates/forward.vert.glsl).
// Precision: highp up to the compare (chunks/shadow_filter.glsl). w ≤ 0 lies behind the light,
// where its cone factor is 0: the divide is kept finite there (max), so that 0 × visibility stays 0
// rather than becoming NaN at w = 0.
#include "shadow_filter.glsl"

// The spot's visibility at this pixel, 0 (in shadow) to 1 (lit).
float shadow_spot_visibility() {
    highp vec4 light = v_spotShadowPosition;
    return shadow_filter(light.xyz / max(light.w, 1e-6));
}
