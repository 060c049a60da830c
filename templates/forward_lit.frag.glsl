// Forward pass, lit, fragment stage: evaluate the material's surface program, then shade with
// image-based ambient light (SH diffuse, or the irradiance cube's, unless lit per vertex, and the tier's environment
// specular), in dir1 variants one directional light, and FACET_POINT_LIGHTS punctual
// lights, each read from its fixed place in the frame block (unrolled below: no dynamic
// indexing). Writes pre-exposed linear HDR.
#include "math.glsl"
#include "precision.glsl"
#if defined(FACET_VIEW_VECTOR_MEDIUMP)
#include "view_vector.glsl"
#endif
#include "facet:material"
#if defined(FACET_MATERIAL_NORMAL) || defined(FACET_MATERIAL_CLEAR_COAT_NORMAL)
#include "normal_mapping.glsl"
#endif
#include "diffuse_lambert.glsl"
#include "facet:specular"
#if defined(FACET_IRRADIANCE_CUBE)
#include "ambient_irradiance_cube.glsl"
#elif !defined(FACET_VERTEX_DIFFUSE)
#include "ambient_sh.glsl"
#endif
// The assembler places each chunk once, at its first #include, whatever the #if around it: a
// chunk shared by several ambient models is included outside the conditionals.
#include "environment_cube.glsl"
// (The clear coat reads the prefiltered environment at its own roughness whatever the tier's
// ambient model.)
#if defined(FACET_IBL_SPLIT_SUM) || defined(FACET_IBL_ANALYTIC) || defined(FACET_IBL_SAMPLED) || \
    defined(FACET_CLEAR_COAT_LOBE) || defined(FACET_CLEAR_COAT_AMBIENT)
#include "ibl_prefiltered.glsl"
#endif
#if defined(FACET_SHEEN_AMBIENT) && !defined(FACET_IBL_TWO_MIP)
#include "ibl_prefiltered.glsl"
#endif
#if defined(FACET_IBL_SPLIT_SUM) || defined(FACET_IBL_SAMPLED)
#include "ibl_split_sum.glsl"
#endif
#if defined(FACET_IBL_ANALYTIC)
#include "env_brdf_karis.glsl"
#endif
#if defined(FACET_IBL_TWO_MIP)
#include "ibl_two_mip.glsl"
#endif
// GGX's fp16-safe denominator, for the coat's lobe and anisotropy's: where the tier's own lobe has
// none (lut), its first #include must not sit inside the coat's #if, or anisotropy alone lacks it.
#if defined(FACET_CLEAR_COAT_GGX_KELEMEN) || defined(FACET_ANISOTROPY_LOBE)
#include "ggx_denominator.glsl"
#endif
// The clear coat's forms (docs/material-models.md); a tier that drops it includes neither.
#if defined(FACET_CLEAR_COAT_LOBE) || defined(FACET_CLEAR_COAT_AMBIENT)
#include "clear_coat_ambient.glsl"
#endif
#if defined(FACET_CLEAR_COAT_GGX_KELEMEN)
#include "clear_coat_ggx_kelemen.glsl"
#endif
// Anisotropy's forms (docs/material-models.md); a tier that drops it includes neither.
#if defined(FACET_ANISOTROPY)
#include "anisotropy_frame.glsl"
#endif
#if defined(FACET_ANISOTROPY_LOBE)
#include "brdf_ggx.glsl"
#include "anisotropy_ggx_smith.glsl"
#endif
// The sheen's lobe (the cloth model's, or a layer's over the standard model) before the standard
// model's lights, which read the layer's scale of the base.
#if defined(FACET_SHEEN_LOBE)
#include "sheen_charlie_neubelt.glsl"
#endif
#include "shading_standard.glsl"
#if defined(FACET_SPECULAR_AA)
#include "specular_antialiasing.glsl"
#endif
#if defined(FACET_IBL_SAMPLED)
#include "ibl_sampled.glsl"
#endif
#if defined(FACET_MATERIAL_AMBIENT_OCCLUSION)
#include "ambient_occlusion.glsl"
#endif
#include "shading_ambient.glsl"
// The sheen over a base (docs/material-models.md, "Cloth" and "Sheen layer"), after the specular
// occlusion it applies; the cloth model, in place of the standard one's lights and ambient
// specular, reads the standard chunk's material terms and the sheen's.
#if defined(FACET_SHEEN_AMBIENT)
#include "sheen_layer.glsl"
#endif
#if defined(FACET_SHADING_CLOTH)
#include "shading_cloth.glsl"
#endif
#include "output_blending.glsl"
// The view vector for the half vector of each light: highp where the tier's lobe sums the half
// vector in highp (shading_standard.glsl, half_vector: at a grazing glint v ≈ −l and v + l
// cancels in fp16); at the tier's precision where the view varying is mediump (a lobe without
// that sum, FACET_VIEW_VECTOR_MEDIUMP), which a highp copy would only convert back.
#if defined(FACET_VIEW_VECTOR_MEDIUMP)
vec3 shading_view_for_lights;
#else
highp vec3 shading_view_for_lights;
#endif
// The filter both receivers share, placed (first included) where either is built.
#if defined(FACET_SHADOW_CASCADES) || defined(FACET_SPOT_SHADOW)
#include "shadow_filter.glsl"
#endif
#if defined(FACET_SHADOW_CASCADES)
#include "shadow_sun.glsl"
#endif
#if defined(FACET_SPOT_SHADOW)
#include "shadow_spot.glsl"
#endif
#if FACET_POINT_LIGHTS > 0
#include "light_punctual.glsl"

