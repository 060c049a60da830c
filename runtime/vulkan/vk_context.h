// The Vulkan instance, the chosen physical device, the logical device and its graphics queue,
// and (when validation is on) the debug messenger that collects the validation layer's reports.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/vulkan_backend.h"

namespace facet::runtime::vulkan {

// What the debug messenger has recorded. Only errors are part of the backend's API; warnings
// are kept apart so they can be inspected without failing anyone's tests.
struct DebugMessages {
  std::vector<std::string> errors;
  std::vector<std::string> warnings;
};

class Context {
 public:
  Context() = default;
  ~Context();
  // The messenger callback holds a pointer to `messages`, so a Context never moves.
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Creates everything. On failure returns false with *error set; whatever was created is
  // destroyed by the destructor.
  // float16Arithmetic: enable VK_KHR_shader_float16_int8's shaderFloat16, failing where the
  // device has none (VulkanOptions::float16Arithmetic).
  // renderToSingleSampled: enable VK_EXT_multisampled_render_to_single_sampled (with the
  // VK_KHR_create_renderpass2 and VK_KHR_depth_stencil_resolve it needs) where the device offers it.
  bool init(bool validation, bool float16Arithmetic, bool renderToSingleSampled, std::string* error);
  // Uses the app's instance, device and queue instead (vulkan_backend.h), checking that the
  // device can run Facet; destroys none of them. Validation is the app's instance's business:
  // its layers report to the app's messenger, and `messages` stays empty.
  bool adopt(const AppDevice& app, std::string* error);

  // Index of a memory type allowed by typeBits that has all of `required`, or UINT32_MAX.
  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const;

  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceMemoryProperties memoryProperties{};
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  uint32_t timestampValidBits = 0;  // of queueFamily; 0: the queue cannot write timestamps
  VkQueue queue = VK_NULL_HANDLE;
  bool validationEnabled = false;
  // textureCompressionASTC_LDR is enabled on the device: ASTC images may be created. Only the
  // backend's own device sets it (an app's device may not have enabled it; its ASTC textures are
  // decoded on the CPU).
  bool astcLdr = false;
  DebugMessages messages;
  // vkAllocateMemory calls made for the backend so far (ResourceCounts::memoryAllocations);
  // counted where memory is allocated, which takes the Context as const.
  mutable uint64_t memoryAllocations = 0;
  // Set when VK_EXT_multisampled_render_to_single_sampled is enabled on the device: MSAA renders
  // into single-sample attachments and the driver keeps the samples (vk_pipeline.h ForwardSamples).
  PFN_vkCreateRenderPass2KHR createRenderPass2 = nullptr;

 private:
  bool createInstance(bool validation, std::string* error);
  bool pickPhysicalDevice(std::string* error);
  bool createDevice(bool float16Arithmetic, bool renderToSingleSampled, std::string* error);

  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  bool owned_ = true;  // false: the app's device and instance (adopt)
};

// True when FACET_VK_VALIDATION is set to something other than "" or "0".
bool validationRequestedByEnvironment();

}  // namespace facet::runtime::vulkan
