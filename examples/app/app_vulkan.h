// What an engine already has before it embeds Facet: its own Vulkan instance, device and queue,
// its render target, its per-frame command buffers and fences. Used by examples/app and by the
// tests of the app-device API (tests/runtime/test_vulkan_app_frames.cpp), which need the same.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/vulkan_backend.h"

namespace facet::example {

struct AppVulkan {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  std::array<VkCommandBuffer, 2> frameCommands{};  // the engine's per-frame command buffers
  std::array<VkFence, 2> frameFences{};
  // Messages of error severity from the validation layer, when `validation` was asked for.
  std::vector<std::string> validationErrors;

  AppVulkan() = default;
  AppVulkan(const AppVulkan&) = delete;
  AppVulkan& operator=(const AppVulkan&) = delete;
  ~AppVulkan() { destroy(); }
  // Waits for the device, then destroys everything (the messenger last but for the instance, so
  // it still hears what vkDestroyDevice reports, such as objects the runtime left behind).
  void destroy();

  // validation: VK_LAYER_KHRONOS_validation with synchronization validation, errors collected
  // (and printed to stderr) by the app's messenger.
  bool create(bool validation, std::string* error);
  runtime::AppDevice appDevice() const { return {instance, physicalDevice, device, queueFamily, queue}; }

  // The engine's frame loop with two frames in flight (as VulkanOptions::framesInFlight's
  // default): wait until the frame that last used this ring slot has finished, record the
  // runtime's frame into the slot's command buffer, submit it with the slot's fence.
  bool recordAndSubmit(runtime::VulkanRenderer& renderer, const runtime::FrameDesc& frame,
                       const runtime::AppImage& image, int index, std::string* error);
  bool waitIdle() const { return vkDeviceWaitIdle(device) == VK_SUCCESS; }

  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const;
};

// The engine's own render target (its swapchain image, say) and, to look at it, the engine's own
// copy of it into host memory: the runtime renders into the image and reads nothing back.
struct AppTarget {
  const AppVulkan* vk = nullptr;
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory imageMemory = VK_NULL_HANDLE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory bufferMemory = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  uint32_t width = 0;
  uint32_t height = 0;
  VkImageUsageFlags usage = 0;
  VkImageCreateFlags flags = 0;

  AppTarget() = default;
  AppTarget(const AppTarget&) = delete;
  AppTarget& operator=(const AppTarget&) = delete;
  ~AppTarget();

  // An RGBA8 image in device-local memory; usage gains TRANSFER_SRC for read().
  bool create(const AppVulkan& app, VkFormat imageFormat, uint32_t imageWidth, uint32_t imageHeight,
              VkImageUsageFlags imageUsage, VkImageCreateFlags createFlags, std::string* error);
  // The image as the runtime should see it, going from `oldLayout` to `newLayout`.
  runtime::AppImage describe(VkImageLayout oldLayout, VkImageLayout newLayout) const {
    return {image, format, width, height, oldLayout, newLayout, usage, flags};
  }
  // The image (in `layout`) into host memory, rows top first; waits for the queue.
  bool read(VkImageLayout layout, std::vector<uint8_t>* rgba, std::string* error);
};

}  // namespace facet::example
