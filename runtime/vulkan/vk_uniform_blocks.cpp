#include "vk_uniform_blocks.h"

#include <algorithm>
#include <vector>

namespace facet::runtime::vulkan {

VkDeviceSize materialRange(size_t bytes) { return bytes == 0 ? 16 : (VkDeviceSize(bytes) + 15) / 16 * 16; }

void UniformBlockCache::destroy() {
  if (!allocator_) return;
  for (auto& [block, entry] : blocks_) allocator_->release(&entry.buffer);
  blocks_.clear();
}

void UniformBlockCache::release(const Entry& entry) {
  retire_->retire([allocator = allocator_, buffer = entry.buffer]() mutable { allocator->release(&buffer); });
}

bool UniformBlockCache::prepare(const FrameDesc& frame, std::string* error) {
  ++frameNumber_;
  for (const DrawItem& draw : FrameDraws(frame)) {
    const UniformBlock* block = draw.materialBlock;
    if (!block) continue;
    Entry& entry = blocks_[block];
    entry.lastUsedFrame = frameNumber_;
    if (entry.buffer.buffer && entry.generation == block->generation) continue;
    const VkDeviceSize size = materialRange(block->bytes.size());
    if (entry.buffer.buffer) release(entry);
    entry.buffer = BufferAllocation{};
    if (!allocator_->create(size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            BufferUse::DeviceRead, &entry.buffer, error)) {
      blocks_.erase(block);
      return false;
    }
    // A buffer no submitted frame reads yet: the bytes, zero-padded to the bound range.
    std::vector<uint8_t> padded(size, 0);
    std::copy(block->bytes.begin(), block->bytes.end(), padded.begin());
    uploads_->write(entry.buffer, 0, padded.data(), size);
    entry.generation = block->generation;
    ++uploadCount_;
  }
  evictUnusedEntries(blocks_, frameNumber_, [&](const Entry& entry) { release(entry); });
  return true;
}

VkBuffer UniformBlockCache::locate(const UniformBlock* block) const {
  auto found = blocks_.find(block);
  return found == blocks_.end() ? VK_NULL_HANDLE : found->second.buffer.buffer;
}

}  // namespace facet::runtime::vulkan
