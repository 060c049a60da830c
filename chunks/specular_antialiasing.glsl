// Specular anti-aliasing (FACET_SPECULAR_AA, materials with `specularAntiAliasing { }`): Y. Tokuyoshi
// and A. S. Kaplanyan, "Improved Geometric Specular Antialiasing" (I3D 2019), projected-space NDF
// filtering, in the form Filament ships (R. Guy and M. Agopian, "Physically Based Rendering in
// Filament", "Specular anti-aliasing"):
//   σ²  = variance · (|∂n/∂x|² + |∂n/∂y|²)          n: the final world shading normal, map applied
//   α'² = min(α² + min(2σ², threshold), 1),        α = r², r the clamped perceptual roughness
//   r'  = (α'²)^(1/4)
// The normals a pixel's footprint covers, seen as a Gaussian of slopes in the projected space of
// the NDF, widen GGX's lobe: their variances add to α². The screen-space derivatives of n give
// that spread (their 2×2 quad's finite differences); threshold bounds what the kernel adds at
// silhouettes and seams, where n jumps and the derivative is not a spread. variance and threshold
// are the material's (FACET_SPECULAR_AA_VARIANCE, FACET_SPECULAR_AA_THRESHOLD, each in [0, 1]).
// The derivatives are taken by the generated main(), in uniform control flow after the surface
// program: a material cannot take them inside a branch (GLSL ES 3.00 §8.13.1 leaves that undefined).
//
// fp16 (mediump): n is a unit vector, so each component of ∂n/∂x and ∂n/∂y is in [−2, 2] and the
// sum of squares is at most 8: no overflow. α² ≥ 0.089⁴ = 6.27e-5 ≥ 2^-14 (precision.glsl's floor,
// r ≥ 2^(−14/4)) and the kernel only adds, so α'² stays a normal fp16 number in [6.27e-5, 1] and
// r' in [0.089, 1]: the floor every lobe relies on holds after filtering. Squares below 2^-14
// (a normal turning by less than 2^-7 rad per pixel) would flush to 0 in fp16 and lose up to
// 2 · variance · 6 · 2^-14 ≤ 7.4e-4 of α², more than α² itself at the floor: hence highp below.
// The kernel is formed in highp: a smooth lobe's α² is as small as 6.27e-5, so squares that fp16
// would flush (below 2^-14) are a large part of what it adds, and a GPU that runs mediump in fp16
// would filter differently from one that runs it in fp32.
float specular_aa_roughness(float perceptualRoughness, vec3 normal) {
    highp vec3 du = dFdx(normal);
    highp vec3 dv = dFdy(normal);
    highp float variance = FACET_SPECULAR_AA_VARIANCE * (dot(du, du) + dot(dv, dv));
    highp float alpha = perceptualRoughness * perceptualRoughness;
    highp float kernel = min(2.0 * variance, FACET_SPECULAR_AA_THRESHOLD);
    return sqrt(sqrt(min(alpha * alpha + kernel, 1.0)));
}
