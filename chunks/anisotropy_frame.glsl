// Anisotropy's per-pixel frame and its image-based light (the `ggx_smith` and `bent_ibl`
// anisotropy of docs/material-models.md): the direction of the brushing in world space, its
// roughness along and across, and the environment read along a bent reflection vector.
//   t = normalize(t₀ − n (n·t₀)),  t₀ = the interpolated tangent frame (normal_mapping.glsl's, MikkTSpace)
//       applied to anisotropyDirection, unnormalized (Gram–Schmidt against the shading normal: a
//       mapped normal or an interpolated tangent is not orthogonal to it; one normalization in all)
//   (the `bent_ibl` form takes t₀ as it is: no projection, no normalization, no fallback. R below stays
//   finite for any t (its bounds rest on c₁ alone); an interpolated tangent a little short of
//   unit length or off the normal's plane bends the reflection a little less or off-axis, a zero
//   tangent not at all. It is what keeps the
//   option within half of high's Mali-G57 cost in mid and low: the frame costs 0.27 cycles
//   there, docs/material-models.md.)
//   α_t = clamp(α (1 + k), α_min, 1),   α_b = clamp(α (1 − k), α_min, 1),   k = anisotropy ∈ [−1, 1]
// The roughness mapping is the one Filament's PBR document (§4.9.1, "Anisotropic specular BRDF")
// takes from Kulla and Conty, "Revisiting Physically Based Shading at Imageworks", SIGGRAPH 2017:
// unlike Burley's 2012 aspect ratio it reaches a sharp highlight across the brushing (α_b → 0 at
// k = 1). The clamps: α_min = MIN_PERCEPTUAL_ROUGHNESS² = 0.007921 (Filament's MIN_ROUGHNESS on
// mobile) keeps α_t α_b ≥ 6.27e-5, above binary16's smallest normal 2^-14 = 6.10e-5, where Filament's
// highp floor 0.001 would give 1e-6 (anisotropy_ggx_smith.glsl has the bounds that rest on both
// clamps); the upper clamp at 1 keeps the lobe's range bounds (it changes Filament's mapping only
// for α (1 + |k|) > 1, perceptual roughness above 0.71 at k = 1).
// Bent reflection vector (image-based light): an anisotropic lobe reflects the environment
// stretched along the brushing, which a prefiltered (isotropic) environment cannot; the normal is
// bent towards the one that faces the view within the plane across the stretch,
//   a = v − d (d·v)         d = b for k ≥ 0, t for k < 0 (the stretch is along t for k > 0)
//   n_bent = normalize(mix(n, a, |k| · saturate(5 r)))     R = reflect(−v, n_bent)
// Sources: D. McAuley, "Rendering the World of Far Cry 4", GDC 2015, and D. Revie, "Implementing
// Fur Using Deferred Shading", GPU Pro 2, 2011, in the form of Filament's shaders (the bend faded
// out below perceptual roughness 0.2, where the lobe is too narrow to stretch the reflection).
// Written without a cross product or a normalization: with e = the stretch's direction (t for
// k ≥ 0, b = n × t for k < 0; d above is the other one), the frame orthonormal and
// v = t (t·v) + b (b·v) + n (n·v), Filament's a = cross(cross(d, v), d) = v − d (d·v) is
// e (e·v) + n (n·v), so
//   m = mix(n, a, bend) = c₁ n + c₂ e,   c₁ = 1 − bend (1 − n·v),   c₂ = bend (e·v)
//   R = reflect(−v, m/|m|) = (2 m (m·v) − |m|² v) / |m|²,   m·v = c₁ n·v + c₂ e·v,   |m|² = c₁² + c₂²
// and the environment read needs R's direction only, so the lookup takes 2^8 |m|² R: no division
// and no square root, so high's fragment stage keeps its budget of four divisions
// (examples/lint/budgets.json; the form with the division measured 0.03–0.06 Mali-G57 cycles
// cheaper, docs/material-models.md). n·v is the clamped
// one (≥ MIN_N_DOT_V, as everywhere), and bend ≤ 1 − 2^-7, so c₁ ≥ 2^-7 and |m|² ≥ 2^-14 where the
// view is at or below the horizon (an interpolated normal facing away at a silhouette; Filament's
// form normalizes the zero vector there: NaN). Then |2^8 |m|² R| = 2^8 |m|² ∈ [2^-6, 2^9]: the
// lookup vector is never flushed to zero, no component overflows, and a component flushed below
// 2^-14 is off by under 2^-8 of the vector's length. The cap bends 0.8 % less at |k| = 1, below
// what the prefiltered environment resolves.
// fp16: unit vectors and α ∈ [α_min, 1]; 1/α ≤ 126.25. Needs: precision.glsl, v_normal and
// v_tangent (FACET_VARYING_TANGENT).

