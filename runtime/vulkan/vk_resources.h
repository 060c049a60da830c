// Buffers and images with their memory. Plain structs with explicit create/destroy functions:
// the backend owns a handful of each and destroys them in its destructor (after waiting for the
// device), so RAII wrappers would add moves and ownership rules without removing any risk.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace facet::runtime::vulkan {

class Context;

// A buffer in host-visible, host-coherent memory, mapped for its whole life. Coherent memory
// means host writes need no flush and device writes need no invalidate after the fence wait;
// Vulkan guarantees every device has such a memory type.
struct HostBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
  VkDeviceSize size = 0;
};

bool createHostBuffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, HostBuffer* out,
                      std::string* error);
// An exclusive VkBuffer without memory, and what memory it needs. On failure *out stays null.
bool createBufferObject(VkDevice device, VkDeviceSize size, VkBufferUsageFlags usage, VkBuffer* out,
                        VkMemoryRequirements* needs, std::string* error);
// Safe on a default-constructed or partly created buffer; leaves *buffer default-constructed.
void destroyHostBuffer(VkDevice device, HostBuffer* buffer);

// A 2D image with one layer and mipLevels levels (render targets: one; sampled textures: their
// whole given chain), in device memory, and a view of all of it.
struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t mipLevels = 1;
  uint32_t layers = 1;           // 6 for a cube map (viewed as VK_IMAGE_VIEW_TYPE_CUBE)
  bool lazilyAllocated = false;  // transient usage and the device had a LAZILY_ALLOCATED type
};

bool createImage(const Context& ctx, uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                 VkImageAspectFlags aspect, Image* out, std::string* error, uint32_t mipLevels = 1, bool cube = false,
                 VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT, VkImageCreateFlags flags = 0);
// Safe on a default-constructed or partly created image; leaves *image default-constructed.
void destroyImage(VkDevice device, Image* image);

// A command pool with one primary command buffer and an unsignalled fence: what submit-and-wait
// work needs (the frame, texture uploads). On failure the handles that were not created stay
// VK_NULL_HANDLE, so the owner's usual destruction is safe.
bool createSubmitRecorder(VkDevice device, uint32_t queueFamily, VkCommandPoolCreateFlags flags, VkCommandPool* pool,
                          VkCommandBuffer* commandBuffer, VkFence* fence, std::string* error);

}  // namespace facet::runtime::vulkan
