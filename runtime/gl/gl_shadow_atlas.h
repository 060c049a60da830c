// The sun's shadow atlas on GL (docs/shadows.md, "Shadow pass"): a D16 depth texture, the
// framebuffer the shadow pass draws it through (depth only), and the compare sampler the forward
// pass's receivers read it with.
#pragma once

#include <cstdint>
#include <string>

#include "gl_objects.h"

namespace facet::runtime::gl {

class ShadowAtlas {
 public:
  // The atlas at size × size, made at the first call and remade when the size changes (then
  // *remade is set: a texture unit that held the old name holds nothing now).
  bool ensure(uint32_t size, bool* remade, std::string* error);

  GLuint texture() const { return depth_.id(); }
  GLuint framebuffer() const { return framebuffer_.id(); }
  GLuint sampler() const { return sampler_.id(); }
  uint32_t size() const { return size_; }

 private:
  uint32_t size_ = 0;
  Texture depth_;
  Framebuffer framebuffer_;
  Sampler sampler_;
};

}  // namespace facet::runtime::gl
