// ACES filmic tone curve, fitted: f(x) = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14)
// Source: K. Narkowicz, "ACES Filmic Tone Mapping Curve" (2015), a rational fit of the ACES
// RRT+ODT; Filament offers it among its mobile tone mappers.
// fp16: the input is pre-exposed (≈1 at middle grey × 5), so x² stays far below 65504 for any
// x < 160; the clamp keeps a stray very bright value from overflowing the product in mediump.
// 160 = sqrt(65504 / 2.51), rounded down.
vec3 tonemap_aces_fitted(vec3 x) {
    x = clamp(x, 0.0, 160.0);
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
