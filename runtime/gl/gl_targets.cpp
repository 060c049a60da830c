#include "gl_targets.h"

#include <utility>

#include "facet/runtime/render_path.h"

namespace facet::runtime::gl {
namespace {

Texture createColorTexture(GLenum internalFormat, GLenum format, GLenum type, GLsizei width, GLsizei height) {
  Texture texture = Texture::generate();
  glBindTexture(GL_TEXTURE_2D, texture.id());
  // glTexImage2D rather than glTexStorage2D: the 3.3 core fallback may lack texture storage.
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width, height, 0, format, type, nullptr);
  // The post pass maps pixels one to one: NEAREST keeps HDR values exact, and a single level
  // makes the texture complete without mipmaps.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

template <typename T>
void readRgba(GLuint framebuffer, GLenum attachment, GLenum type, uint32_t width, uint32_t height,
              std::vector<T>* pixels) {
  const size_t rowElements = size_t{width} * 4;
  pixels->assign(rowElements * height, T{});
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glReadBuffer(attachment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);  // rows tightly packed, whatever the width
  glReadPixels(0, 0, static_cast<GLsizei>(width), static_cast<GLsizei>(height), GL_RGBA, type, pixels->data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

}  // namespace

const char* framebufferStatusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "incomplete attachment";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "missing attachment";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "unsupported format combination";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "incomplete multisample";
    case GL_FRAMEBUFFER_UNDEFINED: return "undefined (a default framebuffer without a surface)";
    default: return "incomplete";
  }
}

bool checkComplete(const char* which, std::string* error) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return true;
  if (error) *error = std::string(which) + " framebuffer is " + framebufferStatusName(status);
  return false;
}

GLenum hdrInternalFormat(HdrFormat format) {
  return format == HdrFormat::R11G11B10Float ? GL_R11F_G11F_B10F : GL_RGBA16F;
}

GLint maxRenderbufferSamples(GLenum internalFormat) {
  GLint count = 0;
  glGetInternalformativ(GL_RENDERBUFFER, internalFormat, GL_NUM_SAMPLE_COUNTS, 1, &count);
  if (count <= 0) return 0;
  GLint largest = 0;
  glGetInternalformativ(GL_RENDERBUFFER, internalFormat, GL_SAMPLES, 1, &largest);
  return largest;
}

bool createRenderTargets(uint32_t width, uint32_t height, bool merged, HdrFormat hdrFormat, GLsizei samples,
                         const Context::RenderToTexture* renderToTexture, bool fxaa, RenderTargets* targets,
                         std::string* error, double renderScale) {
  RenderTargets created;
  created.width = width;
  created.height = height;
  created.forwardWidth = scaledSize(width, renderScale);
  created.forwardHeight = scaledSize(height, renderScale);
  // The forward pass's size; the LDR targets below are the output's.
  auto w = static_cast<GLsizei>(created.forwardWidth);
  auto h = static_cast<GLsizei>(created.forwardHeight);
  created.samples = samples;
  const bool msaa = samples > 1;
  created.renderToTexture = msaa && renderToTexture;

  const bool packed = hdrFormat == HdrFormat::R11G11B10Float;
  created.hdrColor = packed ? createColorTexture(GL_R11F_G11F_B10F, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, w, h)
                            : createColorTexture(GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, w, h);
  if (renderScale < 1.0) {
    // Upscaling: bilinear between the smaller HDR texture's texels (RGBA16F and R11F_G11F_B10F
    // are filterable in GLES 3.0).
    glBindTexture(GL_TEXTURE_2D, created.hdrColor.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  const auto renderbuffer = [&](GLenum internalFormat, GLsizei count) {
    Renderbuffer made = Renderbuffer::generate();
    glBindRenderbuffer(GL_RENDERBUFFER, made.id());
    if (count > 1 && created.renderToTexture) {
      renderToTexture->renderbufferStorage(GL_RENDERBUFFER, count, internalFormat, w, h);
    } else if (count > 1) {
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, count, internalFormat, w, h);
    } else {
      glRenderbufferStorage(GL_RENDERBUFFER, internalFormat, w, h);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    return made;
  };
  if (!msaa) created.depth = renderbuffer(kDepthInternalFormat, 1);
  created.hdrFramebuffer = Framebuffer::generate();
  glBindFramebuffer(GL_FRAMEBUFFER, created.hdrFramebuffer.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, created.hdrColor.id(), 0);
  if (!msaa) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, created.depth.id());
  bool hdrComplete = checkComplete(packed ? "HDR (R11F_G11F_B10F + DEPTH32F)" : "HDR (RGBA16F + DEPTH32F)", error);
  if (msaa && hdrComplete) {
    if (!created.renderToTexture) created.hdrSamples = renderbuffer(hdrInternalFormat(hdrFormat), samples);
    created.depthSamples = renderbuffer(kDepthInternalFormat, samples);
    created.msaaFramebuffer = Framebuffer::generate();
    glBindFramebuffer(GL_FRAMEBUFFER, created.msaaFramebuffer.id());
    if (created.renderToTexture) {
      // The extension's rule: every attachment of the framebuffer has the same sample count.
      renderToTexture->framebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, created.hdrColor.id(),
                                            0, samples);
    } else {
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, created.hdrSamples.id());
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, created.depthSamples.id());
    hdrComplete = checkComplete("MSAA (multisampled HDR + DEPTH32F)", error);
  }

  w = static_cast<GLsizei>(width);
  h = static_cast<GLsizei>(height);
  created.ldrColor = createColorTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
  created.ldrFramebuffer = Framebuffer::generate();
  glBindFramebuffer(GL_FRAMEBUFFER, created.ldrFramebuffer.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, created.ldrColor.id(), 0);
  bool ldrComplete = hdrComplete && checkComplete("LDR (RGBA8)", error);
  if (fxaa && ldrComplete) {
    // FXAA's taps between texel centres average their 2×2 neighbours (chunks/fxaa.glsl).
    glBindTexture(GL_TEXTURE_2D, created.ldrColor.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    created.fxaaColor = createColorTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
    created.fxaaFramebuffer = Framebuffer::generate();
    glBindFramebuffer(GL_FRAMEBUFFER, created.fxaaFramebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, created.fxaaColor.id(), 0);
    ldrComplete = checkComplete("FXAA (RGBA8)", error);
  }
  if (merged && ldrComplete) {
    created.mergedFramebuffer = Framebuffer::generate();
    glBindFramebuffer(GL_FRAMEBUFFER, created.mergedFramebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, created.hdrColor.id(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, created.ldrColor.id(), 0);
    if (!msaa) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, created.depth.id());
    ldrComplete = checkComplete("merged (RGBA16F + RGBA8 + DEPTH32F)", error);
    created.appMergedFramebuffer = Framebuffer::generate();
    glBindFramebuffer(GL_FRAMEBUFFER, created.appMergedFramebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, created.hdrColor.id(), 0);
    if (!msaa) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, created.depth.id());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  if (!ldrComplete || !checkGlError("render target creation", error)) return false;
  *targets = std::move(created);
  return true;
}

void readRgbaFloat(GLuint framebuffer, GLenum attachment, uint32_t width, uint32_t height, std::vector<float>* pixels) {
  readRgba(framebuffer, attachment, GL_FLOAT, width, height, pixels);
}

void readRgba8(GLuint framebuffer, GLenum attachment, uint32_t width, uint32_t height, std::vector<uint8_t>* pixels) {
  readRgba(framebuffer, attachment, GL_UNSIGNED_BYTE, width, height, pixels);
}

}  // namespace facet::runtime::gl
