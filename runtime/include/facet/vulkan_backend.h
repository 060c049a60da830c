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

// nullptr with *error when the device cannot run Facet. VulkanOptions::validation is ignored:
// the app's instance decides which layers run, and reports to the app's messenger
// (validationErrors() stays empty).
std::unique_ptr<RenderBackend> createVulkanBackend(const AppDevice& device, const VulkanOptions& options,
                                                   std::string* error);

}  // namespace facet::runtime
