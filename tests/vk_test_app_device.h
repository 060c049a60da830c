// An app's own Vulkan instance and device for tests of the app-device API (vulkan_backend.h):
// validation and synchronization validation on, every error message counted, and the helpers an
// app would have: images of a chosen usage, reading one back, one-off command buffers.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "facet/vulkan_backend.h"

namespace facet::runtime::testing {

class TestAppDevice {
 public:
  TestAppDevice() = default;
  ~TestAppDevice();
  TestAppDevice(const TestAppDevice&) = delete;
  TestAppDevice& operator=(const TestAppDevice&) = delete;

  bool create(std::string* error);
  AppDevice appDevice() const { return {instance, physicalDevice, device, queueFamily, queue}; }
  const std::vector<std::string>& errors() const { return errors_; }

  // A 2D RGBA8 image in device memory, one level and layer; destroyed with the device helper.
  VkImage createImage(VkFormat format, uint32_t width, uint32_t height, VkImageUsageFlags usage,
                      VkImageCreateFlags flags = 0);
  void destroyImage(VkImage image);
  // Copies `image` (in `layout`, TRANSFER_SRC usage) into host memory, rows top first; waits.
  std::vector<uint8_t> read(VkImage image, VkImageLayout layout, uint32_t width, uint32_t height);

  VkCommandBuffer allocateCommandBuffer();
  // Submits to the queue with `fence` (may be null).
  bool submit(VkCommandBuffer cmd, VkFence fence);
  VkFence createFence();

  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);
  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const;

  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::vector<VkFence> fences_;
  struct OwnedImage {
    VkImage image;
    VkDeviceMemory memory;
  };
  std::vector<OwnedImage> images_;
  std::vector<std::string> errors_;
};

}  // namespace facet::runtime::testing
