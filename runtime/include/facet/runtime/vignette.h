// The vignette's settings and the post pass's uniform block made from them (chunks/vignette.glsl
// has the formula).
#pragma once

#include <cstdint>

#include "facet/shader_abi.h"

namespace facet::runtime {

struct VignetteSettings {
  double intensity = 0.5;   // in [0, 1]: how much the corners lose (1: black)
  double radius = 0.8;      // distance from the centre where darkening starts (1: the top edge)
  double smoothness = 0.8;  // width of the transition beyond the radius
  double roundness = 1;     // in [0, 1]: 1 a circle on screen, 0 an ellipse fitting the frame
};

// FrameDesc::postUniforms for a width × height frame.
abi::PostUniforms postUniforms(const VignetteSettings& vignette, uint32_t width, uint32_t height);

}  // namespace facet::runtime