const float ANISOTROPY_ALPHA_MIN = 0.007921;  // MIN_PERCEPTUAL_ROUGHNESS² (above)
const float ANISOTROPY_BEND_MAX = 0.9921875;  // 1 − 2^-7: keeps |m|² ≥ 2^-14 (above)

// The brushing's tangent in world space, a unit vector orthogonal to the shading normal; set once
// per pixel by anisotropy_frame before any light is shaded (b = n × t is the lobe's:
// anisotropy_ggx_smith.glsl).
vec3 shading_anisotropic_t;

// With FACET_PRESHADED_ANISOTROPY, k, (α_t, α_b) and the reflection's bend depend only on
// parameters: the preshader (compiler/preshader.h) forms these same values on the CPU, from its
// r and α = r² (material_perceptual_roughness, material_alpha: shading_standard.glsl). With
// FACET_SPECULAR_AA the roughness is widened per pixel (specular_antialiasing.glsl): then
// (α_t, α_b) and the bend are formed here from it.
float anisotropy_strength(MaterialInputs material) {
#if defined(FACET_PRESHADED_ANISOTROPY)
    return params.facet_anisotropy;
#else
    return clamp(material.anisotropy, -1.0, 1.0);
#endif
}

// (α_t, α_b) for the material's α (material_alpha) and anisotropy.
vec2 anisotropic_alpha(MaterialInputs material, float alpha) {
#if defined(FACET_PRESHADED_ANISOTROPY) && !defined(FACET_SPECULAR_AA)
    return params.facet_anisotropicAlpha;
#else
    float k = anisotropy_strength(material);
    return clamp(alpha * vec2(1.0 + k, 1.0 - k), ANISOTROPY_ALPHA_MIN, 1.0);
#endif
}

void anisotropy_frame(MaterialInputs material, vec3 n) {
#if defined(FACET_MATERIAL_ANISOTROPY_DIRECTION)
    vec3 d = material.anisotropyDirection;
    vec3 t = d.x * v_tangent.xyz + d.y * (v_tangent.w * cross(v_normal, v_tangent.xyz)) + d.z * v_normal;
#else
    vec3 t = v_tangent.xyz;  // the default direction (1, 0, 0): the mesh's tangent
#endif
#if defined(FACET_ANISOTROPY_LOBE)
    t -= n * dot(n, t);
    // A mesh without tangents or a direction along the normal leaves nothing of t: any direction
    // in the tangent plane then (the brushing's direction is unknown). The test is on |t|² of an
    // interpolated unit tangent: 1e-3 is a normal fp16 number, and t is then 1.8° off the normal or more.
    vec3 fallback = abs(n.z) < 0.5 ? vec3(-n.y, n.x, 0.0) : vec3(0.0, -n.z, n.y);
    t = normalize(dot(t, t) > 1.0e-3 ? t : fallback);
#endif
    shading_anisotropic_t = t;
}

// The direction of the reflection about the bent normal (not normalized: only the environment read
// takes it); NoV = max(n·v, MIN_N_DOT_V).
vec3 anisotropic_reflection(MaterialInputs material, vec3 n, vec3 v, float NoV, float perceptualRoughness) {
    float k = anisotropy_strength(material);
    vec3 e = k >= 0.0 ? shading_anisotropic_t : cross(n, shading_anisotropic_t);
    float EoV = dot(e, v);
#if defined(FACET_PRESHADED_ANISOTROPY) && !defined(FACET_SPECULAR_AA)
    float bend = params.facet_anisotropicBend;
#else
    float bend = min(abs(k) * clamp(5.0 * perceptualRoughness, 0.0, 1.0), ANISOTROPY_BEND_MAX);
#endif
    float c1 = 1.0 - bend * (1.0 - NoV);
    float c2 = bend * EoV;
    float MoV = c1 * NoV + c2 * EoV;
    // 2^8 |m|² R (above): a direction for the environment read, not a unit vector.
    return (512.0 * MoV) * (c1 * n + c2 * e) - (256.0 * (c1 * c1 + c2 * c2)) * v;
}
