// Occlusion of the ambient terms from the material's ambientOcclusion (the visibility V ∈ [0, 1]),
// in materials that write it (FACET_MATERIAL_AMBIENT_OCCLUSION); shading_ambient.glsl applies it.

// Multi-bounce AO (Jimenez, Wu, Pesce & Jarabo 2016, "Practical Realtime Strategies for Accurate
// Indirect Occlusion", their cubic fit of ground-truth interreflected visibility in albedo ρ):
//   V' = max(V, ((a·V + b)·V + c)·V),  a = 2.0404ρ − 0.3324, b = −4.7951ρ + 0.6417, c = 2.7552ρ + 0.6903
// Light that bounces between the occluders and a bright surface comes back: V' ≥ V, more the
// brighter ρ; for ρ = 0 the fit is below V and the max keeps V. At V = 1 the fit is
// 0.9996 + 0.0005ρ: V' ∈ [1, 1.0001], below a step of an 8-bit image.
// fp16: ρ, V ∈ [0, 1]; a ∈ [−0.34, 1.71], b ∈ [−4.16, 0.65], c ∈ [0.69, 3.45], the Horner terms
// within ±4.2: no overflow; terms of magnitude up to 4 cancelling to ~1 leave an absolute error of
// a few ulp at 4 (2^-8 each), ~0.004 in V' under fp16. Three FMAs per channel after the three that
// form a, b, c.
vec3 multi_bounce_ao(float visibility, vec3 albedo) {
    vec3 a = 2.0404 * albedo - 0.3324;
    vec3 b = -4.7951 * albedo + 0.6417;
    vec3 c = 2.7552 * albedo + 0.6903;
    return max(vec3(visibility), ((visibility * a + b) * visibility + c) * visibility);
}

// Specular occlusion from AO (Lagarde & de Rousiers 2014, "Moving Frostbite to Physically Based
// Rendering", §4.10.2, their fit, α = perceptual roughness²):
//   S = saturate((n·v + V)^e − 1 + V),  e = 2^(−16α − 1)
// A smooth lobe at grazing view sees less of the unoccluded cone than the diffuse lobe does: S
// falls below V there. S ≤ (1 + e)·V (as (n·v + V)^e ≤ 1 + e·V): S → 0 as V → 0; S = 1 at V = 1.
// pow is written as exp2(e·log2 x): two transcendental ops (what the mobile cost model counts for a
// pow, docs/eval.md), the exponent's exp2 a third. x = n·v + V ≥ MIN_N_DOT_V > 0: log2 is finite.
// fp16: x ∈ (0, 2], log2 x ∈ [log2 MIN_N_DOT_V, 1] = [−13.3, 1]; e ∈ [2^-17, 0.46] (α ≥ 0.0079);
// e < 2^-14 (α > 0.81) is an fp16 subnormal: flushed to 0 it gives x^0 = 1 and S = V, off by at
// most e·|log2 x|·ln 2 < 2^-14 · 13.3 · 0.69 = 6e-4.
float specular_occlusion_lagarde(float NoV, float visibility, float alpha) {
    float exponent = exp2(-16.0 * alpha - 1.0);
    return clamp(exp2(exponent * log2(NoV + visibility)) - 1.0 + visibility, 0.0, 1.0);
}
