// Height-correlated Smith visibility without square roots (the `ggx_fastv` specular):
//   V = 0.5 / mix(2 n·l n·v, n·l + n·v, α)
// Each √((n·x)²(1 − α²) + α²) of the exact V (brdf_ggx.glsl) is replaced by the lerp
// n·x (1 − α) + α, which agrees at α = 0 and α = 1 and is linear in between.
// Source: E. Hammon, "PBR Diffuse Lighting for GGX+Smith Microsurfaces", GDC 2017; Filament uses
// it on its mobile path only (Filament mobile talk, "no more square roots"). Error against the
// exact V and the sphere PSNR: docs/specular-tiers.md.
// fp16: the denominator is ≥ α · n·v when n·l = 0; with α ≥ 0.089² and n·v ≥ MIN_N_DOT_V that is
// 7.9e-7, below fp16's normal range, so 0.5/x may overflow: saturateMediump keeps it at 65504, and
// the caller's × n·l (= 0 there) removes it. For n·l, n·v ≥ 2^-7 the denominator is a normal fp16.
// Needs: precision.glsl.
float visibility_hammon(float alpha, float NoV, float NoL) {
    float v = 0.5 / mix(2.0 * NoL * NoV, NoL + NoV, alpha);
    return saturateMediump(v);
}
