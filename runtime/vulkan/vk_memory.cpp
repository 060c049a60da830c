#include "vk_memory.h"

#include <algorithm>

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
  for (uint32_t i = 0; i < blocks_.size(); ++i) {
    const Block& b = blocks_[i];
    if (!b.memory || b.memoryType != type || (b.mapped != nullptr) != mappable) continue;
    const VkDeviceSize at = alignUp(b.top, needs.alignment);
    if (at + needs.size <= b.size) {
      index = i;
      offset = at;
      break;
    }
  }
  if (index == UINT32_MAX) {
    if (!newBlock(type, std::max(kBlockSize, alignUp(needs.size, kBlockSize)), mappable, &index, error)) {
      vkDestroyBuffer(ctx_->device, allocation.buffer, nullptr);
      return false;
    }
    offset = 0;
  }
  Block& block = blocks_[index];
  if (!check(vkBindBufferMemory(ctx_->device, allocation.buffer, block.memory, offset), "vkBindBufferMemory",
             error)) {
    vkDestroyBuffer(ctx_->device, allocation.buffer, nullptr);
    return false;
  }
  block.top = offset + needs.size;
  ++block.live;
  allocation.block = index;
  if (block.mapped) allocation.mapped = static_cast<uint8_t*>(block.mapped) + offset;
  *out = allocation;
  return true;
}

void BufferAllocator::release(BufferAllocation* allocation) {
  if (allocation->buffer) vkDestroyBuffer(ctx_->device, allocation->buffer, nullptr);
  if (allocation->block < blocks_.size()) {
    Block& block = blocks_[allocation->block];
    if (--block.live == 0) {
      block.top = 0;  // empty: starts over
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
