// Dithering before 8-bit quantisation: noise of triangular distribution over (−1, 1) output steps
// added to the encoded colour, so a gradient flatter than one 8-bit step per pixel is drawn as a
// mix of its two neighbouring levels in proportion instead of as bands, and the error it leaves
// is independent of the signal (a triangular PDF of 2 LSB width makes the error's mean and
// variance independent of the value: Lipshitz, Wannamaker & Vanderkooy, "Quantization and
// Dither: A Theoretical Survey", JAES 1992).
// Noise: interleaved gradient noise, fract(52.9829189 · fract(dot(p, (0.06711056, 0.00583715))))
// (J. Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH
// 2014): uniform over a pixel's neighbours, no texture fetch. The second sample reads the pattern
// transposed (and shifted), which is uncorrelated with the first, so their sum minus 1 is
// triangular over (−1, 1); a sample at a mere offset is not (its sum stays within ±0.55).
// Precision: highp. Pixel coordinates reach 4096 and the products need 2^-12 of fraction after
// it, beyond fp16's 11 significant bits; on mediump the noise would collapse into a few values.
highp float interleaved_gradient_noise(highp vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// `encoded` in [0, 1], to be stored in an 8-bit UNORM target.
vec3 dither_triangular_8bit(vec3 encoded, highp vec2 pixel) {
    highp float n = interleaved_gradient_noise(pixel) + interleaved_gradient_noise(pixel.yx + vec2(17.0, 31.0)) - 1.0;
    return encoded + vec3(n / 255.0);
}
