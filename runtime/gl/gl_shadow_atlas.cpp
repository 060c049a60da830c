#include "gl_shadow_atlas.h"

#include "gl_targets.h"

namespace facet::runtime::gl {

bool ShadowAtlas::ensure(uint32_t size, bool* remade, std::string* error) {
  *remade = false;
  if (size_ == size && depth_.id() != 0) return true;
  if (sampler_.id() == 0) {
    // The receivers' depth compare (chunks/shadow_sun.glsl): lit when ref <= stored. LINEAR: GLES
    // 3.0 makes a depth texture with a compare mode filterable (spec 3.8.13, "Texture
    // Completeness"), and a driver may blend the four nearest comparisons (the 2×2 PCF the mid
    // and low tiers rely on); llvmpipe does (docs/shadows.md, "Shadow pass").
    sampler_ = Sampler::generate();
    glSamplerParameteri(sampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(sampler_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glSamplerParameteri(sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(sampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  *remade = depth_.id() != 0;
  framebuffer_.reset();
  depth_ = Texture::generate();
  const auto side = static_cast<GLsizei>(size);
  glBindTexture(GL_TEXTURE_2D, depth_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, side, side, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, nullptr);
  // The texture's own parameters, for a unit that holds it without the sampler: one level, complete.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  framebuffer_ = Framebuffer::generate();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
  const GLenum none = GL_NONE;  // no colour: the pass writes depth only
  glDrawBuffers(1, &none);
  glReadBuffer(GL_NONE);
  if (!checkComplete("shadow atlas", error)) {
    framebuffer_.reset();
    depth_.reset();
    size_ = 0;
    return false;
  }
  size_ = size;
  return checkGlError("shadow atlas", error);
}

}  // namespace facet::runtime::gl
