// Specular intensity from a 2D table (the `lut` tier, for GPUs with a low ALU:TEX ratio):
//   spec ≈ S(R·L, r) = D_GGX(α, n·h') / 4,  n·h'² = (1 + R·L)/2,  R = reflect(−v, n)
// with the implicit geometric term (V = 1/4) and no Fresnel, each roughness row divided by its
// lobe's albedo A(r) (specular_lut_lobe.glsl multiplies by the environment BRDF's albedo instead
// of f0, and the caller by n·l, E_light). The table (compiler/specular_lut.h) stores √(S/A · π/16),
// saturated, in R8 UNORM, 128 × 64: u = max(R·L, 0)⁴ across, perceptual roughness down, texel
// (i, j) holding u_i = i/127, r_j = j/63; this function inverts that mapping and decodes with a
// square (one multiply): the √ puts the 8-bit steps in the lobe's tail, where the linear table's
// steps showed as rings (docs/specular-tiers.md, "The low tier's table"). Bilinear filtering acts
// on the encoded values: between two texels the decoded value is the square of their lerp, a
// little below the lerp of the squares (by f(1−f)(√a − √b)², under a step of the table).
// Source: R. Zioma, "Optimizing PBR", SIGGRAPH 2015 (LUT specular for the low tier: store
// intensity / 16, index by R·L as suggested by B. Karis, "Physically Based Shading on Mobile",
// 2014, warp the cosine axis with a power of 4 to give the highlight more texels). Measured in
// docs/specular-tiers.md: (R·L)⁴ beats an n·h axis, and folding π into the /16 was chosen there.
// fp16: RoL ∈ [0, 1] after the clamp, u = RoL⁴ ≥ 2^-14 for RoL ≥ 0.089 (smaller u only matter to
// the flat tail of the roughest lobes); the mediump coordinate (11 bits) addresses 1/16 of a texel
// of a 128-wide table. The input is the tighter limit: R·L from mediump vectors is good to about
// 2^-10, which du = 4 RoL³ dRoL makes up to about a texel near the highlight (docs/specular-tiers.md). textureLod(…, 0.0): the table has one mip, and implicit derivatives are not
// needed (and not available outside fragment shaders).
// The same 3 numbers are in compiler/specular_lut.h: kSpecularLutWidth, kSpecularLutHeight and
// kSpecularLutScale (16/π = 5.0929582).
const vec2 SPECULAR_LUT_SIZE = vec2(128.0, 64.0);
const float SPECULAR_LUT_SCALE = 5.0929582;

float specular_lut(mediump sampler2D lut, float RoL, float perceptualRoughness) {
    float c = clamp(RoL, 0.0, 1.0);
    float c2 = c * c;
    vec2 t = vec2(c2 * c2, perceptualRoughness);
    // t ∈ [0, 1]² onto the texel centres: t (n − 1)/n + 0.5/n, so t = 1 samples the last texel.
    vec2 uv = t * ((SPECULAR_LUT_SIZE - 1.0) / SPECULAR_LUT_SIZE) + 0.5 / SPECULAR_LUT_SIZE;
    float encoded = textureLod(lut, uv, 0.0).r;
    return encoded * encoded * SPECULAR_LUT_SCALE;
}
