// Diffuse ambient from spherical harmonics: irradiance / π of the environment at normal n,
// Ramamoorthi & Hanrahan 2001's clamped-cosine convolution with every constant folded on the CPU
// (facet::ibl::shaderIrradianceCoefficients; docs/ibl.md, "SH coefficient convention"):
//   E(n)/π = max(Σ_k c_k p_k(n), 0),  p = 1, y, z, x | xy, yz, 3z² − 1, xz, x² − y²
// FACET_SH_BANDS 2 sums the first four terms (the talks' cheapest ambient: Filament mobile talk,
// "Spherical harmonics", 2 or 3 bands; Zioma 2015's low-end 2nd-order SH), 3 all nine. The max()
// removes the negative lobes SH ringing gives opposite a bright source. Lambert is then
// diffuseColor · E/π: no π in the shader.
// fp16: c_k arrive pre-exposed (O(1), the lights' contract) and are copied into tier-precision
// locals so the sum runs at the stage's precision; n is a unit vector, each p_k ∈ [−1, 2].

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
    return max(e, vec3(0.0));
}
