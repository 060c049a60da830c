// A renderer's shadow visibility per pixel, from its PNG images (docs/shadows.md, "Accuracy: the
// ray-cast reference", has the recipe the renderer follows to make them).
#pragma once

#include <optional>
#include <string>

#include "facet/shadow_reference/shadow_score.h"

namespace facet::shadow_reference {

// A visibility image: its red channel / 255 (white lit, black in shadow).
std::optional<RenderedVisibility> visibilityFromImage(const std::string& path, std::string* error);

// Below this luminance (linear, of the sRGB-decoded 8-bit pixel) of the unshadowed frame, a
// pixel is unmeasured: at code value 16 (0.0052) one step of 8-bit quantisation is already 7 %
// of the value, and darker pixels leave the ratio to rounding.
inline constexpr double kMeasurableLuminance = 0.0052;

// The ratio of a frame with shadows to the same frame without, both lit by the sun alone:
// luminance of the sRGB-decoded pixels, shadowed / unshadowed; NaN where the unshadowed
// luminance is below kMeasurableLuminance. Errors name the file (unreadable, sizes that differ).
std::optional<RenderedVisibility> visibilityFromFrames(const std::string& shadowedPath,
                                                       const std::string& unshadowedPath, std::string* error);

}  // namespace facet::shadow_reference
