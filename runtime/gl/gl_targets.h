// The two render targets of a frame and their readback.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/render_path.h"
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
  // Merged path only: HDR at colour 0, LDR at colour 1, depth, in one framebuffer (the
  // framebuffer-fetch post pass reads colour 0 of the pixel it writes colour 1 of).
  Framebuffer mergedFramebuffer;
  // Merged path, frames into the app's framebuffer (GlRenderer::renderToFramebuffer): HDR at
  // colour 0 and depth like mergedFramebuffer, colour 1 the app's image, attached per frame.
  Framebuffer appMergedFramebuffer;
};

// "missing attachment", "undefined (...)": a glCheckFramebufferStatus result for messages.
const char* framebufferStatusName(GLenum status);
// True when the framebuffer bound to GL_FRAMEBUFFER is complete; else *error is
// "<which> framebuffer is <status>".
bool checkComplete(const char* which, std::string* error);

// Creates the framebuffers at width × height (the merged one when `merged`) with an HDR colour
// target of `hdrFormat` and checks their completeness.
bool createRenderTargets(uint32_t width, uint32_t height, bool merged, HdrFormat hdrFormat, RenderTargets* targets,
                         std::string* error);

// Reads colour attachment `attachment` (GL_COLOR_ATTACHMENTi) of `framebuffer` with rows top to
// bottom (GL returns bottom-up).
void readRgbaFloat(GLuint framebuffer, GLenum attachment, uint32_t width, uint32_t height, std::vector<float>* pixels);
void readRgba8(GLuint framebuffer, GLenum attachment, uint32_t width, uint32_t height, std::vector<uint8_t>* pixels);

}  // namespace facet::runtime::gl
