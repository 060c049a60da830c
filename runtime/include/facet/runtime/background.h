// The environment drawn as the background (docs/runtime.md, "The environment background"): the
// frame's prefiltered environment (facet_environment) seen through each pixel, at a chosen level,
// behind everything, pre-exposed like the lights so the background and what it lights agree.
// A draw of the forward pass (DrawItem::atFarPlane), so both backends draw it on either render
// path, with MSAA and render scale, and an app embedding the runtime adds it to its own frames.
#pragma once

#include "facet/abi/shader_abi.h"
#include "facet/runtime/render_backend.h"

namespace facet::runtime {

struct BackgroundSettings {
  float lod = 0;        // the environment's level: 0 its base level, up to abi::kEnvironmentLevels − 1
  float intensity = 1;  // the radiance's factor
};

// The block the background's shaders read: the GL view-projection's pixel-to-direction matrix
// (abi::BackgroundParams) and the settings.
abi::BackgroundParams backgroundParams(const float viewProjection[16], const BackgroundSettings& settings);

// The world direction (unnormalized) the background samples at GL normalized device coordinates
// (x, y), as the shaders compute it from the block: what tests compare the image with.
void backgroundDirection(const abi::BackgroundParams& params, float x, float y, float direction[3]);

// The background's draw for a frame whose frame block holds `viewProjection` (GL clip): the
// process's full-screen triangle and backgroundProgram(). The frame must bind the environment
// (setEnvironment, SceneFrame).
DrawItem backgroundDraw(const float viewProjection[16], const BackgroundSettings& settings);

// Inserts backgroundDraw(frame->frame.viewProjection, settings) after the frame's opaque draws
// and before its blended ones: drawn after the opaque ones, its pixels under them fail the early
// depth test and are never shaded; blended draws must come after it to blend over it.
void addBackground(FrameDesc* frame, const BackgroundSettings& settings);

}  // namespace facet::runtime
