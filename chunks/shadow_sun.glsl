// The sun's visibility from its cascaded shadow atlas (docs/shadows.md), fragment stage of
// receiver variants (shader_abi.h ShadowUniforms, sampler facet_shadowAtlas). The vertex stage
// sends v_shadowPosition: xyz the normal-offset position in the sun's frame (metres), w its view
// depth; both are affine in the position, so their interpolation is exact.
//
// Normal offset (Holbein, "Normal Offset Shadows", 2011): the vertex stage moves the position along
// its normal by normalBias texels of its cascade (cascadeScale.w, metres), so a surface tilted
// towards grazing compares against its own depth one texel towards the light, not the texel that
// straddles it (acne); the raster's slope-scaled depth bias covers the rest (docs/shadows.md,
// "Bias").
// atlas (u, v, depth) = light · cascadeScale.xyz + cascadeOffset.xyz of the pixel's cascade
// (chunks/shadow_cascade.glsl), and the shadow fades to full light over the last part of the
// shadow distance: visibility = mix(v, 1, saturate(d · fade.x + fade.y)).
// Filter and precision: chunks/shadow_filter.glsl, which the spot's receiver shares.
#include "shadow_cascade.glsl"
#include "shadow_filter.glsl"

// The sun's visibility at this pixel, 0 (in shadow) to 1 (lit).
float shadow_sun_visibility() {
    highp vec4 light = v_shadowPosition;
    highp vec4 scale =
        shadow_select(light.w, shadow.cascadeScale[0], shadow.cascadeScale[1], shadow.cascadeScale[2], shadow.cascadeScale[3]);
    highp vec4 offset = shadow_select(light.w, shadow.cascadeOffset[0], shadow.cascadeOffset[1], shadow.cascadeOffset[2],
                                      shadow.cascadeOffset[3]);
    float visibility = shadow_filter(light.xyz * scale.xyz + offset.xyz);
    return mix(visibility, 1.0, clamp(light.w * shadow.fadeAtlas.x + shadow.fadeAtlas.y, 0.0, 1.0));
}
