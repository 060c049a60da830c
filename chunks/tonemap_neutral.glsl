// Neutral tone curve for display: Khronos PBR Neutral (E. Lalish, Khronos 3D Formats WG, 2024,
// "Khronos PBR Neutral Tone Mapper"). Unlike a filmic curve it keeps hue and saturation of
// everything below the compression start: a base colour lit at 1.0 shows as authored, which is
// what product and e-commerce viewers (the mobile case the spec was written for) need.
//   toe:   x = min(r, g, b);  offset = x < 0.08 ? x − 6.25 x² : 0.04;  c −= offset
//          (a smooth black level: 6.25 = 1 / (4 · 0.04), so offset and its slope are continuous at 0.08)
//   knee:  peak = max(c); below s = 0.8 − 0.04 the colour is unchanged; above it the peak is
//          compressed to p' = 1 − d² / (peak + d − s), d = 1 − s (a hyperbola tangent to y = x at s,
//          approaching 1), every channel scaled by p' / peak;
//   fade:  mixed towards white by g = 1 − 1 / (0.15 · (peak − p') + 1), so very bright colours desaturate.
// fp16: the input is pre-exposed and clamped to 1024 first. At 1024, p' = 1 − 0.0576 / 1023.2 and
// g > 0.99, white to 8 bits, so a brighter input could not change the output; the clamp keeps
// peak + d − s and 0.15 · (peak − p') far inside mediump. x² only runs below 0.08.
vec3 tonemap_khronos_neutral(vec3 c) {
    const float kStart = 0.76;          // 0.8 − 0.04
    const float kKnee = 1.0 - kStart;   // d
    const float kDesaturation = 0.15;
    c = clamp(c, 0.0, 1024.0);
    float low = min(c.r, min(c.g, c.b));
    float offset = low < 0.08 ? low - 6.25 * low * low : 0.04;
    c -= offset;
    float peak = max(c.r, max(c.g, c.b));
    if (peak < kStart) return c;
    float compressed = 1.0 - kKnee * kKnee / (peak + kKnee - kStart);
    c *= compressed / peak;
    float toWhite = 1.0 - 1.0 / (kDesaturation * (peak - compressed) + 1.0);
    return mix(c, vec3(compressed), toWhite);
}
