// Cook-Torrance specular terms for the GGX microfacet model.
// Sources: Walter et al. 2007, "Microfacet Models for Refraction" (GGX D); Heitz 2014,
// "Understanding the Masking-Shadowing Function" (height-correlated Smith); Schlick 1994
// (Fresnel); the fp16 forms follow Filament's PBR document §4.4 and its mobile talk.
// Needs: math.glsl, precision.glsl.

#include "ggx_denominator.glsl"

// GGX normal distribution D(h) = α² / (π ((n·h)²(α² − 1) + 1)²), written with the Lagrange
// identity 1 − (n·h)² = |n × h|² as D = (α / d)² / π, d = |n × h|² + (α n·h)², formed scaled as
// d' = 2^12 d (ggx_denominator.glsl has why and the bounds): D = (2^12 α / d')² / π.
// fp16: the textbook form computes 1 − (n·h)², which cancels to 0 for n·h within 2^-11 of 1
// (the whole highlight core of a smooth surface); the cross product keeps those bits, and the
// scale keeps its squares normal where a GPU flushes subnormals. With α ≥ 0.089², d' ≥ 0.257 and
// k = 2^12 α / d' = α / d ≤ 1/α ≤ 127; the peak 1/(π α²) ≤ 5075 is finite; saturateMediump guards
// the rest.
float distribution_ggx(float alpha, float NoH, vec3 n, vec3 h) {
    float k = GGX_D_SCALE2 * alpha / ggx_d_scaled(alpha, NoH, n, h);
    return saturateMediump(k * k * INV_PI);
}

// Height-correlated Smith visibility V = G₂ / (4 n·l n·v):
//   V = 0.5 / (n·l √((n·v)²(1 − α²) + α²) + n·v √((n·l)²(1 − α²) + α²))
// fp16: n·v ≥ MIN_N_DOT_V and α² ≥ 6.27e-5 keep the denominator ≥ ~1e-4·α > 0 when n·l > 0.
float visibility_smith_ggx_correlated(float alpha, float NoV, float NoL) {
    float a2 = alpha * alpha;
    float lambdaV = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float lambdaL = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    return saturateMediump(0.5 / (lambdaV + lambdaL));
}

// Schlick's Fresnel F = f0 + (1 − f0)(1 − l·h)⁵ with f90 = 1; the fifth power by three
// multiplications, not pow(), which costs exp2+log2 on most mobile GPUs.
vec3 fresnel_schlick(vec3 f0, float LoH) {
    float f = 1.0 - LoH;
    float f2 = f * f;
    float f5 = f2 * f2 * f;
    return f0 + (vec3(1.0) - f0) * f5;
}
