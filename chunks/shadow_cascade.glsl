// Cascade selection for the sun's shadow (docs/shadows.md; shader_abi.h ShadowUniforms), both
// stages of receiver variants (FACET_SHADOW_CASCADES 1, 2 or 4).
//
// A position at view depth d = (p − eye) · forward takes the first cascade whose split lies beyond
// d. The splits increase, so the passed ones form a prefix, passed = step(splits, d), and cascade
// i's value is picked with a chain of mixes, v = mix(mix(mix(c0, c1, passed.x), c2, passed.y), c3,
// passed.z): arithmetic on values every thread reads at the same addresses, where indexing the
// block by a per-pixel cascade number is a load per vec4 (Mali-G57 measured 5 load cycles for a
// matrix and an offset read that way, more than the rest of a mid-tier shader).
// Precision: highp throughout; d and the picked values address the atlas (chunks/shadow_sun.glsl).

highp vec4 shadow_select(highp float viewDepth, highp vec4 c0, highp vec4 c1, highp vec4 c2, highp vec4 c3) {
#if FACET_SHADOW_CASCADES == 1
    return c0;
#else
    highp vec4 passed = step(shadow.splits, vec4(viewDepth));
    highp vec4 value = mix(c0, c1, passed.x);
#if FACET_SHADOW_CASCADES == 4
    value = mix(value, c2, passed.y);
    value = mix(value, c3, passed.z);
#endif
    return value;
#endif
}

highp float shadow_view_depth(highp vec3 worldPosition) {
    return dot(worldPosition - frame.cameraPosition.xyz, shadow.cameraForward.xyz);
}
