// Forward pass, vertex stage (lit and unlit). World-space position and normal go to the
// fragment stage in highp/mediump as the precision policy says: positions far from the origin
// need fp32 (a fp16 world position 1 km away has 0.5 m steps).
#include "math.glsl"
#if defined(FACET_VIEW_VECTOR_MEDIUMP)
#include "view_vector.glsl"
#endif
#if defined(FACET_SHADOW_CASCADES)
#include "shadow_cascade.glsl"
#endif
#if defined(FACET_VERTEX_DIFFUSE)
#include "ambient_sh.glsl"
#endif
#if defined(FACET_VERTEX_DIFFUSE) && FACET_POINT_LIGHTS > 0
#include "light_punctual.glsl"

// Lambert irradiance / π of one punctual light at this vertex.
vec3 punctual_diffuse(PunctualLightData light, highp vec3 worldPosition, vec3 n) {
    highp vec3 l;
    vec3 illuminance = punctual_light_illuminance(light, worldPosition, l);
    return illuminance * (clamp(dot(n, l), 0.0, 1.0) * INV_PI);
}
#endif

void main() {
#include "object_to_world.glsl"
#if defined(FACET_VARYING_WORLD_POSITION)
    v_worldPosition = worldPosition.xyz;
#else
    // Nothing in the fragment stage reads the position itself: it gets the vector to the eye,
    // exact once interpolated (affine in the position), one highp subtraction per vertex instead
    // of per pixel. A mediump varying takes it scaled into binary16's range (view_vector.glsl).
#if defined(FACET_VIEW_VECTOR_MEDIUMP)
    v_toEye = (frame.cameraPosition.xyz - worldPosition.xyz) * VIEW_VECTOR_SCALE;
#else
    v_toEye = frame.cameraPosition.xyz - worldPosition.xyz;
#endif
#endif
    // Normalized before it becomes a mediump varying: the normal matrix carries the inverse of
    // the object's scale (a 1000 m sphere's normals come out 1/1000 long), and a binary16
    // component below 2^-14 ≈ 6.1e-5 is flushed to 0 (subnormal) or keeps few bits, so such a
    // normal lost every tilt below 0.061 rad (the grazing_glint hard case, docs/fp16-emulation.md).
    // A unit normal keeps 11 significant bits in every component ≥ 2^-14: tilts ≥ 6.1e-5 rad.
    // Normals take the inverse-transpose of the upper 3×3 M, which stays perpendicular to the
    // surface under a non-uniform scale. Its rows are the cross products of M's rows divided by
    // det M (the cofactor matrix over the determinant): the normalize removes the scale, and the
    // determinant's sign (negative for a mirroring transform) is kept so the normal still points
    // out. 3 cross products and a dot instead of a second matrix per instance (36 bytes).
    highp vec3 row0 = a_instanceRow0.xyz, row1 = a_instanceRow1.xyz, row2 = a_instanceRow2.xyz;
    highp vec3 cofactor0 = cross(row1, row2);
    highp vec3 objectNormal = dot(row0, cofactor0) < 0.0 ? -a_normal : a_normal;
    v_normal = normalize(objectNormal * mat3(cofactor0, cross(row2, row0), cross(row0, row1)));
#include "uv_color_varyings.glsl"
#if defined(FACET_VARYING_TANGENT)
    // A tangent lies in the surface, so it transforms with the model matrix itself (the normal
    // matrix is for normals); the handedness sign passes through. Normalized as the normal is:
    // MikkTSpace's frame is unit n and t per vertex (normal_mapping.glsl keeps them unnormalized
    // only after interpolation). Left s long by an object scaled s, t and b = w·cross(n, t) would
    // weigh a map's tilt s times against n: a normal map 40× as steep on a floor scaled 40. A mesh
    // without tangents keeps its zero tangent (0 · 1e15: normal_mapping.glsl's fallback, not a
    // NaN); 1e-30 is a normal fp32 number far below any real tangent's |t|².
    highp vec3 tangent = a_tangent.xyz * mat3(row0, row1, row2);
    v_tangent = vec4(tangent * inversesqrt(max(dot(tangent, tangent), 1e-30)), a_tangent.w);
#endif
#if defined(FACET_VERTEX_DIFFUSE)
    // Per-vertex diffuse (Zioma 2015: diffuse varies slowly, so mid and low tiers light it per
    // vertex): irradiance / π from the environment's SH and the lights. The fragment stage only
    // multiplies it by the material's diffuse colour. n·l is clamped per vertex, which darkens
    // the terminator slightly on coarse meshes. SH irradiance is smooth (at most quadratic in n),
    // which per-vertex evaluation and interpolation follow closely.
    vec3 n = v_normal;  // unit length (above)
    vec3 irradiance = sh_irradiance_over_pi(n);
#if defined(FACET_MATERIAL_AMBIENT_OCCLUSION)
    // Ambient occlusion occludes the ambient alone (shading_ambient.glsl): the lights' diffuse
    // goes to the fragment stage on its own varying, added after the occlusion.
    vec3 ambientIrradiance = irradiance;
    irradiance = vec3(0.0);
#endif
#if defined(FACET_DIRECTIONAL_LIGHT) && defined(FACET_SHADOW_CASCADES)
    // A shadow receiver darkens the sun alone: its n·l / π goes to the fragment stage on its own
    // (one channel: the sun's colour is uniform), which scales it by the visibility there.
    v_sunDiffuse = clamp(dot(n, frame.lightDirection.xyz), 0.0, 1.0) * INV_PI;
#elif defined(FACET_DIRECTIONAL_LIGHT)
    irradiance += frame.lightColor.rgb * (clamp(dot(n, frame.lightDirection.xyz), 0.0, 1.0) * INV_PI);  // a unit vector by the ABI
#endif
#if FACET_POINT_LIGHTS > 0 && defined(FACET_SPOT_SHADOW)
    // A spot-shadow receiver darkens light slot 0 alone, the casting spot: its irradiance / π per
    // unit colour goes to the fragment stage on its own (one channel: the light's colour is
    // uniform), which scales it by the colour and the visibility there.
    PunctualLightData spot = frame.punctualLights[0];
    spot.colorIntensity = vec4(1.0);
    v_spotDiffuse = punctual_diffuse(spot, worldPosition.xyz, n).x;
#elif FACET_POINT_LIGHTS > 0
    irradiance += punctual_diffuse(frame.punctualLights[0], worldPosition.xyz, n);
#endif
#if FACET_POINT_LIGHTS > 1
    irradiance += punctual_diffuse(frame.punctualLights[1], worldPosition.xyz, n);
#endif
#if FACET_POINT_LIGHTS > 2
    irradiance += punctual_diffuse(frame.punctualLights[2], worldPosition.xyz, n);
    irradiance += punctual_diffuse(frame.punctualLights[3], worldPosition.xyz, n);
#endif
#if defined(FACET_GAMMA_HACK)
    irradiance = sqrt(irradiance);  // gamma hack: light encoded per vertex, γ = 2 (shading_standard.glsl)
#endif
#if defined(FACET_MATERIAL_AMBIENT_OCCLUSION) && defined(FACET_GAMMA_HACK)
    v_directDiffuse = irradiance;
    v_diffuseLight = sqrt(ambientIrradiance);
#elif defined(FACET_MATERIAL_AMBIENT_OCCLUSION)
    v_directDiffuse = irradiance;
    v_diffuseLight = ambientIrradiance;
#else
    v_diffuseLight = irradiance;
#endif
#endif
#if defined(FACET_SHADOW_CASCADES)
    // The sun's frame and the view depth for the fragment stage's shadow lookup (chunks/shadow_sun.glsl),
    // moved along the normal by its cascade's normal offset (the vertex's own cascade: a triangle
    // across a split blends the two offsets, a bias that varies smoothly).
    highp float viewDepth = shadow_view_depth(worldPosition.xyz);
    highp float normalOffset = shadow_select(viewDepth, shadow.cascadeScale[0], shadow.cascadeScale[1],
                                             shadow.cascadeScale[2], shadow.cascadeScale[3]).w;
    highp vec4 offsetPosition = vec4(worldPosition.xyz + v_normal * normalOffset, 1.0);
    v_shadowPosition = vec4((shadow.lightView * offsetPosition).xyz, viewDepth);
#endif
#if defined(FACET_SPOT_SHADOW)
    // The casting spot's view of the position moved along the normal by normalBias texels of that
    // view at the position's distance w along the light's axis (chunks/shadow_spot.glsl): the view's
    // cell spans 2·tan(half angle)·w metres at distance w, so a texel there is w times its width at
    // 1 m, and spotNormalOffset.x = normalBias × that width. w is the unmoved position's: the move
    // changes it by (n · axis) × the offset, a fraction normalBias · 2·tan(half) / cell of w (at most
    // about 1 % for a 682-texel cell, a 60° cone and normalBias 2), which the offset does not need.
    highp vec4 spotPosition = shadow.spotAtlasFromWorld * worldPosition;
    v_spotShadowPosition =
        spotPosition + shadow.spotAtlasFromWorld * vec4(v_normal * (shadow.spotNormalOffset.x * spotPosition.w), 0.0);
#endif
    gl_Position = frame.viewProjection * worldPosition;
}
