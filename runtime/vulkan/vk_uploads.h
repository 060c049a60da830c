// Host data into BufferAllocations (vk_memory.h): copied straight into mapped memory, or, where
// the buffer's memory is not host-visible, into a staging buffer and from there by copy commands
// recorded into the frame's command buffer before its render passes.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "vk_memory.h"
#include "vk_retire.h"

namespace facet::runtime::vulkan {

class UploadQueue {
 public:
  void init(BufferAllocator* allocator, RetireQueue* retire) {
    allocator_ = allocator;
    retire_ = retire;
  }
  // Puts `size` bytes at `offset` of `dst`, a buffer no submitted frame reads yet (it has
  // TRANSFER_DST usage when not mapped). Mapped: written now (coherent memory; the frame's
  // submission makes it visible). Otherwise queued for record().
  void write(const BufferAllocation& dst, VkDeviceSize offset, const void* data, VkDeviceSize size);
  // Records the queued copies into cmd, then a barrier making them visible to vertex input and
  // uniform reads of later commands. The staging buffer is retired (vk_retire.h). No-op when
  // nothing is queued.
  bool record(VkCommandBuffer cmd, std::string* error);

  uint64_t stagedBytes() const { return stagedBytes_; }

 private:
  struct Copy {
    VkBuffer dst;
    VkDeviceSize dstOffset;
    VkDeviceSize srcOffset;
    VkDeviceSize size;
  };
  BufferAllocator* allocator_ = nullptr;
  RetireQueue* retire_ = nullptr;
  std::vector<uint8_t> bytes_;
  std::vector<Copy> copies_;
  uint64_t stagedBytes_ = 0;
};

}  // namespace facet::runtime::vulkan
