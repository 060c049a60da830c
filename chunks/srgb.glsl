// sRGB transfer functions, IEC 61966-2-1:1999 (piecewise: linear toe below 0.0031308).
// fp16: inputs are in [0, 1]; pow of a value in [0.0031308, 1] is well conditioned in mediump
// and the 8-bit output step (1/255) is far above fp16's 2^-11 relative precision.
vec3 srgb_from_linear(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 lo = c * 12.92;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(lo, hi, step(vec3(0.0031308), c));
}
