// Diffuse ambient from the irradiance cube (the `cube` diffuse, permutations::DiffuseModel::Cube):
//   E(n)/π = textureLod(facet_irradiance, n, 0)
// an irradiance environment map (Ramamoorthi & Hanrahan 2001, "An Efficient Representation for
// Irradiance Environment Maps"; SH3's own error, 5.15 % of the peak on docs/ibl.md's bright cap) tabulated from the same SH3 sum as
// ambient_sh.glsl, max(Σ_{k<9} c_k p_k(n), 0), which the runtime evaluates at
// each texel's centre direction (runtime::irradianceTexture; abi::kIrradianceMapSize² a face) and
// the sampler interpolates bilinearly, across faces: one texture read on the texture pipe in place
// of the sum's 9 RGB multiply-adds and 5 quadratic terms on the FMA pipe (docs/ibl.md, "In the
// shaders", has its error; docs/eval.md, "The irradiance cube", its Mali-G57 cycles).
// fp16: the texels are RGBA16F of pre-exposed irradiance / π (O(1), the lights' contract), the
// direction is the tier's precision and need not be unit length (a cube lookup takes ratios,
// environment_cube.glsl). Level 0 only: no derivative is taken.
vec3 cube_irradiance_over_pi(vec3 n) {
    return textureLod(facet_irradiance, n, 0.0).rgb;
}
