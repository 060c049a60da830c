// The post pass's settings as a scene gives them (docs/scene-format.md, "post"): which effects,
// the colour grading and the vignette. Plain values, so that the scene reader and the renderer
// that applies them (render_path.h, color_grading.h, vignette.h) share them without either
// linking the other.
#pragma once

#include <array>
#include <string>

// In the runtime's namespace, as scene.h's types are (scene.h says why).
namespace facet::runtime {

// The effects a backend's post pass runs: a post variant compiled in at build time (compiler/post.h
// PostEffects, docs/runtime.md). Per renderer, not per frame: a pipeline is built for it once.
struct PostSettings {
  std::string toneCurve = "aces";  // "aces" (filmic) | "neutral" (Khronos PBR Neutral) | "none"
  bool dither = false;             // triangular noise of ±1 step before 8-bit quantisation
  bool colorGrading = false;       // the encoded colour through FrameDesc::colorLut (3D LUT)
  bool vignette = false;           // darker corners, from FrameDesc::postUniforms
  bool bloom = false;              // the bloom chain (BloomSettings) composited before the tone curve
  bool operator==(const PostSettings&) const = default;
};

// The grading a scene asks for, applied in this order to the display-referred linear colour (the
// LUT, buildColorLut in color_grading.h, decodes its sRGB input first and encodes its output again):
struct ColorGradingSettings {
  // White balance, each in [−1, 1], 0 neutral. The scene's white is taken to be a chromaticity on
  // the daylight locus shifted by `temperature` (> 0: a bluer white, so the image warms) and off it
  // by `tint` (> 0: a greener white, so the image turns magenta), and adapted to D65 by a von
  // Kries scaling in the Bradford cone space (K. M. Lam, 1985; the CAT of ICC v4 and CIECAM97s).
  double temperature = 0;
  double tint = 0;
  // Lift / gamma / gain per channel (ASC-style primary correction on linear values):
  // c = gain · (c + lift · (1 − c)), then c^(1 / gamma).
  std::array<double, 3> lift{0, 0, 0};
  std::array<double, 3> gamma{1, 1, 1};
  std::array<double, 3> gain{1, 1, 1};
  // Contrast around middle grey in log space: c = 0.18 · (c / 0.18)^contrast (1 neutral).
  double contrast = 1;
  // Saturation around Rec.709 luminance: c = Y + saturation · (c − Y) (1 neutral, 0 grey).
  double saturation = 1;
};

// The vignette (chunks/vignette.glsl has the formula; postUniforms in vignette.h makes its block).
struct VignetteSettings {
  double intensity = 0.5;   // in [0, 1]: how much the corners lose (1: black)
  double radius = 0.8;      // distance from the centre where darkening starts (1: the top edge)
  double smoothness = 0.8;  // width of the transition beyond the radius
  double roundness = 1;     // in [0, 1]: 1 a circle on screen, 0 an ellipse fitting the frame
};

// Bloom (chunks/bloom.glsl has the filters and the composite; render_path.h the chain's images).
inline constexpr int kMaxBloomLevels = 12;  // the mip count of the quarter-resolution image of 4096 × 4096
struct BloomSettings {
  // In [0, 1]: the fraction of each pixel's light (of its part above the threshold) spread over
  // the chain's blur: hdr + intensity · (bloom − bright(hdr)), which keeps the frame's energy.
  double intensity = 0.1;
  // 1..kMaxBloomLevels: images in the chain from a quarter of the HDR image's pixels; each level
  // doubles the radius. A frame too small for them renders as many as its first image has mips.
  int levels = 6;
  // ≥ 0, 0: none. The brightest channel's value from which a pixel blooms (soft knee of t / 2).
  double threshold = 0;
};

}  // namespace facet::runtime
