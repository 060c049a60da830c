// GGX D times Hammon's height-correlated Smith visibility, the whole specular scalar with ONE
// division; Fresnel is taken as f0, applied by the caller (spec · f0):
//   spec = D · V = α² / (d² · X),   X = 2π · M,   M = mix(2 NoL NoV, NoL + NoV, α)
//   d = |n × h|² + (α NoH)²   (the GGX denominator NoH²(α² − 1) + 1 by the Lagrange identity)
// Sources: V = 0.5 / M is Hammon's approximation (GDC 2017, "PBR Diffuse Lighting for GGX+Smith
// Microsurfaces"; brdf_ggx_fastv.glsl); writing D·V as k · (k · X) with k = α / (d X) is the
// single-division fusion of Zioma ("Optimizing PBR", SIGGRAPH 2015), here applied to Hammon's V
// instead of Zioma's Kelemen-style V·F = 1 / (4 LoH² (r + 0.5)).
// Why: the Kelemen term has no 1/(n·v n·l) growth, so a rough lobe seen along the light
// (retro-reflection, l ≈ v) fades to 0 at the rim where the exact lobe tends to 1/(4α); Hammon's
// V keeps that growth. F = f0 is exact at l·h = 1 and near it for metals; it drops Schlick's
// rise at grazing l·h (the grazing view of a dielectric). Measured in docs/specular-tiers.md.
// fp16 (mediump), for α ≥ 0.089² (MIN_PERCEPTUAL_ROUGHNESS) and d ∈ [α², 1]:
//   - M is floored at 2^-12 (it only gets there for α n·v < 2^-12, far past the grazing peak),
//     so X ≥ 2π·2^-12 = 1.5e-3 is a normal number;
//   - d is formed scaled, d' = 2^12 d ∈ [0.257, 4096] (ggx_denominator.glsl: unscaled, the squares
//     of n × h flush to 0 in the highlight's core of a smooth lobe, and F = 1 reflected 1.48× its
//     light at r = 0.089); d X alone can fall below 2^-14 (d = α² = 6.27e-5, X < 1), d' X ∈
//     [0.257 · 1.5e-3, 4096 · 4π] = [3.9e-4, 51472] is normal and finite, the numerator 2^12 α ≤ 4096;
//   - k · X = α / d ≤ 1/α ≤ 127, so k · (k · X) overflows only where the true value exceeds
//     65504 (the grazing mirror peak, 1/(α² X)); saturateMediump then returns 65504 (k itself may
//     be inf there; X > 0, so never NaN). (k · k) · X would overflow for k > 256 first.
//   - 2 NoL NoV flushes to 0 below 2^-14 (n·l = n·v < 0.0055): M then loses at most 2^-14
//     against its α(NoL + NoV), a few percent only for a light within 0.3° of the horizon.
// tests/compiler/test_fp16.cpp (FusedHammonGlintFollowsItsFormulaAtGrazingMirror) fails without either.
// Needs: math.glsl, precision.glsl.

#include "ggx_denominator.glsl"

const float FUSED_HAMMON_M_MIN = 2.44140625e-4;   // 2^-12, the floor of M (above)

float specular_fused_hammon(float alpha, float NoV, float NoL, float NoH, vec3 n, vec3 h) {
    float d = ggx_d_scaled(alpha, NoH, n, h);  // 2^12 (|n × h|² + (α n·h)²)
    float m = max(mix(2.0 * NoL * NoV, NoL + NoV, alpha), FUSED_HAMMON_M_MIN);
    float k = (GGX_D_SCALE2 * alpha) / (d * ((2.0 * PI) * m));
    return saturateMediump(k * (k * ((2.0 * PI) * m)));
}

// Specular lobe of the `fused_hammon` tiers (mid): f_s = specular_fused_hammon(...) · f0.
vec3 specular_lobe(float perceptualRoughness, float alpha, float NoV, float NoL, float NoH, float LoH,
                   vec3 n, vec3 v, vec3 l, vec3 h, vec3 f0) {
    return specular_fused_hammon(alpha, NoV, NoL, NoH, n, h) * f0;
}
