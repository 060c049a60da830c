// The vignette's settings and the post pass's uniform block made from them (chunks/vignette.glsl
// has the formula).
#pragma once

#include <cstdint>

#include "facet/abi/shader_abi.h"
#include "facet/scene/post_settings.h"

namespace facet::runtime {

struct FrameDesc;

// FrameDesc::postUniforms for a width × height frame.
abi::PostUniforms postUniforms(const VignetteSettings& vignette, uint32_t width, uint32_t height);

// What a backend writes into the block: the frame's postUniforms, with the viewport of the frame's
// size when `viewport` (the upscaled read and bloom divide by it, whatever the frame says) and
// bloom's parameters (intensity, threshold, knee = threshold / 2) when `bloom` is not null.
abi::PostUniforms postUniformsFor(const FrameDesc& frame, bool viewport, const BloomSettings* bloom);

}  // namespace facet::runtime
