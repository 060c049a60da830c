// Recording of one frame's command buffer: forward pass, post pass, readback copies.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "facet/vulkan_backend.h"
#include "vk_frame.h"
#include "vk_targets.h"

namespace facet::runtime::vulkan {

// The long-lived objects a frame's commands refer to.
struct FrameObjects {
  bool merged = false;       // forwardPass is the one render pass; the post pass is its subpass 1
  bool readBackHdr = false;  // copy HDR to the targets' hdrReadback
  VkRenderPass forwardPass = VK_NULL_HANDLE;
  VkRenderPass postPass = VK_NULL_HANDLE;  // separate path only
  VkPipelineLayout forwardLayout = VK_NULL_HANDLE;
  VkPipelineLayout postLayout = VK_NULL_HANDLE;
  VkPipeline postPipeline = VK_NULL_HANDLE;
  VkDescriptorSet postSet = VK_NULL_HANDLE;
  // kTimestampCount timestamps: frame start, forward pass done, post pass done. Null: not timed.
  VkQueryPool timestamps = VK_NULL_HANDLE;
};

inline constexpr uint32_t kTimestampCount = 3;

// Records into cmd (reset first): the forward pass (clear to clearColor and depth 1, then each
// slot), the post pass (a second render pass, or the next subpass when merged), and copies of
// LDR (and HDR when read back) into the targets' readback buffers, made visible to the host. Each slot draws its own mesh buffer.
// With appImage, LDR is copied into the app's image (vulkan_backend.h) instead of the readback buffer.
bool recordFrame(VkCommandBuffer cmd, const FrameObjects& objects, const RenderTargets& targets,
                 const float clearColor[4], const std::vector<DrawSlot>& slots, const AppImage* appImage,
                 std::string* error);

}  // namespace facet::runtime::vulkan
