// The cloth model (`shading cloth`; docs/material-models.md, "Cloth"): Filament's (R. Guy and
// M. Agopian, "Physically Based Rendering in Filament", "Cloth model"), no Fresnel:
//   f_sheen   = sheenColor · D(h) · V · s(n·v, r)
//   D         = (2 + 1/α) · sin(θ_h)^(1/α) / (2π)              Charlie (A. Estevez and C. Kulla,
//               "Production Friendly Microfacet Sheen BRDF", 2017), α = r², sin² θ_h = 1 − (n·h)²
//   V         = 1 / (4 (n·l + n·v − n·l · n·v))                 D. Neubelt and M. Pettineo,
//               "Crafting a Next-Gen Material Pipeline for The Order: 1886", 2013
//   s         = 1 / max(1, E(n·v, r))                           the energy correction (below)
//   L_direct  = (diffuseColor/π · w · b + f_sheen · n·l) · E_light
//   w         = n·l, or with subsurfaceColor Filament's wrap: saturate((n·l + 0.5) / 1.5²) ·
//               saturate(subsurfaceColor + saturate(n·l))   (energy-conserving wrap, w = 0.5)
//   L_ambient = diffuseColor · E_env(n)/π · ao · b + prefiltered(reflect(−v, n), r) · sheenColor · min(E, 1) · so
//   b         = 1 − max(sheenColor) · min(E(n·v, r), 1)     the fabric under the sheen
// E(n·v, r) = ∫ D V n·l dω is the sheen's directional albedo: up to 3.9 at r = 0.089 and
// n·v = 0.005 (D's mass lies on microfacets perpendicular to n, which a grazing view sees
// head-on, and V → 1/(4 n·l) as n·v → 0). Dividing the lobe by max(1, E) makes its albedo
// min(E, 1): ≤ 1 everywhere, unchanged where it was ≤ 1. Both numbers come from the DFG
// texture's B and A channels (ibl/sheen_lut.h; one fetch at (n·v, r), the split sum's
// coordinates), read once per pixel by sheen_layer (sheen_layer.glsl) before any light.
// b is KHR_materials_sheen's albedo scaling (the Khronos glTF extension's specification, "Albedo
// scaling"), at the view only (as the clear coat's 1 − Fc(n·v), one per pixel, not per light):
// sheen and fabric together reflect at most what a white fabric alone would, so the white furnace
// of a white fabric under a white sheen reads ≤ 1 where the sum alone reads up to 1 + min(E, 1).
// The environment is read from the GGX-prefiltered levels at r (Filament's approximation: the
// sheen's own lobe is wider at grazing views). sheenColor defaults to √baseColor (Filament's
// default: a two-tone sheen lighter than the fabric); the diffuse colour is baseColor (no metal).
// The sheen's colour and environment are sheen_layer.glsl's, one light's sheen
// sheen_charlie_neubelt.glsl's (sheen_light), shared with the sheen layer over the standard model.
// Needs: both, shading_standard.glsl (material terms, half_vector), diffuse_lambert.glsl.
//
// fp16: the lobe's bounds are sheen_charlie_neubelt.glsl's; the light's product is saturated at
// 65504 as the standard model's (shading_standard.glsl). The table's two numbers lie in [0, 1].

vec3 shade_cloth_direct(MaterialInputs material, vec3 n, highp vec3 viewHighp, highp vec3 lightHighp,
                        vec3 lightColor) {
    vec3 l = lightHighp;  // mediump from here on; the half vector alone takes them highp
    float NoLSigned = dot(n, l);
    float NoL = clamp(NoLSigned, 0.0, 1.0);
#if defined(FACET_SHEEN_LOBE)
    vec3 v = viewHighp;
    vec3 h = half_vector(viewHighp, lightHighp);
    float NoV = max(dot(n, v), MIN_N_DOT_V);
    float NoH = clamp(dot(n, h), 0.0, 1.0);
    vec3 sheen = sheen_light(NoV, NoL, NoH);
#else
    vec3 sheen = vec3(0.0);  // (the tier's sheen form has no lobe per light: folded away)
#endif
#if defined(FACET_VERTEX_DIFFUSE)
    // Diffuse is lit per vertex (forward.vert.glsl, Lambert's: the wrap is this form's loss).
    return min(sheen * lightColor, MEDIUMP_FLT_MAX);
#else
    vec3 diffuseColor = material_diffuse_color(material);
#if defined(FACET_GAMMA_HACK)
    diffuseColor *= diffuseColor;  // encoded with γ = 2: back to linear
#endif
#if defined(FACET_MATERIAL_SUBSURFACE_COLOR)
    // Filament's wrap: (n·l + w)/(1 + w)² with w = 0.5 integrates to Lambert's energy over the
    // sphere of light directions; the tint lets light through where n·l is small.
    vec3 diffuse = diffuseColor * (diffuse_lambert() * clamp((NoLSigned + 0.5) * (1.0 / 2.25), 0.0, 1.0)) *
                   clamp(material.subsurfaceColor + NoL, 0.0, 1.0);
#else
    vec3 diffuse = diffuseColor * (diffuse_lambert() * NoL);
#endif
#if defined(FACET_SHEEN_LOBE)
    diffuse *= shading_sheen_base_scale;
#endif
    return min((diffuse + sheen) * lightColor, MEDIUMP_FLT_MAX);
#endif
}