vec3 shade_punctual(MaterialInputs material, PunctualLightData light) {
    highp vec3 l;
    vec3 illuminance = punctual_light_illuminance(light, v_worldPosition, l);
#if defined(FACET_SHADING_CLOTH)
    return shade_cloth_direct(material, shading_normal, shading_view_for_lights, l, illuminance);
#else
    return shade_standard_direct(material, shading_normal, shading_view_for_lights, l, illuminance);
#endif
}
#endif

void main() {
    shading_normal = normalize(v_normal);
#if defined(FACET_SHADOW_CASCADES)
    float sunVisibility = shadow_sun_visibility();
#endif
#if defined(FACET_SPOT_SHADOW)
    float spotVisibility = shadow_spot_visibility();
#endif
    // The surface program and the ambient terms read the view vector at the tier's precision, the
    // lights' half vectors at shading_view_for_lights's.
#if defined(FACET_VIEW_VECTOR_MEDIUMP)
    shading_view_for_lights = view_direction(FACET_TO_EYE);
#else
    shading_view_for_lights = normalize(FACET_TO_EYE);
#endif
    shading_view = shading_view_for_lights;
    MaterialInputs material = material_defaults();
    evaluate_surface(material);
#if defined(FACET_MATERIAL_CLEAR_COAT_NORMAL)
    shading_clear_coat_normal = tangent_to_world(material.clearCoatNormal);
#elif defined(FACET_CLEAR_COAT_LOBE) || defined(FACET_CLEAR_COAT_AMBIENT)
    shading_clear_coat_normal = shading_normal;  // the interpolated one: a base normal map stays under the coat
#endif
#if defined(FACET_MATERIAL_NORMAL)
    // vertex.normal reads in the surface program saw the interpolated normal; shading uses the
    // mapped one. Per-vertex diffuse (mid, low) was lit before any map: it keeps the vertex normal.
    shading_normal = tangent_to_world(material.normal);
#endif
#if defined(FACET_SPECULAR_AA)
    // The shading normal is final: its screen-space derivatives are taken here, in main()'s uniform
    // control flow, never in the surface program (the language has no derivative to misuse).
    material.roughness = specular_aa_roughness(material_perceptual_roughness(material), shading_normal);
#endif
#if defined(FACET_ANISOTROPY)
    // The brushing's frame about the final shading normal, before the ambient and the lights.
    anisotropy_frame(material, shading_normal);
#endif
#if defined(FACET_ANISOTROPY_LOBE)
    anisotropy_setup(material, material_alpha(material), shading_normal,
                     max(dot(shading_normal, shading_view), MIN_N_DOT_V), shading_view);
#endif

#if defined(FACET_VERTEX_DIFFUSE) && (defined(FACET_SHADOW_CASCADES) || defined(FACET_SPOT_SHADOW))
    // The shadowed lights' per-vertex diffuse (the sun's, the casting spot's in slot 0), each
    // scaled by its visibility; linear.
#if defined(FACET_SHADOW_CASCADES) && defined(FACET_SPOT_SHADOW)
    vec3 shadowedDiffuse = frame.lightColor.rgb * (v_sunDiffuse * sunVisibility) +
                      frame.punctualLights[0].colorIntensity.rgb * (v_spotDiffuse * spotVisibility);
#elif defined(FACET_SHADOW_CASCADES)
    vec3 shadowedDiffuse = frame.lightColor.rgb * (v_sunDiffuse * sunVisibility);
#else
    vec3 shadowedDiffuse = frame.punctualLights[0].colorIntensity.rgb * (v_spotDiffuse * spotVisibility);
#endif
#endif
#if defined(FACET_VERTEX_DIFFUSE) && defined(FACET_MATERIAL_AMBIENT_OCCLUSION)
    // The occluded ambient, then the lights' per-vertex diffuse (forward.vert.glsl), the shadowed
    // ones' shadowed here; with FACET_GAMMA_HACK summed in the gamma-2 encoding.
    vec3 directLight = v_directDiffuse;
#if (defined(FACET_SHADOW_CASCADES) || defined(FACET_SPOT_SHADOW)) && defined(FACET_GAMMA_HACK)
    directLight = sqrt(directLight * directLight + shadowedDiffuse);
#elif defined(FACET_SHADOW_CASCADES) || defined(FACET_SPOT_SHADOW)
    directLight += shadowedDiffuse;
#endif
    vec3 color = apply_ambient_occlusion(material, material_diffuse_color(material) * v_diffuseLight);
    vec3 directDiffuse = material_diffuse_color(material) * directLight;
#if defined(FACET_GAMMA_HACK)
    color = sqrt(color * color + directDiffuse * directDiffuse);
#else
    color += directDiffuse;
#endif
#elif defined(FACET_VERTEX_DIFFUSE) && (defined(FACET_SHADOW_CASCADES) || defined(FACET_SPOT_SHADOW))
    // The shadowed lights' per-vertex diffuse joins the rest of the per-vertex light.
#if defined(FACET_GAMMA_HACK)
    vec3 diffuseLight = sqrt(v_diffuseLight * v_diffuseLight + shadowedDiffuse);  // both in the gamma-2 encoding
#else
    vec3 diffuseLight = v_diffuseLight + shadowedDiffuse;
#endif
    vec3 color = apply_ambient_occlusion(material, material_diffuse_color(material) * diffuseLight);
#elif defined(FACET_VERTEX_DIFFUSE)
    vec3 color = apply_ambient_occlusion(material, material_diffuse_color(material) * v_diffuseLight);
#elif defined(FACET_IBL_SAMPLED)
    vec3 color = shade_standard_ambient(material, sampled_irradiance_over_pi(shading_normal));
#elif defined(FACET_IRRADIANCE_CUBE)
    vec3 color = shade_standard_ambient(material, cube_irradiance_over_pi(shading_normal));
#else
    vec3 color = shade_standard_ambient(material, sh_irradiance_over_pi(shading_normal));
#endif
    // The one term formed in the tier's colour space (encoded with FACET_GAMMA_HACK); the rest is
    // summed in linear (shading_ambient.glsl).
    color = linear_from_shading_space(color);
    // Before the lights: with FACET_ENERGY_COMPENSATION it sets the factor they use.
#if !defined(FACET_SHADING_CLOTH)
    color = add_light(color, shade_standard_ambient_specular(material, shading_normal, shading_view));
#endif
#if defined(FACET_SHEEN_AMBIENT)
    // The sheen over the fabric, or over the standard model's base, lit so far, before the lights:
    // it sets the sheen's energy correction and the base's scale they use.
    color = sheen_layer(material, color, shading_normal, shading_view);
#endif
#if defined(FACET_CLEAR_COAT_LOBE)
    // The ambient base under the coat, and the coat's environment; each light layers its own.
    color = clear_coat_layer(material, color, shading_view);
#endif
#if defined(FACET_DIRECTIONAL_LIGHT)
    // A unit vector by the ABI (shader_abi.h FrameUniforms::lightDirection): the runtime
    // normalizes it once per frame on the CPU instead of every pixel doing so.
    highp vec3 l = frame.lightDirection.xyz;
#if defined(FACET_SHADING_CLOTH) && defined(FACET_SHADOW_CASCADES)
    color = add_light(color, shade_cloth_direct(material, shading_normal, shading_view_for_lights, l,
                                                frame.lightColor.rgb * sunVisibility));
#elif defined(FACET_SHADING_CLOTH)
    color = add_light(color, shade_cloth_direct(material, shading_normal, shading_view_for_lights, l, frame.lightColor.rgb));
#elif defined(FACET_SHADOW_CASCADES)
    color = add_light(color, shade_standard_direct(material, shading_normal, shading_view_for_lights, l,
                                                   frame.lightColor.rgb * sunVisibility));
#else
    color = add_light(color, shade_standard_direct(material, shading_normal, shading_view_for_lights, l, frame.lightColor.rgb));
#endif
#endif
#if FACET_POINT_LIGHTS > 0 && defined(FACET_SPOT_SHADOW)
    color = add_light(color, shade_punctual(material, frame.punctualLights[0]) * spotVisibility);
#elif FACET_POINT_LIGHTS > 0
    color = add_light(color, shade_punctual(material, frame.punctualLights[0]));
#endif
#if FACET_POINT_LIGHTS > 1
    color = add_light(color, shade_punctual(material, frame.punctualLights[1]));
#endif
#if FACET_POINT_LIGHTS > 2
    color = add_light(color, shade_punctual(material, frame.punctualLights[2]));
    color = add_light(color, shade_punctual(material, frame.punctualLights[3]));
#endif
#if defined(FACET_CLEAR_COAT_AMBIENT)
    // The whole lit base under the coat, and the coat's environment (no lobe per light).
    color = clear_coat_layer(material, color, shading_view);
#endif
    fragColor = blend_output(add_light(color, linear_from_shading_space(material.emissive)), material.alpha);
}
