#include "vk_uploads.h"

#include <cstring>

namespace facet::runtime::vulkan {

void UploadQueue::write(const BufferAllocation& dst, VkDeviceSize offset, const void* data, VkDeviceSize size) {
  if (size == 0) return;
  if (dst.mapped) {
    std::memcpy(static_cast<uint8_t*>(dst.mapped) + offset, data, size);
    return;
  }
  // 16-byte steps keep every copy's source offset aligned for any element type.
  const VkDeviceSize at = (bytes_.size() + 15) / 16 * 16;
  bytes_.resize(at + size);
  std::memcpy(bytes_.data() + at, data, size);
  copies_.push_back({dst.buffer, offset, at, size});
}

bool UploadQueue::record(VkCommandBuffer cmd, std::string* error) {
  if (copies_.empty()) return true;
  BufferAllocation staging;
  if (!allocator_->create(bytes_.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, BufferUse::Staging, &staging, error)) {
    return false;
  }
  std::memcpy(staging.mapped, bytes_.data(), bytes_.size());
  for (const Copy& copy : copies_) {
    const VkBufferCopy region{copy.srcOffset, copy.dstOffset, copy.size};
    vkCmdCopyBuffer(cmd, staging.buffer, copy.dst, 1, &region);
  }
  VkMemoryBarrier visible{};
  visible.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  visible.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  visible.dstAccessMask = VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDEX_READ_BIT | VK_ACCESS_UNIFORM_READ_BIT;
  vkCmdPipelineBarrier(
      cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
      VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
      0, 1, &visible, 0, nullptr, 0, nullptr);
  stagedBytes_ += bytes_.size();
  BufferAllocator* allocator = allocator_;
  retire_->retire([allocator, staging]() mutable { allocator->release(&staging); });
  bytes_.clear();
  copies_.clear();
  return true;
}

}  // namespace facet::runtime::vulkan
