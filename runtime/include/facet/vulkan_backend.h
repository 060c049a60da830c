// The Vulkan backend on the app's own device: what an engine that already has a VkDevice links
// (facet_runtime_vulkan). render_backend.h's createVulkanBackend(options) makes a device of its
// own instead, for tests, tools and the viewer.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>

#include "facet/render_backend.h"

namespace facet::runtime {

// The app's Vulkan objects. The device must be Vulkan 1.1 with RGBA16F, D32F and RGBA8 colour
// attachments; queueFamily must support graphics. The backend submits to `queue` from the
// thread that calls render() and waits for its own work with a fence: the app must not use the
// queue from another thread meanwhile (Vulkan's external synchronisation rule for queues).
// Everything must outlive the backend; the backend destroys none of it.
struct AppDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
};

// An image of the app's that a frame's tone-mapped, sRGB-encoded result is copied into:
// VK_FORMAT_R8G8B8A8_UNORM (bytes as encoded) or _SRGB (the same bytes, decoded when sampled),
// the frame's size, one mip level and layer, created with VK_IMAGE_USAGE_TRANSFER_DST_BIT.
struct AppImage {
  VkImage image = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  uint32_t width = 0;
  uint32_t height = 0;
  VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // its layout now (UNDEFINED: contents discarded)
  VkImageLayout newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;  // left in this layout
};

class VulkanRenderer : public RenderBackend {
 public:
  // Renders the frame into the app's image instead of reading it back: FrameResult's pixels
  // are not filled. Synchronous like render(): the copy has finished when this returns, and the
  // image is in target.newLayout, visible to all later commands on the device.
  virtual bool renderToImage(const FrameDesc& frame, const AppImage& target, std::string* error) = 0;
};

// nullptr with *error when the device cannot run Facet. VulkanOptions::validation is ignored:
// the app's instance decides which layers run, and reports to the app's messenger
// (validationErrors() stays empty).
std::unique_ptr<VulkanRenderer> createVulkanBackend(const AppDevice& device, const VulkanOptions& options,
                                                    std::string* error);

}  // namespace facet::runtime
