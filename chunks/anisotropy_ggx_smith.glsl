// The anisotropic specular lobe of each light (the `ggx_smith` anisotropy of reference and high;
// docs/material-models.md), in place of the tier's isotropic lobe:
//   f_s = D_aniso(h) · V_aniso(v, l) · F(l·h)
//   D_aniso = 1 / (π α_t α_b s²),   s = (t·h / α_t)² + (b·h / α_b)² + (n·h)²
//   V_aniso = 0.5 / (n·l |(α_t t·v, α_b b·v, n·v)| + n·v |(α_t t·l, α_b b·l, n·l)|)
// with t, b, α_t, α_b from anisotropy_frame.glsl and F Schlick's (brdf_ggx.glsl).
// Sources: B. Burley, "Physically-Based Shading at Disney", SIGGRAPH 2012 (anisotropic GGX D,
// appendix B.2); E. Heitz, "Understanding the Masking-Shadowing Function in Microfacet-Based
// BRDFs", JCGT 2014 (the height-correlated Smith G₂ of the anisotropic GGX, whose Λ is the
// isotropic one at the projected roughness α_o = |(α_t t·o, α_b b·o)| / |(t·o, b·o)|); the V form
// is Filament's (PBR document §4.9.1). D written with s rather than Filament's
// d = (α_b t·h, α_t b·h, α_t α_b n·h): the same value, ≠ in range (below).
// Energy: the lobe's directional albedo (F = 1) is at most 1.00000 over roughness, anisotropy, n·v
// and the view's azimuth (tests/reference/anisotropy.h, Reference.AnisotropicFurnaceIsAtMostOne);
// times the tiers' multiple-scattering compensation of the isotropic lobe of the same α, 1/E(α)
// (Filament applies it to its anisotropic lobe), it reaches 1.74 (r = 1, k = 1: α_b = α_min keeps
// the energy the isotropic E(1) = 0.57 loses), and 1.02–1.07 with the E of α_b or of √(α_t α_b),
// so the lobe goes uncompensated: it loses what single scattering loses (up to 1 − E of a rough
// metal) rather than create light.
// Per pixel (anisotropy_setup): 1/α_t, 1/α_b, C = 1/(π α_t α_b) and the view's length; per light
// two divisions (D's 1/s and V's), as the isotropic ggx_smith lobe.
// fp16 (mediump). The hazard: at perceptual roughness 0.089 (α = 0.0079) and k = 1, Filament's
// d² = dot(d, d) is (α_t α_b)² ≈ 1.6e-8 at the highlight's centre, far below binary16's smallest
// normal 2^-14 = 6.1e-5 (Filament's mobile shader computes d in highp for that reason), and
// its D = α_t α_b (α_t α_b / d²)² passes through 1/(α_t α_b)² ≈ 6.4e7 > 65504. The form here stays
// inside binary16's normal range with α_t, α_b ∈ [α_min, 1], α_min = 0.007921 (the clamps of
// anisotropy_frame.glsl), and needs no highp island:
//   - |t·h| / α_t, |b·h| / α_b ≤ 1/α_min = 126.25, their squares ≤ 15939;
//   - s ∈ [1, 15940]: t, b, n orthonormal, so s ≥ (t·h)² + (b·h)² + (n·h)² = 1 (every 1/α ≥ 1), and
//     at the centre s = (n·h)² ≈ 1: a sum of squares, no cancellation;
//   - q = 1/s ∈ [6.27e-5, 1] is a normal number; C ≤ 1/(π α_min²) = 5073 (α_t α_b ≥ 6.27e-5, normal);
//     D = (C q) q: C q ≤ 5073, and the product falls below 2^-14 (flushed to 0) only where the
//     true D < 6.1e-5, where the lost D · V · n·l < 6.1e-5 · 63 = 4e-3 (V · n·l ≤
//     0.5 / |(α_t t·v, α_b b·v, n·v)| ≤ 0.5 / α_min = 63);
//   - V on operands scaled by 2^7 = 128, the smallest power of two with 2^k α_min ≥ 1: every length
//     |128 (α_t t·o, α_b b·o, n·o)| ∈ [1.014, 128] (t, b, n orthonormal: the smallest component scale
//     is min(α_t, α_b, 1) ≥ α_min; each square ≤ 16384, their sum too), so the denominator
//     n·l |·| + n·v |·| ≥ n·v · 1.014 ≥ 1.01e-4 (n·v ≥ MIN_N_DOT_V) is normal and ≤ 256; its n·l
//     term is flushed only where n·l < 6.1e-5, a light whose term is multiplied by that n·l;
//     V = 64 / (…) ≤ 6.3e5 may exceed 65504 (the grazing view of a smooth surface): saturated
//     (V finite), so D · V is finite or +inf, never NaN (D finite), and saturated in turn.
// Fp16Anisotropy.HighAbove50DbAtItsHardCases renders the hard case fp16-emulated (docs/material-models.md).
// highp (`reference`): the same formula, saturateMediump an identity.
// Needs: math.glsl, precision.glsl, brdf_ggx.glsl (fresnel_schlick), anisotropy_frame.glsl.

