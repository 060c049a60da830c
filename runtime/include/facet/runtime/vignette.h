// The vignette's settings and the post pass's uniform block made from them (chunks/vignette.glsl
// has the formula).
#pragma once

#include <cstdint>

#include "facet/abi/shader_abi.h"
#include "facet/scene/post_settings.h"

namespace facet::runtime {

// FrameDesc::postUniforms for a width × height frame.
abi::PostUniforms postUniforms(const VignetteSettings& vignette, uint32_t width, uint32_t height);

}  // namespace facet::runtime
