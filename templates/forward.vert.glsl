// Forward pass, vertex stage (lit and unlit). World-space position and normal go to the
// fragment stage in highp/mediump as the precision policy says: positions far from the origin
// need fp32 (a fp16 world position 1 km away has 0.5 m steps).
#include "math.glsl"

void main() {
    highp vec4 worldPosition = object.model * vec4(a_position, 1.0);
    v_worldPosition = worldPosition.xyz;
    v_normal = mat3(object.normalMatrix) * a_normal;
#if defined(FACET_VARYING_UV0)
    v_uv0 = a_uv0;
#endif
#if defined(FACET_VERTEX_DIFFUSE)
    // Per-vertex diffuse (Zioma 2015: diffuse varies slowly, so mid and low tiers light it per
    // vertex): irradiance / π from the sky and the directional light. The fragment stage only
    // multiplies it by the material's diffuse colour. n·l is clamped per vertex, which darkens
    // the terminator slightly on coarse meshes.
    vec3 n = normalize(v_normal);
    vec3 irradiance = frame.ambient.rgb;
#if defined(FACET_DIRECTIONAL_LIGHT)
    irradiance += frame.lightColor.rgb * (clamp(dot(n, normalize(frame.lightDirection.xyz)), 0.0, 1.0) * INV_PI);
#endif
#if defined(FACET_GAMMA_HACK)
    irradiance = sqrt(irradiance);  // gamma hack: light encoded per vertex, γ = 2 (shading_standard.glsl)
#endif
    v_diffuseLight = irradiance;
#endif
    gl_Position = frame.viewProjection * worldPosition;
}
