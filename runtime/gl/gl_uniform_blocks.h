// Persistent uniform blocks in GL buffers (material instances' parameters): one buffer per
// UniformBlock, specified when the block is first drawn and again only when its generation changes.
#pragma once

#include <cstdint>
#include <unordered_map>

#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/render_backend.h"
#include "gl_objects.h"

namespace facet::runtime::gl {

// Cache rule as vulkan::UniformBlockCache's (vk_uniform_blocks.h): keyed by address, rewritten
// when the generation differs, deleted after kEvictAfterFrames frames unused.
class UniformBlockCache {
 public:
  void beginFrame() { ++frameNumber_; }
  // The block's buffer, current. Changes the GL_UNIFORM_BUFFER binding.
  GLuint resident(const facet::runtime::UniformBlock& block);
  void endFrame();

  size_t residentCount() const { return blocks_.size(); }
  uint64_t uploadCount() const { return uploads_; }

 private:
  struct Entry {
    uint64_t generation = 0;
    Buffer buffer;
    uint64_t lastUsedFrame = 0;
  };

  std::unordered_map<const facet::runtime::UniformBlock*, Entry> blocks_;
  uint64_t frameNumber_ = 0;
  uint64_t uploads_ = 0;
};

}  // namespace facet::runtime::gl
