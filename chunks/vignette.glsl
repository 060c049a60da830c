// Vignette: the frame darkens towards its corners, applied "on top at the end of the shader" (on
// the graded, encoded value, before dithering) as in HypeHype's single-pass mobile post stack
// (Aaltonen, "Transitioning HypeHype to Physically Based Rendering", SIGGRAPH 2024).
//   p = (2 · pixel / size − 1) · (mix(1, width / height, roundness), 1): the centre is 0, the top
//       and bottom edges are at |p.y| = 1; roundness 1 makes the falloff a circle on screen,
//       0 an ellipse fitting the frame (the side edges at |p.x| = 1 too);
//   factor = 1 − intensity · smoothstep(radius, radius + smoothness, |p|).
// Multiplying the encoded value scales perceived lightness (sRGB encoding is close to it), so
// intensity 0.5 reads as "half as light" in the corners whatever their colour.
// Precision: the pixel and the reciprocal size are highp (pixel coordinates reach 4096, beyond
// fp16's integers); |p| < 3 and the factor in [0, 1] are fine in mediump.
// params: x intensity, y radius, z smoothness, w roundness; viewport: x 1/width, y 1/height, z width/height.
float vignette_factor(highp vec2 pixel, highp vec4 viewport, vec4 params) {
    highp vec2 p = pixel * viewport.xy * 2.0 - 1.0;
    p.x *= mix(1.0, viewport.z, params.w);
    float d = length(vec2(p));
    return 1.0 - params.x * smoothstep(params.y, params.y + max(params.z, 1e-3), d);
}
