// Octahedral coordinates of a world direction, the layout of facet_environment (docs/ibl.md,
// "Conventions"; facet::ibl::octahedralCoordinates on the CPU; Praun & Hoppe 2003, Cigolle et
// al. 2014 — the layout HypeHype's mobile renderer uses for its normals, seeds/hypehype-siggraph2024.txt):
//   p = d.xz / (|d.x| + |d.y| + |d.z|),  if d.y < 0: p = (1 − |p.yx|) · sgn(p)
//   (u, v) = p / 2 + 1/2            (+y at the centre, −y at the four corners)
// It replaces the equirect lookup's highp atan + acos (0.34 Mali cycles per lookup, issue 10) by
// one reciprocal, a fold and a few adds. sgn(0) = +1 (a select, not sign(), which gives 0 and would
// send the folded ±x/±z axes to the centre). The sampler clamps to the edge; the runtime's map
// holds the edge direction in its outer texels (facet::ibl::octahedralTexelDirection), so the
// bilinear clamp is continuous across the folds at every level: no seam, no gutter, no fract().
// Precision: the tier's (mediump on mobile tiers), unlike the equirect lookup it replaces, whose
// acos needed highp near the poles. Here every step is an add, an abs or a product of values in
// [−1, 1], and the one division is by |x| + |y| + |z| ∈ [1, √3] for a unit d: fp16 keeps u and v
// within about 2^-11, 1/16 of a texel of the 128² map. Measured on the roughness grid under fp16
// emulation (Tiers.RoughnessGrid…, analytic sky): high 65.4 dB against reference with this
// mediump lookup, 65.7 dB with it highp. d need not be unit length but must not be 0 (a
// reflected unit vector never is).
vec2 octahedral_uv(vec3 d) {
    vec2 p = d.xz / (abs(d.x) + abs(d.y) + abs(d.z));
    if (d.y < 0.0) {
        vec2 signs = vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
        p = (1.0 - abs(p.yx)) * signs;
    }
    return p * 0.5 + 0.5;
}

// The prefiltered environment's last level: level m holds perceptual roughness m / (levels − 1)
// (facet::ibl::prefilterLevelRoughness), FACET_ENVIRONMENT_LEVELS set by the assembler.
#define ENVIRONMENT_MAX_LOD float(FACET_ENVIRONMENT_LEVELS - 1)
