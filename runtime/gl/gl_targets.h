// The two render targets of a frame and their readback.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/render_path.h"
#include "gl_context.h"
#include "gl_objects.h"

namespace facet::runtime::gl {

struct RenderTargets {
  uint32_t width = 0;  // the output's (LDR) size
  uint32_t height = 0;
  uint32_t forwardWidth = 0;  // HDR's and depth's: the output's, or scaled by the render scale
  uint32_t forwardHeight = 0;
  // Forward pass: RGBA16F colour (sampled by the post pass, read back for tests) + depth.
  // With MSAA, depth is not made (the forward pass draws into msaaFramebuffer) and hdrFramebuffer
  // holds colour only: the target of the resolve.
  Texture hdrColor;
  Renderbuffer depth;
  Framebuffer hdrFramebuffer;
  // MSAA only: multisampled HDR colour and depth renderbuffers, the forward pass's framebuffer.
  // Resolved into hdrColor by glBlitFramebuffer, then invalidated (never stored on a tiler).
  // With GL_EXT_multisampled_render_to_texture (renderToTexture) there is no hdrSamples: hdrColor
  // itself is attached with `samples` samples and the driver resolves it when the framebuffer is
  // flushed (the next framebuffer bound), and depthSamples is that extension's renderbuffer.
  Renderbuffer hdrSamples;
  Renderbuffer depthSamples;
  Framebuffer msaaFramebuffer;
  GLsizei samples = 1;
  bool renderToTexture = false;
  // Post pass: RGBA8 colour, the displayable image; with FXAA the tone-mapped image the FXAA
  // pass samples (bilinear then, not nearest).
  Texture ldrColor;
  Framebuffer ldrFramebuffer;
  // FXAA only: the FXAA pass's RGBA8 output, the displayable image.
  Texture fxaaColor;
  Framebuffer fxaaFramebuffer;
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
// target of `hdrFormat`, and `samples` > 1 the multisampled forward framebuffer, and checks their
// completeness.
// renderToTexture: the context's GL_EXT_multisampled_render_to_texture entry points, or null for
// multisampled renderbuffers resolved by glBlitFramebuffer. fxaa: the FXAA pass's target too.
// renderScale < 1: HDR and depth are scaledSize() of width × height (render_path.h), and HDR is
// filtered bilinearly for the post pass's upscaled read.
bool createRenderTargets(uint32_t width, uint32_t height, bool merged, HdrFormat hdrFormat, GLsizei samples,
                         const Context::RenderToTexture* renderToTexture, bool fxaa, RenderTargets* targets,
                         std::string* error, double renderScale = 1.0);

// The internal formats of the HDR target and of depth (GL_RGBA16F or GL_R11F_G11F_B10F;
// GL_DEPTH_COMPONENT32F).
GLenum hdrInternalFormat(HdrFormat format);
inline constexpr GLenum kDepthInternalFormat = GL_DEPTH_COMPONENT32F;

// The largest renderbuffer sample count of `internalFormat` (glGetInternalformativ GL_SAMPLES,
// whose list is in descending order), 0 when none.
GLint maxRenderbufferSamples(GLenum internalFormat);

// Reads colour attachment `attachment` (GL_COLOR_ATTACHMENTi) of `framebuffer` with its rows in
// memory order: top to bottom for what render() drew, as it draws top-down (gl_row_order.h).
void readRgbaFloat(GLuint framebuffer, GLenum attachment, uint32_t width, uint32_t height, std::vector<float>* pixels);
void readRgba8(GLuint framebuffer, GLenum attachment, uint32_t width, uint32_t height, std::vector<uint8_t>* pixels);

}  // namespace facet::runtime::gl
