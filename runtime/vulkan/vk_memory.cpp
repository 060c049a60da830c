#include "vk_memory.h"

#include <algorithm>
#include <iterator>

#include "vk_check.h"
#include "vk_context.h"
#include "vk_resources.h"

namespace facet::runtime::vulkan {
namespace {

constexpr VkMemoryPropertyFlags kHostCoherent =
    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

}  // namespace

// The memory type query decides, not the device kind: unified-memory devices (phones, lavapipe)
// have a device-local type the host can map, written directly; a discrete GPU's device-local
// memory is not host-visible, and is written through a staging copy.
uint32_t BufferAllocator::chooseType(uint32_t typeBits, BufferUse use, bool* mappable) const {
  *mappable = true;
  if (use == BufferUse::Staging) return ctx_->findMemoryType(typeBits, kHostCoherent);
  if (!stageDeviceReads_) {
    const uint32_t both = ctx_->findMemoryType(typeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | kHostCoherent);
    if (both != UINT32_MAX) return both;
  }
  const uint32_t local = ctx_->findMemoryType(typeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (local != UINT32_MAX) {
    *mappable = false;
    return local;
  }
  return ctx_->findMemoryType(typeBits, kHostCoherent);  // no device-local type: host memory it is
}

bool BufferAllocator::newBlock(uint32_t type, VkDeviceSize size, bool map, uint32_t* index, std::string* error) {
  Block block;
  block.memoryType = type;
  block.size = size;
  VkMemoryAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  info.allocationSize = size;
  info.memoryTypeIndex = type;
  if (!check(vkAllocateMemory(ctx_->device, &info, nullptr, &block.memory), "vkAllocateMemory", error)) return false;
  ++ctx_->memoryAllocations;
  const bool hostVisible = (ctx_->memoryProperties.memoryTypes[type].propertyFlags & kHostCoherent) == kHostCoherent;
  if (map && hostVisible &&
      !check(vkMapMemory(ctx_->device, block.memory, 0, VK_WHOLE_SIZE, 0, &block.mapped), "vkMapMemory", error)) {
    vkFreeMemory(ctx_->device, block.memory, nullptr);
    return false;
  }
  // Reuse a freed block's slot.
  auto freeSlot = std::find_if(blocks_.begin(), blocks_.end(), [](const Block& b) { return !b.memory; });
  if (freeSlot != blocks_.end()) {
    *freeSlot = block;
    *index = static_cast<uint32_t>(freeSlot - blocks_.begin());
  } else {
    blocks_.push_back(block);
    *index = static_cast<uint32_t>(blocks_.size() - 1);
  }
  return true;
}

bool BufferAllocator::create(VkDeviceSize size, VkBufferUsageFlags usage, BufferUse use, BufferAllocation* out,
                             std::string* error) {
  BufferAllocation allocation;
  allocation.size = size;
  VkMemoryRequirements needs{};
  if (!createBufferObject(ctx_->device, size, usage, &allocation.buffer, &needs, error)) return false;
  bool mappable = true;
  const uint32_t type = chooseType(needs.memoryTypeBits, use, &mappable);
  if (type == UINT32_MAX) {
    vkDestroyBuffer(ctx_->device, allocation.buffer, nullptr);
    *error = "no Vulkan memory type for a buffer of usage " + std::to_string(usage);
    return false;
  }
  // The first block of this type with room, else a new one.
  uint32_t index = UINT32_MAX;
  VkDeviceSize offset = 0;
  Range held{};
  for (uint32_t i = 0; i < blocks_.size() && index == UINT32_MAX; ++i) {
    Block& b = blocks_[i];
    if (!b.memory || b.memoryType != type || (b.mapped != nullptr) != mappable) continue;
    if (take(&b, needs.size, needs.alignment, &offset, &held)) index = i;
  }
  if (index == UINT32_MAX) {
    if (!newBlock(type, std::max(kBlockSize, alignUp(needs.size, kBlockSize)), mappable, &index, error)) {
      vkDestroyBuffer(ctx_->device, allocation.buffer, nullptr);
      return false;
    }
    take(&blocks_[index], needs.size, needs.alignment, &offset, &held);
  }
  Block& block = blocks_[index];
  if (!check(vkBindBufferMemory(ctx_->device, allocation.buffer, block.memory, offset), "vkBindBufferMemory", error)) {
    vkDestroyBuffer(ctx_->device, allocation.buffer, nullptr);
    giveBack(&block, held);
    return false;
  }
  ++block.live;
  allocation.block = index;
  allocation.offset = held.offset;
  allocation.reserved = held.size;
  if (block.mapped) allocation.mapped = static_cast<uint8_t*>(block.mapped) + offset;
  *out = allocation;
  return true;
}

void BufferAllocator::release(BufferAllocation* allocation) {
  if (allocation->buffer) vkDestroyBuffer(ctx_->device, allocation->buffer, nullptr);
  if (allocation->block < blocks_.size()) {
    Block& block = blocks_[allocation->block];
    giveBack(&block, {allocation->offset, allocation->reserved});
    if (--block.live == 0) {
      block.top = 0;  // empty: starts over
      block.released.clear();
      // Keep one empty block per memory type and mapping for reuse; free the others.
      const bool spare = std::any_of(blocks_.begin(), blocks_.end(), [&](const Block& b) {
        return &b != &block && b.memory && b.live == 0 && b.memoryType == block.memoryType &&
               (b.mapped != nullptr) == (block.mapped != nullptr);
      });
      if (spare) {
        vkFreeMemory(ctx_->device, block.memory, nullptr);  // unmaps it
        block = Block{};
      }
    }
  }
  *allocation = BufferAllocation{};
}

bool BufferAllocator::take(Block* block, VkDeviceSize size, VkDeviceSize alignment, VkDeviceSize* at, Range* held) {
  for (auto it = block->released.begin(); it != block->released.end(); ++it) {
    const VkDeviceSize start = alignUp(it->offset, alignment);
    if (start + size > it->offset + it->size) continue;
    *at = start;
    *held = {it->offset, start + size - it->offset};
    it->offset += held->size;
    it->size -= held->size;
    if (it->size == 0) block->released.erase(it);
    return true;
  }
  const VkDeviceSize start = alignUp(block->top, alignment);
  if (start + size > block->size) return false;
  *at = start;
  *held = {block->top, start + size - block->top};
  block->top = start + size;
  return true;
}

void BufferAllocator::giveBack(Block* block, Range range) {
  auto& released = block->released;
  auto next = std::lower_bound(released.begin(), released.end(), range.offset,
                               [](const Range& r, VkDeviceSize offset) { return r.offset < offset; });
  if (next != released.end() && range.offset + range.size == next->offset) {  // merge with the next
    range.size += next->size;
    next = released.erase(next);
  }
  if (next != released.begin()) {  // merge with the previous
    auto previous = std::prev(next);
    if (previous->offset + previous->size == range.offset) {
      range.offset = previous->offset;
      range.size += previous->size;
      next = released.erase(previous);
    }
  }
  if (range.offset + range.size == block->top) {
    block->top = range.offset;  // the top comes down instead of keeping a range below it
  } else {
    released.insert(next, range);
  }
}

VkDeviceSize BufferAllocator::bytesBelowTops() const {
  VkDeviceSize total = 0;
  for (const Block& block : blocks_) total += block.top;
  return total;
}

void BufferAllocator::destroy() {
  if (!ctx_) return;
  for (Block& block : blocks_) {
    if (block.memory) vkFreeMemory(ctx_->device, block.memory, nullptr);
  }
  blocks_.clear();
}

size_t BufferAllocator::blockCount() const {
  return static_cast<size_t>(std::count_if(blocks_.begin(), blocks_.end(), [](const Block& b) { return b.memory; }));
}

}  // namespace facet::runtime::vulkan
