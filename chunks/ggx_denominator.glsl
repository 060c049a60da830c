// The GGX distribution's denominator, shared by every lobe that forms GGX's D from n and h (the
// standard lobes' brdf_ggx.glsl, specular_fused_hammon.glsl, specular_zioma.glsl and the clear
// coat's clear_coat_ggx_kelemen.glsl):
//   D = α² / (π d²),   d = (n·h)²(α² − 1) + 1 = |n × h|² + (α n·h)²   (Lagrange's identity)
// returned scaled (ggx_d_scaled): d' = 2^12 d = |2^6 (n × h)|² + (2^6 α n·h)², so D = (2^12 α / d')² / π.
// Sources: Walter et al. 2007, "Microfacet Models for Refraction" (GGX D); the cross-product form
// keeps the bits the textbook 1 − (n·h)² loses by cancellation for n·h within 2^-11 of 1 (the whole
// highlight core of a smooth surface in fp16).
// fp16 (mediump), for α ≥ 0.089² (MIN_PERCEPTUAL_ROUGHNESS: α² = 6.27e-5 ≥ 2^-14) and
// d ∈ [α², 1] (sin² θ_h + α² cos² θ_h, α ≤ 1):
//   - unscaled, the squares of t = n × h fall below binary16's smallest normal 2^-14 and are
//     flushed to 0 (most mobile GPUs flush fp16 subnormals; the fp16 emulation does) wherever
//     |t_i| < 2^-7, which at α = 0.0079 is the whole core of a smooth lobe's highlight: d read
//     (α n·h)² there and D its peak. Measured by `matc eval`'s white furnace of each lobe
//     (docs/eval.md, "The BRDF domain"): F = 1 at r = 0.089 reflected 1.48× its light (ggx_smith,
//     ggx_fastv, fused_hammon; zioma 1.47), and the clear coat 1.48×.
//   - scaled by 2^6 before squaring: d' ∈ [2^12 α², 2^12] = [0.257, 4096]; a flushed square
//     (< 2^-14) is ≤ 2.4e-4 of d'; a component of t itself below 2^-14, flushed, loses
//     < (2^6 · 2^-14)² = 2^-16, ≤ 6e-5 of d'; 2^6 |t_i| ≤ 64 and (2^6)² = 4096, far below 65504.
//   - callers divide 2^12 α ≤ 4096 by d' (times their visibility's X, each header bounds d' X).
// Scaling the cross product (not n before it) keeps cross(n, h) one expression for the base's D and
// the coat's (the coat measured +0.09 Mali-G57 cycles so, +0.17 scaling n). Cost: red_plastic's
// high.dir1 +0.08 Mali-G57 cycles, mid.dir1 +0.06 (docs/eval.md); (t, α n·h) as one 4-vector costs
// 1/64 cycle more than t and α n·h apart, which shipped three fragment variants over 8 KB.
// Needs: nothing.

// Defines, not consts: the shipped text keeps no declaration of them (every fragment variant ships
// at most 8 KB, tests/compiler/test_minify_glsl.cpp).
// 2^6, which keeps d's squares normal in fp16 (above), and 2^12 = GGX_D_SCALE², d' = GGX_D_SCALE2 · d.
#define GGX_D_SCALE 64.0
#define GGX_D_SCALE2 4096.0

#if defined(FACET_CLEAR_COAT_LOBE)
// d' = |2^6 (n × h)|² + (2^6 α n·h)²: under a clear coat the base's D and the coat's share their
// first term (the coat's normal is the base's unless the material writes `normal` or
// `clearCoatNormal`, and h is the light's), so it is one sum, not part of a 4-vector, and the
// shader compiler forms it once: car_paint's high.dir1 −0.08 Mali-G57 cycles
// (docs/material-models.md). 2^6 α is taken before n·h, where the compiler folds it (−0.03 against
// 2^6 (α n·h)). Same terms, same fp16 bounds.
float ggx_d_scaled(float alpha, float NoH, vec3 n, vec3 h) {
    vec3 t = GGX_D_SCALE * cross(n, h);
    float q = GGX_D_SCALE * alpha * NoH;
    return dot(t, t) + q * q;
}
#elif defined(FACET_HALF_VECTOR_SCALED)
// h and n·h arrive scaled by 2^6, folded into the half vector's normalization
// (shade_standard_direct): d' = |(n × h', α n·h')|² with h' = 2^6 h, the same terms. fp16: 2^6 is
// exact, so every term is the one above, and a component of n × h' is flushed only below 2^-14,
// where the form above flushed below 2^-14 before scaling.
float ggx_d_scaled(float alpha, float NoH, vec3 n, vec3 h) {
    vec4 t = vec4(cross(n, h), alpha * NoH);
    return dot(t, t);
}
#else
// d' = 2^12 (|n × h|² + (α n·h)²) = |2^6 (n × h, α n·h)|², one 4-vector.
float ggx_d_scaled(float alpha, float NoH, vec3 n, vec3 h) {
    vec4 t = GGX_D_SCALE * vec4(cross(n, h), alpha * NoH);
    return dot(t, t);
}
#endif