// Resolves α_min across the brushing, as ggx_smith does (its half vector formed at highp:
// shading_standard.glsl, half_vector), in whatever tier takes this lobe.
#if !defined(SPECULAR_HALF_VECTOR_HIGHP)
#define SPECULAR_HALF_VECTOR_HIGHP 1
#endif

const float ANISOTROPY_V_SCALE = 128.0;  // 2^7: keeps V's lengths ≥ 1 and its denominator normal (above)

// Set once per pixel by anisotropy_setup, after anisotropy_frame.
vec3 shading_anisotropic_b;             // n × t
vec2 shading_anisotropy_inverse_alpha;  // (1/α_t, 1/α_b)
vec2 shading_anisotropy_scaled_alpha;   // 128 (α_t, α_b)
float shading_anisotropy_d_scale;       // 1/(π α_t α_b)
float shading_anisotropy_view_length;   // |128 (α_t t·v, α_b b·v, n·v)|

void anisotropy_setup(MaterialInputs material, float alpha, vec3 n, float NoV, vec3 v) {
    shading_anisotropic_b = cross(n, shading_anisotropic_t);
    vec2 a = anisotropic_alpha(material, alpha);
    shading_anisotropy_inverse_alpha = 1.0 / a;
    shading_anisotropy_scaled_alpha = ANISOTROPY_V_SCALE * a;
    shading_anisotropy_d_scale = INV_PI * (shading_anisotropy_inverse_alpha.x * shading_anisotropy_inverse_alpha.y);
    vec2 tb = vec2(dot(shading_anisotropic_t, v), dot(shading_anisotropic_b, v));
    shading_anisotropy_view_length = length(vec3(shading_anisotropy_scaled_alpha * tb, ANISOTROPY_V_SCALE * NoV));
}

// D_aniso · V_aniso, saturated (the caller multiplies by F).
float anisotropic_ggx_smith(float NoV, float NoL, float NoH, vec3 l, vec3 h) {
    vec2 x = vec2(dot(shading_anisotropic_t, h), dot(shading_anisotropic_b, h)) * shading_anisotropy_inverse_alpha;
    float q = 1.0 / (dot(x, x) + NoH * NoH);
    float D = (shading_anisotropy_d_scale * q) * q;
    vec2 tb = vec2(dot(shading_anisotropic_t, l), dot(shading_anisotropic_b, l));
    float lightLength = length(vec3(shading_anisotropy_scaled_alpha * tb, ANISOTROPY_V_SCALE * NoL));
    float V = saturateMediump((0.5 * ANISOTROPY_V_SCALE) / (NoL * shading_anisotropy_view_length + NoV * lightLength));
    return saturateMediump(D * V);
}
