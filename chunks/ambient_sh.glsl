// Diffuse ambient from spherical harmonics: irradiance / π of the environment at normal n,
// Ramamoorthi & Hanrahan 2001's clamped-cosine convolution with every constant folded on the CPU
// (facet::ibl::shaderIrradianceCoefficients; docs/ibl.md, "SH coefficient convention"):
//   E(n)/π = max(Σ_k c_k p_k(n), 0),  p = 1, y, z, x | xy, yz, 3z² − 1, xz, x² − y²
// FACET_SH_BANDS 2 sums the first four terms (the talks' cheapest ambient: Filament mobile talk,
// "Spherical harmonics", 2 or 3 bands; Zioma 2015's low-end 2nd-order SH), 3 all nine, 5 also
// band 4's nine (l = 0..4; band 3 is zero under the clamped cosine, Â_3 = 0, and band 4's
// Â_4 = −π/24 is folded into its c_k), in frame.sh[9..17]:
//   xy(x² − y²), yz(3x² − y²), xy(7z² − 1), yz(7z² − 3), 35z⁴ − 30z² + 3, xz(7z² − 3),
//   (x² − y²)(7z² − 1), xz(x² − 3y²), x²(x² − 3y²) − y²(3x² − y²)
// (an option `matc eval` measures against its ground truth: sh_bands=5; no preset selects it). The max()
// removes the negative lobes SH ringing gives opposite a bright source. Lambert is then
// diffuseColor · E/π: no π in the shader.
// fp16: c_k arrive pre-exposed (O(1), the lights' contract) and are copied into tier-precision
// locals so the sum runs at the stage's precision; n is a unit vector, each p_k ∈ [−1, 2] for
// SH3, band 4's within [−6, 8] (35z⁴ − 30z² + 3 at z = ±1 is 8; the others are ≤ 6 in
// magnitude). Band 4's sum is bounded by the addition theorem: Σ_m c_4m p_4m(n) =
// (Â_4/π) ∫ L(d) (9/4π) P_4(n·d) dω, |P_4| ≤ 1, so |Σ| ≤ (1/24) · 9 · mean L = 0.375 c_0 — each
// term and the sum stay as finite in fp16 as c_0, the environment's mean radiance, is.

vec3 sh_irradiance_over_pi(vec3 n) {
    vec3 c0 = frame.sh[0].rgb;
    vec3 c1 = frame.sh[1].rgb;
    vec3 c2 = frame.sh[2].rgb;
    vec3 c3 = frame.sh[3].rgb;
    vec3 e = c0 + c1 * n.y + c2 * n.z + c3 * n.x;
#if FACET_SH_BANDS > 2
    vec3 c4 = frame.sh[4].rgb;
    vec3 c5 = frame.sh[5].rgb;
    vec3 c6 = frame.sh[6].rgb;
    vec3 c7 = frame.sh[7].rgb;
    vec3 c8 = frame.sh[8].rgb;
    e += c4 * (n.x * n.y) + c5 * (n.y * n.z) + c6 * (3.0 * n.z * n.z - 1.0) + c7 * (n.x * n.z) +
         c8 * (n.x * n.x - n.y * n.y);
#endif
#if FACET_SH_BANDS > 3
    vec3 c16 = frame.sh[9].rgb;
    vec3 c17 = frame.sh[10].rgb;
    vec3 c18 = frame.sh[11].rgb;
    vec3 c19 = frame.sh[12].rgb;
    vec3 c20 = frame.sh[13].rgb;
    vec3 c21 = frame.sh[14].rgb;
    vec3 c22 = frame.sh[15].rgb;
    vec3 c23 = frame.sh[16].rgb;
    vec3 c24 = frame.sh[17].rgb;
    float xx = n.x * n.x;
    float yy = n.y * n.y;
    float zz = n.z * n.z;
    float xy = n.x * n.y;
    float yz = n.y * n.z;
    float xz = n.x * n.z;
    e += c16 * (xy * (xx - yy)) + c17 * (yz * (3.0 * xx - yy)) + c18 * (xy * (7.0 * zz - 1.0)) +
         c19 * (yz * (7.0 * zz - 3.0)) + c20 * ((35.0 * zz - 30.0) * zz + 3.0) + c21 * (xz * (7.0 * zz - 3.0)) +
         c22 * ((xx - yy) * (7.0 * zz - 1.0)) + c23 * (xz * (xx - 3.0 * yy)) +
         c24 * (xx * (xx - 3.0 * yy) - yy * (3.0 * xx - yy));
#endif
    return max(e, vec3(0.0));
}
