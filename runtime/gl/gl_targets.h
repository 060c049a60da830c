// The two render targets of a frame and their readback.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gl_objects.h"

namespace facet::runtime::gl {

struct RenderTargets {
  uint32_t width = 0;
  uint32_t height = 0;
  // Forward pass: RGBA16F colour (sampled by the post pass, read back for tests) + depth.
  Texture hdrColor;
  Renderbuffer depth;
  Framebuffer hdrFramebuffer;
  // Post pass: RGBA8 colour, the displayable image.
  Texture ldrColor;
  Framebuffer ldrFramebuffer;
};

// Creates both framebuffers at width × height and checks their completeness.
bool createRenderTargets(uint32_t width, uint32_t height, RenderTargets* targets, std::string* error);

// Reads colour attachment 0 of `framebuffer` with rows top to bottom (GL returns bottom-up).
void readRgbaFloat(GLuint framebuffer, uint32_t width, uint32_t height, std::vector<float>* pixels);
void readRgba8(GLuint framebuffer, uint32_t width, uint32_t height, std::vector<uint8_t>* pixels);

}  // namespace facet::runtime::gl
