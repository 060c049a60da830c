// Colour grading on the CPU, API-neutral: the 3D lookup table the post pass samples
// (chunks/color_grading.glsl), built from grading settings or read from an Adobe/Resolve .cube
// file. The table maps the tone-mapped, sRGB-encoded colour in [0, 1]³ to the graded encoded
// colour; the GPU interpolates it trilinearly between kColorLutSize³ lattice points.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "facet/runtime/render_backend.h"
#include "facet/scene/post_settings.h"

namespace facet::runtime {

// A lattice of size³ RGB entries: entry (r, g, b) at index r + size · (g + size · b) (red
// fastest, the .cube order) holds the output for the input (r, g, b) / (size − 1) of the domain.
struct ColorLut {
  uint32_t size = 0;
  std::vector<float> rgb;  // 3 floats per entry
  std::array<float, 3> domainMin{0, 0, 0};
  std::array<float, 3> domainMax{1, 1, 1};
  std::string title;
};

// The LUT of `settings` at `size` lattice points per axis (2..64): identity settings give the
// identity table (to float rounding).
ColorLut buildColorLut(const ColorGradingSettings& settings, uint32_t size = abi::kColorLutSize);

// `lut` evaluated at size³ lattice points of [0, 1]³: its domain mapped, values between its own
// points interpolated trilinearly (as the GPU will). A table already of that size and of the unit
// domain is copied exactly; a linear table stays exactly linear.
ColorLut resampleColorLut(const ColorLut& lut, uint32_t size);

// The trilinear interpolation of `lut` at `rgb` (in its domain, clamped to it).
std::array<float, 3> sampleColorLut(const ColorLut& lut, const std::array<float, 3>& rgb);

// The post pass's texture: `lut` resampled to abi::kColorLutSize, as RGBA16F, alpha 1.
ColorLutTexels colorLutTexels(const ColorLut& lut);

// Adobe/Resolve .cube (Adobe "Cube LUT Specification" 1.0): TITLE, LUT_3D_SIZE (2..64 here),
// DOMAIN_MIN/DOMAIN_MAX (or Resolve's LUT_3D_INPUT_RANGE), # comments, then size³ lines of three
// finite numbers, red fastest. Errors read `<name>:<line>: error: ...`.
inline constexpr uint32_t kMaxCubeLutSize = 64;
inline constexpr uint64_t kMaxCubeFileBytes = 16u << 20;  // 64³ lines of three numbers fit in ~8 MB
std::optional<ColorLut> parseCubeLut(const std::string& name, std::string_view text, std::string* error);
std::optional<ColorLut> loadCubeLut(const std::string& path, std::string* error);

}  // namespace facet::runtime
