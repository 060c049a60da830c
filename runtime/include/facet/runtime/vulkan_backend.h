// The Vulkan backend on the app's own device: what an engine that already has a VkDevice links
// (facet_runtime_vulkan). render_backend.h's createVulkanBackend(options) makes a device of its
// own instead, for tests, tools and the viewer.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// The app's Vulkan objects. The device must be Vulkan 1.1 with RGBA16F, D32F and RGBA8 colour
// attachments; queueFamily must support graphics. The backend submits to `queue` from the
// thread that calls render(), renderToImage() or recordFrame() (frames; texture uploads) and
// waits for its own work with a fence: the app must not use the queue from another thread
// meanwhile (Vulkan's external synchronisation rule for queues).
// Everything must outlive the backend; the backend destroys none of it.
struct AppDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
};

// An image of the app's that a frame's tone-mapped, sRGB-encoded result goes into:
// VK_FORMAT_R8G8B8A8_UNORM (bytes as encoded) or _SRGB (the same bytes, decoded when sampled),
// the frame's size, one mip level and layer. Describe it as it was created:
// - `usage` with VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT: the post pass writes the image itself (its
//   LDR attachment is a view of it; no copy). An _SRGB image also needs `createFlags` with
//   VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT, because the post shader writes encoded bytes through a
//   UNORM view (an _SRGB view would encode them twice).
// - otherwise `usage` must have VK_IMAGE_USAGE_TRANSFER_DST_BIT: the backend renders into its
//   own LDR target and copies it in (one extra RGBA8 copy per frame). Kept for images an app
//   cannot make renderable (an _SRGB swapchain without a mutable format, a storage-only image).
// The backend keeps a view and framebuffer per image it rendered into directly, released when
// the image goes unused for kEvictAfterFrames frames (frame_eviction.h), or by forgetImage(),
// which an app must call before destroying such an image (a new image may get the old handle).
struct AppImage {
  VkImage image = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  uint32_t width = 0;
  uint32_t height = 0;
  VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;                 // its layout now (UNDEFINED: contents discarded)
  VkImageLayout newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;  // left in this layout
  VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;           // as created
  VkImageCreateFlags createFlags = 0;                                  // as created
};

class VulkanRenderer : public RenderBackend {
 public:
  // Renders the frame into the app's image instead of reading it back: FrameResult's pixels
  // are not filled. Synchronous like render(): the frame has finished when this returns, and the
  // image is in target.newLayout, visible to all later commands on the device.
  virtual bool renderToImage(const FrameDesc& frame, const AppImage& target, std::string* error) = 0;
  // Records the frame into the app's command buffer instead of submitting it: `cmd` is a primary
  // command buffer the app has begun, outside a render pass, from a pool of AppDevice::queueFamily.
  // The app ends it and submits it to AppDevice::queue itself. The image needs no other
  // synchronisation from the app: the recorded barriers order it after the app's earlier work
  // on the queue (from target.oldLayout) and leave it in target.newLayout for later work.
  // FrameDesc and what it points to may be freed when this returns (uniforms are copied, meshes
  // and textures uploaded). Not timed (FrameResult::gpuTimes is render()'s).
  //
  // Lifetime rule, with N = VulkanOptions::framesInFlight:
  // - the app submits the recorded command buffers once each, to AppDevice::queue, in the order
  //   they were recorded, and before its next render()/renderToImage() call (which first waits
  //   for the queue to be idle, then reuses what earlier frames used);
  // - before recording frame k + N, frame k has finished on the device (the app waited for the
  //   fence of its submission): the backend keeps N copies of a frame's uniforms and descriptor
  //   sets, and frame k + N reuses frame k's; buffers, pipelines and framebuffers it replaces
  //   (a changed mesh, a material block, a resized target) are destroyed N frames later;
  // - target.image stays alive until its frame's fence; the backend stays alive until every
  //   recorded frame has finished (its destructor waits for the device to be idle).
  // Texture uploads (a texture seen for the first time or changed) are still submitted by the
  // backend to AppDevice::queue and waited for during this call.
  virtual bool recordFrame(const FrameDesc& frame, const AppImage& target, VkCommandBuffer cmd, std::string* error) = 0;
  // Releases what the backend keeps for `image` (see AppImage). The app calls it before
  // destroying an image it rendered into, once no submitted frame uses the image any more.
  virtual void forgetImage(VkImage image) = 0;
};

// nullptr with *error when the device cannot run Facet. VulkanOptions::validation is ignored:
// the app's instance decides which layers run, and reports to the app's messenger
// (validationErrors() stays empty).
std::unique_ptr<VulkanRenderer> createVulkanBackend(const AppDevice& device, const VulkanOptions& options,
                                                    std::string* error);

}  // namespace facet::runtime
