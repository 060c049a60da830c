// The vector to the eye of the tiers that read it mediump (FACET_VIEW_VECTOR_MEDIUMP; which ones:
// compiler/src/assemble.cpp, viewVectorMediump). The vertex stage forms camera − position in highp
// and sends it scaled by VIEW_VECTOR_SCALE; the fragment stage normalizes it in binary16.
//
// normalize(v) = v · inversesqrt(v·v), and binary16 holds v·v as a normal number only within
// [2^-14, 65504], so |v| must lie in [2^-7, 255.9]: unscaled, every surface beyond 256 m from
// the eye overflowed to +inf and its view vector came out 0. Scaled by 2^-4, |v| from 0.125 m
// (2^-7 · 2^4) to 4094 m (255.9 · 2^4) keeps 11 significant bits in every step. A power of two is
// exact in the highp product and normalize cancels it; constant over the frame, it keeps the
// varying affine in the position, so its interpolation stays exact.
//
// Closer than 0.125 m the square is subnormal (2^-14.6 at the default 0.1 m near plane), which a
// GPU that flushes fp16 subnormals makes 0: inversesqrt(0) = +inf and v · inf is not finite.
// view_direction clamps the square at 2^-14 instead, so such a surface gets a finite view vector
// |v| / 0.125 m long (0.8 at 0.1 m). A component of the varying below 2^-14 may flush too, which
// turns it by at most √3 · 2^-14 / (2^-4 |v|): 0.017 rad at 0.1 m, 0.17 at 0.01 m. On Mali-G57
// (Mesa) the clamp lands on the conversion pipe, not the FMA pipe that bounds mid and low: no cycle.
// The fp16 hard cases render a surface 3 km away (tests/compiler/test_fp16.cpp, far_from_camera).
const highp float VIEW_VECTOR_SCALE = 0.0625;   // 2^-4
const float VIEW_VECTOR_MIN_SQUARE = 6.103515625e-05;  // 2^-14, binary16's smallest normal number

vec3 view_direction(vec3 scaledToEye) {
    return scaledToEye * inversesqrt(max(dot(scaledToEye, scaledToEye), VIEW_VECTOR_MIN_SQUARE));
}
