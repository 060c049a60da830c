// Tangent-space normal mapping: the material's `normal` output (tangent space, (0, 0, 1) = the
// interpolated normal) is taken to world space by the per-pixel tangent frame
//   b = w · cross(n, t),   n_shading = normalize(x·t + y·b + z·n)
// with n and t the interpolated vertex normal and tangent, w the tangent's handedness sign.
// Source: MikkTSpace (Mikkelsen 2008, "Simulation of Wrinkled Surfaces Revisited"); its pixel
// shader recipe keeps n and t unnormalized after interpolation so the frame matches the one a
// baker used, and normalizes only the result. Precision: mediump is enough (unit vectors, 8-bit
// maps carry about 1/128 of resolution); a zero tangent falls back to the interpolated normal
// instead of normalizing a zero vector (NaN).
// Needs: v_normal, v_tangent (FACET_VARYING_TANGENT).

vec3 tangent_to_world(vec3 tangentNormal) {
    vec3 n = v_normal;
    vec3 t = v_tangent.xyz;
    if (dot(t, t) == 0.0) return normalize(n);
    vec3 b = v_tangent.w * cross(n, t);
    return normalize(tangentNormal.x * t + tangentNormal.y * b + tangentNormal.z * n);
}
