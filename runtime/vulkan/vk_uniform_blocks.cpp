#include "vk_uniform_blocks.h"

#include <cstring>

#include "vk_context.h"

namespace facet::runtime::vulkan {

VkDeviceSize materialRange(size_t bytes) { return bytes == 0 ? 16 : (VkDeviceSize(bytes) + 15) / 16 * 16; }

void UniformBlockCache::destroy() {
  if (!ctx_) return;
  for (auto& [block, entry] : blocks_) destroyHostBuffer(ctx_->device, &entry.buffer);
  blocks_.clear();
}

void UniformBlockCache::release(const Entry& entry) {
  VkDevice device = ctx_->device;
  retire_->retire([device, buffer = entry.buffer]() mutable { destroyHostBuffer(device, &buffer); });
}

bool UniformBlockCache::prepare(const FrameDesc& frame, std::string* error) {
  ++frameNumber_;
  for (const DrawItem& draw : frame.draws) {
    const UniformBlock* block = draw.materialBlock;
    if (!block) continue;
    Entry& entry = blocks_[block];
    entry.lastUsedFrame = frameNumber_;
    if (entry.buffer.buffer && entry.generation == block->generation) continue;
    const VkDeviceSize size = materialRange(block->bytes.size());
    if (entry.buffer.buffer) release(entry);
    entry.buffer = HostBuffer{};
    if (!createHostBuffer(*ctx_, size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &entry.buffer, error)) {
      blocks_.erase(block);
      return false;
    }
    // Coherent memory, a buffer no submitted frame reads yet, and the frame's vkQueueSubmit
    // makes the host writes visible.
    auto* mapped = static_cast<uint8_t*>(entry.buffer.mapped);
    std::memset(mapped, 0, size);
    if (!block->bytes.empty()) std::memcpy(mapped, block->bytes.data(), block->bytes.size());
    entry.generation = block->generation;
    ++uploads_;
  }
  evictUnusedEntries(blocks_, frameNumber_, [&](const Entry& entry) { release(entry); });
  return true;
}

VkBuffer UniformBlockCache::locate(const UniformBlock* block) const {
  auto found = blocks_.find(block);
  return found == blocks_.end() ? VK_NULL_HANDLE : found->second.buffer.buffer;
}

}  // namespace facet::runtime::vulkan
