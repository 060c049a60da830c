// Persistent uniform blocks on the device (material instances' parameters): one buffer per
// UniformBlock, written when the block is first drawn and again only when its generation changes.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <unordered_map>

#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/render_backend.h"
#include "vk_memory.h"
#include "vk_retire.h"
#include "vk_uploads.h"

namespace facet::runtime::vulkan {

// Keyed by the UniformBlock's address; an entry whose generation differs from the block's gets
// a new buffer, the old one retired (frames in flight may still read it: never rewritten in
// place). Generations are unique in the process
// (nextUniformGeneration), so a block at a freed one's address is never taken for it. An entry
// unused for kEvictAfterFrames frames is released. Buffers are sub-allocated device-local memory
// (vk_memory.h), written once through UploadQueue before any frame reads them.
class UniformBlockCache {
 public:
  UniformBlockCache() = default;
  UniformBlockCache(const UniformBlockCache&) = delete;
  UniformBlockCache& operator=(const UniformBlockCache&) = delete;

  void init(BufferAllocator* allocator, UploadQueue* uploads, RetireQueue* retire) {
    allocator_ = allocator;
    uploads_ = uploads;
    retire_ = retire;
  }
  // Releases every buffer. The device must be idle. Safe to call twice.
  void destroy();

  // Makes every materialBlock of the (already checked) frame's FrameDraws resident and current; releases stale entries.
  bool prepare(const FrameDesc& frame, std::string* error);
  // The buffer of a block that went through prepare() this frame; its first `size` bytes (the
  // block's bytes, zero-padded to whole vec4s, at least 16) are what the shader binds.
  VkBuffer locate(const UniformBlock* block) const;

  size_t residentCount() const { return blocks_.size(); }
  uint64_t uploadCount() const { return uploadCount_; }

 private:
  struct Entry {
    uint64_t generation = 0;
    BufferAllocation buffer;
    uint64_t lastUsedFrame = 0;
  };

  void release(const Entry& entry);

  BufferAllocator* allocator_ = nullptr;
  UploadQueue* uploads_ = nullptr;
  RetireQueue* retire_ = nullptr;
  std::unordered_map<const UniformBlock*, Entry> blocks_;
  uint64_t frameNumber_ = 0;
  uint64_t uploadCount_ = 0;
};

// The bytes a "MaterialParams" binding covers: whole std140 vec4s, and 16 for an empty block
// (a zero-sized uniform range is invalid).
VkDeviceSize materialRange(size_t bytes);

}  // namespace facet::runtime::vulkan
