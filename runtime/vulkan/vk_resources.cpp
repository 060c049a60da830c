#include "vk_resources.h"

#include "vk_check.h"
#include "vk_context.h"

namespace facet::runtime::vulkan {
namespace {

bool allocate(const Context& ctx, const VkMemoryRequirements& requirements, VkMemoryPropertyFlags preferred,
              VkMemoryPropertyFlags required, VkDeviceMemory* memory, std::string* error) {
  uint32_t type = ctx.findMemoryType(requirements.memoryTypeBits, preferred);
  if (type == UINT32_MAX) type = ctx.findMemoryType(requirements.memoryTypeBits, required);
  if (type == UINT32_MAX) {
    *error = "no Vulkan memory type with property flags " + std::to_string(required);
    return false;
  }
  VkMemoryAllocateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  info.allocationSize = requirements.size;
  info.memoryTypeIndex = type;
  if (!check(vkAllocateMemory(ctx.device, &info, nullptr, memory), "vkAllocateMemory", error)) {
    *memory = VK_NULL_HANDLE;
    return false;
  }
  ++ctx.memoryAllocations;
  return true;
}

}  // namespace

bool createBufferObject(VkDevice device, VkDeviceSize size, VkBufferUsageFlags usage, VkBuffer* out,
                        VkMemoryRequirements* needs, std::string* error) {
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (!check(vkCreateBuffer(device, &info, nullptr, out), "vkCreateBuffer", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  vkGetBufferMemoryRequirements(device, *out, needs);
  return true;
}

bool createHostBuffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, HostBuffer* out,
                      std::string* error) {
  HostBuffer buffer;
  buffer.size = size;
  VkMemoryRequirements requirements{};
  if (!createBufferObject(ctx.device, size, usage, &buffer.buffer, &requirements, error)) return false;
  constexpr VkMemoryPropertyFlags kHost = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  bool ok = allocate(ctx, requirements, kHost, kHost, &buffer.memory, error) &&
            check(vkBindBufferMemory(ctx.device, buffer.buffer, buffer.memory, 0), "vkBindBufferMemory", error) &&
            check(vkMapMemory(ctx.device, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped), "vkMapMemory", error);
  if (!ok) {
    destroyHostBuffer(ctx.device, &buffer);
    return false;
  }
  *out = buffer;
  return true;
}

void destroyHostBuffer(VkDevice device, HostBuffer* buffer) {
  // Freeing memory unmaps it implicitly.
  if (buffer->buffer) vkDestroyBuffer(device, buffer->buffer, nullptr);
  if (buffer->memory) vkFreeMemory(device, buffer->memory, nullptr);
  *buffer = HostBuffer{};
}

bool createImage(const Context& ctx, uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                 VkImageAspectFlags aspect, Image* out, std::string* error, uint32_t mipLevels, bool cube,
                 VkSampleCountFlagBits samples, VkImageCreateFlags flags) {
  Image image;
  image.format = format;
  image.width = width;
  image.height = height;
  image.mipLevels = mipLevels;
  image.layers = cube ? 6 : 1;

  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = mipLevels;
  info.arrayLayers = image.layers;
  info.flags = flags | (cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0);
  info.samples = samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  if (!check(vkCreateImage(ctx.device, &info, nullptr, &image.image), "vkCreateImage", error)) {
    return false;
  }
  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(ctx.device, image.image, &requirements);
  // A transient attachment (never loaded or stored: the frame graph's verdict) can live in tile
  // memory only: lazily allocated memory, where the device offers it, gets no DRAM backing.
  const bool transient = (usage & VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT) != 0;
  const VkMemoryPropertyFlags preferred =
      transient ? VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT
                : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  image.lazilyAllocated = transient && ctx.findMemoryType(requirements.memoryTypeBits, preferred) != UINT32_MAX;
  bool ok = allocate(ctx, requirements, preferred, 0, &image.memory, error) &&
            check(vkBindImageMemory(ctx.device, image.image, image.memory, 0), "vkBindImageMemory", error);
  if (ok) {
    VkImageViewCreateInfo viewInfo{};
    viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    viewInfo.image = image.image;
    viewInfo.viewType = cube ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format;
    viewInfo.subresourceRange = {aspect, 0, mipLevels, 0, image.layers};
    ok = check(vkCreateImageView(ctx.device, &viewInfo, nullptr, &image.view), "vkCreateImageView", error);
  }
  if (!ok) {
    destroyImage(ctx.device, &image);
    return false;
  }
  *out = image;
  return true;
}

void destroyImage(VkDevice device, Image* image) {
  if (image->view) vkDestroyImageView(device, image->view, nullptr);
  if (image->image) vkDestroyImage(device, image->image, nullptr);
  if (image->memory) vkFreeMemory(device, image->memory, nullptr);
  *image = Image{};
}

bool createSubmitRecorder(VkDevice device, uint32_t queueFamily, VkCommandPoolCreateFlags flags, VkCommandPool* pool,
                          VkCommandBuffer* commandBuffer, VkFence* fence, std::string* error) {
  VkCommandPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  poolInfo.flags = flags;
  poolInfo.queueFamilyIndex = queueFamily;
  if (!check(vkCreateCommandPool(device, &poolInfo, nullptr, pool), "vkCreateCommandPool", error)) {
    *pool = VK_NULL_HANDLE;
    return false;
  }
  VkCommandBufferAllocateInfo cmdInfo{};
  cmdInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  cmdInfo.commandPool = *pool;
  cmdInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cmdInfo.commandBufferCount = 1;
  if (!check(vkAllocateCommandBuffers(device, &cmdInfo, commandBuffer), "vkAllocateCommandBuffers", error)) {
    *commandBuffer = VK_NULL_HANDLE;
    return false;
  }
  VkFenceCreateInfo fenceInfo{};
  fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  if (!check(vkCreateFence(device, &fenceInfo, nullptr, fence), "vkCreateFence", error)) {
    *fence = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

}  // namespace facet::runtime::vulkan
