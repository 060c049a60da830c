// Buffers sub-allocated from a few large VkDeviceMemory blocks. Drivers cap the number of live
// allocations (maxMemoryAllocationCount, 4096 on many mobile drivers) and each one costs a
// kernel call, so thousands of material instances must not mean thousands of allocations.
//
// Each buffer is its own VkBuffer bound at an offset of a shared block. A block hands out space
// from the first released range that fits, else from its top (a bump pointer); a released range
// merges with its neighbours and, at the top, lowers it. So a material block replaced every frame
// (a new buffer each time, vk_uniform_blocks.h) reuses the space of the one released frames
// before instead of creeping through the block. An empty block starts over; one empty block per
// memory type is kept for reuse, others are freed. Debian 12 packages no Vulkan Memory
// Allocator (libvulkan-memory-allocator-dev is not in bookworm), hence this small one.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace facet::runtime::vulkan {

class Context;

enum class BufferUse {
  DeviceRead,  // read by the device every frame (meshes, material blocks): device-local memory
  Staging,     // written by the host, copied from once: host-visible, coherent memory
};

struct BufferAllocation {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  // Where the host writes the buffer's bytes; null when it must be written through a staging
  // copy (device-local memory the host cannot map, or BufferAllocator's forced staging).
  void* mapped = nullptr;
  uint32_t block = UINT32_MAX;
  VkDeviceSize offset = 0;  // the block range it holds, alignment padding included
  VkDeviceSize reserved = 0;
};

class BufferAllocator {
 public:
  // 8 MiB: a few hundred thousand material blocks, or a mesh of 130 000 vertices, per block;
  // a larger buffer gets a block of its own size.
  static constexpr VkDeviceSize kBlockSize = VkDeviceSize{8} << 20;

  BufferAllocator() = default;
  BufferAllocator(const BufferAllocator&) = delete;
  BufferAllocator& operator=(const BufferAllocator&) = delete;

  // stageDeviceReads: treat device-local memory as unmappable even where it is host-visible
  // (lavapipe, phones), so tests exercise the staging path a discrete GPU takes.
  void init(const Context* ctx, bool stageDeviceReads) {
    ctx_ = ctx;
    stageDeviceReads_ = stageDeviceReads;
  }
  bool create(VkDeviceSize size, VkBufferUsageFlags usage, BufferUse use, BufferAllocation* out, std::string* error);
  // Destroys the buffer now: no submitted frame may still use it (see vk_retire.h). Safe on a
  // default-constructed allocation; leaves it default-constructed.
  void release(BufferAllocation* allocation);
  // Frees every block; every buffer must have been released. The device must be idle.
  void destroy();

  size_t blockCount() const;
  // Bytes below the blocks' tops, in use or released: how far the blocks have been filled.
  VkDeviceSize bytesBelowTops() const;

 private:
  struct Range {
    VkDeviceSize offset;
    VkDeviceSize size;
  };
  struct Block {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    uint32_t memoryType = 0;
    VkDeviceSize size = 0;
    VkDeviceSize top = 0;         // first free byte
    uint32_t live = 0;            // buffers bound in it
    void* mapped = nullptr;       // the whole block, when its memory is host-visible
    std::vector<Range> released;  // below top, sorted by offset, never adjacent to each other
  };
  // Takes `size` bytes at `alignment` from the block, or returns false when it has no room.
  static bool take(Block* block, VkDeviceSize size, VkDeviceSize alignment, VkDeviceSize* at, Range* held);
  static void giveBack(Block* block, Range range);
  uint32_t chooseType(uint32_t typeBits, BufferUse use, bool* mappable) const;
  bool newBlock(uint32_t type, VkDeviceSize size, bool map, uint32_t* index, std::string* error);

  const Context* ctx_ = nullptr;
  bool stageDeviceReads_ = false;
  std::vector<Block> blocks_;  // freed blocks keep their slot (memory null) so indices stay valid
};

}  // namespace facet::runtime::vulkan
