// Recording of one frame's commands: forward pass, post pass, readback copies, and the barriers
// around the app's image. The caller begins and ends the command buffer: the backend's own
// (render, renderToImage) or the app's (recordFrame).
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "facet/runtime/vulkan_backend.h"
#include "vk_app_images.h"
#include "vk_bloom.h"
#include "vk_frame.h"
#include "vk_targets.h"

namespace facet::runtime::vulkan {

// The long-lived objects a frame's commands refer to.
struct FrameObjects {
  bool merged = false;  // the forward render pass is the one render pass; the post pass its subpass 1
  bool msaa = false;    // the forward render pass has the multisampled colour as its last attachment
  // Clear HDR and depth again with vkCmdClearAttachments as the forward subpass starts: lavapipe
  // (Mesa 22.3) leaves the implicit samples of VK_EXT_multisampled_render_to_single_sampled
  // uncleared by loadOp CLEAR (measured: the background read 0 instead of the clear colour).
  bool clearInSubpass = false;
  VkPipelineLayout forwardLayout = VK_NULL_HANDLE;
  VkPipelineLayout postLayout = VK_NULL_HANDLE;
  VkPipeline postPipeline = VK_NULL_HANDLE;
  VkDescriptorSet postSet = VK_NULL_HANDLE;
  // FXAA (null when off): a render pass of its own after the post pass, sampling its output.
  VkPipelineLayout fxaaLayout = VK_NULL_HANDLE;
  VkPipeline fxaaPipeline = VK_NULL_HANDLE;
  VkDescriptorSet fxaaSet = VK_NULL_HANDLE;
  // Bloom (null when off; the separate path): its chain's passes after the forward pass, with the
  // frame slot's sets.
  const BloomChain* bloom = nullptr;
  uint32_t slot = 0;
  // kTimestampCount timestamps: frame start, forward pass done, post (and FXAA) passes done, bloom
  // chain done (with bloom).
  // Null: not timed.
  VkQueryPool timestamps = VK_NULL_HANDLE;
  VkBuffer arena = VK_NULL_HANDLE;  // this frame's uniforms and instance transforms (DrawSlot offsets)
  // The sun's shadow pass (null: none): drawn into shadowFramebuffer (the atlas) by shadowPass
  // before the forward pass, from the slots after the forward draws' (FrameDraws' order).
  const ShadowPassDesc* shadow = nullptr;
  VkRenderPass shadowPass = VK_NULL_HANDLE;
  VkFramebuffer shadowFramebuffer = VK_NULL_HANDLE;
};

// Where the passes write: render passes and framebuffers, and, when the LDR attachment is the
// app's image (AppImage, rendersDirectly), that image for its layout transitions.
struct FrameOutput {
  VkRenderPass forwardPass = VK_NULL_HANDLE;
  VkRenderPass postPass = VK_NULL_HANDLE;  // separate path only
  Framebuffers framebuffers;
  VkRenderPass fxaaPass = VK_NULL_HANDLE;  // FXAA only, into the targets' own LDR
  VkFramebuffer fxaaFramebuffer = VK_NULL_HANDLE;
  const AppImage* directImage = nullptr;
};

inline constexpr uint32_t kTimestampCount = 4;

// With objects.shadow, the shadow pass first: the atlas cleared to depth 1, then per cascade its
// viewport, scissor and depth bias, and its casters. Then the forward pass (clear to clearColor and depth 1, then each
// slot, each with its own mesh buffer) and the post pass (a second render pass, or the next subpass when merged). With
// output.directImage, the image goes from its oldLayout to COLOR_ATTACHMENT_OPTIMAL after
// whatever the app did with it before, and to its newLayout afterwards, visible to any later
// command. forward: the forward pass's size (the HDR and depth targets'); extent: the output's.
void recordPasses(VkCommandBuffer cmd, const FrameObjects& objects, const FrameOutput& output, VkExtent2D forward,
                  VkExtent2D extent, const float clearColor[4], const std::vector<DrawSlot>& slots);

// After recordPasses into the targets' own LDR: copies LDR (and HDR with readBackHdr) into the
// targets' readback buffers, made visible to the host.
void recordReadback(VkCommandBuffer cmd, bool merged, bool readBackHdr, const RenderTargets& targets);

// After recordPasses into the targets' own LDR: copies it into the app's image (which has
// TRANSFER_DST usage), leaving that in its newLayout, visible to any later command.
void recordCopyToAppImage(VkCommandBuffer cmd, const RenderTargets& targets, const AppImage& image);

}  // namespace facet::runtime::vulkan
