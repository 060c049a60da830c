// Colour grading through a 3D lookup table of N³ texels (N = FACET_COLOR_LUT_SIZE, printed from
// shader_abi.h kColorLutSize), built on the CPU from the scene's settings (white balance,
// contrast, saturation, lift/gamma/gain) or loaded from an Adobe/Resolve .cube file
// (runtime/color_grading.h); HypeHype's mobile post stack grades the same way, one LUT built on
// the CPU whenever a slider moves (Aaltonen, "Transitioning HypeHype to Physically Based
// Rendering", SIGGRAPH 2024).
// Where: after the tone curve and the sRGB encoding, on display-referred values in [0, 1]. A
// lattice needs a bounded domain, which HDR is not; and the encoded values spread the lattice
// evenly in perceived lightness (on linear input half of the 32 points would go to the
// brightest stop and the shadows would get four), which is also how .cube files for SDR
// displays are authored (sRGB/Rec.709-encoded in and out).
// Texture: a sampler3D (core in GLES 3.0 and Vulkan), so the lookup is one hardware-trilinear
// fetch; a 2D strip of N slices would need two bilinear fetches and a blend between slices.
// Lookup: lattice point i lies at the texel centre (i + 0.5) / N,
// so [0, 1] maps onto [0.5/N, 1 − 0.5/N]: coord = c·(N − 1)/N + 0.5/N (J. Selan, "Using Lookup
// Tables to Accelerate Color Transformations", GPU Gems 2, ch. 24, 2005).
// fp16: the coordinate's error (2^-11 near 1 in mediump) is 1/64 of a texel at N = 32; texels are
// RGBA16F (2^-11 relative, 1/8 of an 8-bit step). Filtering weights have the GPU's fixed-point
// subTexelPrecisionBits (8 on lavapipe, queried; Vulkan guarantees 4): with 8, a linear LUT is
// interpolated to within 1/256 of a lattice step, 1/8000 of the range; with 4, 1/500 (half a step).
vec3 grade_color_lut(mediump sampler3D lut, vec3 encoded) {
    const float n = float(FACET_COLOR_LUT_SIZE);
    vec3 coord = clamp(encoded, 0.0, 1.0) * ((n - 1.0) / n) + 0.5 / n;
    return texture(lut, coord).rgb;
}
