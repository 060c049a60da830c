// Analytic environment BRDF (the mid tier): B. Karis, "Physically Based Shading on Mobile"
// (2014), a fit after D. Lazarov's 2013 one, replacing the DFG table by a few ALU ops:
//   k = r · (−1, −0.0275, −0.572, 0.022) + (1, 0.0425, 1.04, −0.04)
//   s = min(k.x², 2^(−9.28 n·v)) · k.x + k.y
//   f0 · A + B = f0 · (−1.04 s + k.z) + (1.04 s + k.w)
// Mirrors facet::ibl::envBrdfKaris. Against the 64 × 64 DFG table (docs/ibl.md): mean abs error
// 0.014 for f0 = 0.04, 0.11 for f0 = 1 (flat in n·v where the height-correlated albedo is not).
// Zioma ("Optimizing PBR", SIGGRAPH 2015, "Environment BRDF") cites it as the
// ALU-over-texture choice for GPUs with a high ALU:TEX ratio.
// fp16: every term is in [−0.1, 1.1]; exp2(−9.28 n·v) ≥ 2^-9.28 is a normal fp16 number.
vec3 env_brdf_karis(vec3 f0, float NoV, float perceptualRoughness) {
    vec4 k = perceptualRoughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
    float s = min(k.x * k.x, exp2(-9.28 * NoV)) * k.x + k.y;
    vec2 ab = vec2(-1.04, 1.04) * s + k.zw;
    return f0 * ab.x + ab.y;
}
