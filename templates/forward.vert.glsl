// Forward pass, vertex stage (lit and unlit). World-space position and normal go to the
// fragment stage in highp/mediump as the precision policy says: positions far from the origin
// need fp32 (a fp16 world position 1 km away has 0.5 m steps).
void main() {
    highp vec4 worldPosition = object.model * vec4(a_position, 1.0);
    v_worldPosition = worldPosition.xyz;
    v_normal = mat3(object.normalMatrix) * a_normal;
#if defined(FACET_VARYING_UV0)
    v_uv0 = a_uv0;
#endif
    gl_Position = frame.viewProjection * worldPosition;
}
