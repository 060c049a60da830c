#include "vk_commands.h"

#include "facet/abi/shader_abi.h"

namespace facet::runtime::vulkan {
namespace {

static_assert(abi::kTextureSet == 1, "draws bind sets 0 and 1 with one call");

// A layout transition of the app's image between whatever the app does with it (any stage, any
// access) and the stage and access given.
VkImageMemoryBarrier appImageBarrier(const AppImage& image, VkImageLayout from, VkImageLayout to,
                                     VkAccessFlags srcAccess, VkAccessFlags dstAccess) {
  VkImageMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image.image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  return barrier;
}

constexpr VkAccessFlags kAnyAccess = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;

// Binds what the slot needs that differs from the previous slot's and draws it.
void drawSlot(VkCommandBuffer cmd, const FrameObjects& objects, const DrawSlot& slot, VkPipeline* bound) {
  if (slot.mesh.vertexCount == 0) return;
  if (slot.pipeline != *bound) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, slot.pipeline);
    *bound = slot.pipeline;
  }
  const VkDescriptorSet sets[2] = {slot.set, slot.textureSet};  // sets 0 and abi::kTextureSet
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, objects.forwardLayout, 0, 2, sets, 0, nullptr);
  const VkBuffer streams[abi::kStreams] = {slot.mesh.buffer, slot.mesh.buffer, objects.arena};
  const VkDeviceSize offsets[abi::kStreams] = {slot.mesh.streamOffsets[0], slot.mesh.streamOffsets[1],
                                               slot.instanceOffset};
  vkCmdBindVertexBuffers(cmd, 0, abi::kStreams, streams, offsets);
  if (slot.mesh.indexCount > 0) {
    vkCmdBindIndexBuffer(cmd, slot.mesh.buffer, slot.mesh.indexOffset, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, slot.mesh.indexCount, slot.instanceCount, 0, 0, 0);
  } else {
    vkCmdDraw(cmd, slot.mesh.vertexCount, slot.instanceCount, 0, 0);
  }
}

// The D16 atlas's depth bias unit: Vulkan's r for a fixed-point depth format of n bits is 2^-n
// (spec, "Depth Bias"), one D16 step, so a bias of d in window depth is d / 2^-16 units.
constexpr float kD16BiasUnit = 1.0f / 65536.0f;

void recordShadowPass(VkCommandBuffer cmd, const FrameObjects& objects, const std::vector<DrawSlot>& slots) {
  const ShadowPassDesc& shadow = *objects.shadow;
  VkClearValue clear{};
  clear.depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo passInfo{};
  passInfo.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  passInfo.renderPass = objects.shadowPass;
  passInfo.framebuffer = objects.shadowFramebuffer;
  passInfo.renderArea = {{0, 0}, {shadow.atlasSize, shadow.atlasSize}};
  passInfo.clearValueCount = 1;
  passInfo.pClearValues = &clear;
  vkCmdBeginRenderPass(cmd, &passInfo, VK_SUBPASS_CONTENTS_INLINE);
  size_t next = slots.size();
  for (const ShadowCascadeDesc& cascade : shadow.cascades) next -= cascade.casters.size();
  VkPipeline bound = VK_NULL_HANDLE;
  for (const ShadowCascadeDesc& cascade : shadow.cascades) {
    // Row y of the atlas is GL's window y (no flip, glToVulkanDepthClip).
    const VkViewport viewport{float(cascade.viewport[0]),
                              float(cascade.viewport[1]),
                              float(cascade.viewport[2]),
                              float(cascade.viewport[3]),
                              0.0f,
                              1.0f};
    const VkRect2D scissor{{int32_t(cascade.viewport[0]), int32_t(cascade.viewport[1])},
                           {cascade.viewport[2], cascade.viewport[3]}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdSetDepthBias(cmd, cascade.depthBias / kD16BiasUnit, 0.0f, cascade.slopeBias);
    for (size_t k = 0; k < cascade.casters.size(); ++k) drawSlot(cmd, objects, slots[next++], &bound);
  }
  vkCmdEndRenderPass(cmd);
}

}  // namespace

void recordPasses(VkCommandBuffer cmd, const FrameObjects& objects, const FrameOutput& output, VkExtent2D forward,
                  VkExtent2D extent, const float clearColor[4], const std::vector<DrawSlot>& slots) {
  const auto viewportOf = [](VkExtent2D size) {
    return VkViewport{0.0f, 0.0f, static_cast<float>(size.width), static_cast<float>(size.height), 0.0f, 1.0f};
  };
  const VkViewport forwardViewport = viewportOf(forward);
  const VkRect2D forwardScissor{{0, 0}, forward};
  const VkViewport viewport = viewportOf(extent);
  const VkRect2D scissor{{0, 0}, extent};

  if (output.directImage) {
    const VkImageMemoryBarrier toAttachment =
        appImageBarrier(*output.directImage, output.directImage->oldLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        VK_ACCESS_MEMORY_WRITE_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &toAttachment);
  }

  // Shadow pass (timed with the forward pass), then forward pass.
  if (objects.timestamps) {
    vkCmdResetQueryPool(cmd, objects.timestamps, 0, kTimestampCount);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, objects.timestamps, 0);
  }
  if (objects.shadow) recordShadowPass(cmd, objects, slots);
  // Indexed by attachment (vk_pipeline.h): colour for HDR and the multisampled HDR after LDR,
  // whichever is the one cleared; LDR's (merged path) is unused: its loadOp is DONT_CARE.
  VkClearValue clears[4]{};
  for (VkClearValue& clear : clears) {
    for (int c = 0; c < 4; ++c) clear.color.float32[c] = clearColor[c];
  }
  clears[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo passInfo{};
  passInfo.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  passInfo.renderPass = output.forwardPass;
  passInfo.framebuffer = output.framebuffers.forward;
  passInfo.renderArea = forwardScissor;
  passInfo.clearValueCount = (objects.merged ? 3 : 2) + (objects.msaa ? 1 : 0);
  passInfo.pClearValues = clears;
  vkCmdBeginRenderPass(cmd, &passInfo, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdSetViewport(cmd, 0, 1, &forwardViewport);
  vkCmdSetScissor(cmd, 0, 1, &forwardScissor);
  if (objects.clearInSubpass) {
    VkClearAttachment again[2]{};
    again[0].aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    again[0].colorAttachment = 0;
    again[0].clearValue = clears[0];
    again[1].aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    again[1].clearValue = clears[1];
    const VkClearRect rect{forwardScissor, 0, 1};
    vkCmdClearAttachments(cmd, 2, again, 1, &rect);
  }
  VkPipeline bound = VK_NULL_HANDLE;
  size_t forwardSlots = slots.size();
  if (objects.shadow) {
    for (const ShadowCascadeDesc& cascade : objects.shadow->cascades) forwardSlots -= cascade.casters.size();
  }
  for (size_t i = 0; i < forwardSlots; ++i) drawSlot(cmd, objects, slots[i], &bound);
  // Post pass: one full-screen triangle reading the HDR image (its own pixel when merged).
  // BOTTOM_OF_PIPE: written once everything recorded before it has finished. Inside the merged
  // render pass this splits the subpasses on an immediate-mode GPU like lavapipe; on a tiler the
  // two subpasses interleave per tile and only the total is meaningful.
  // A render pass of one full-screen triangle, nothing cleared.
  const auto beginUncleared = [&](VkRenderPass renderPass, VkFramebuffer framebuffer) {
    passInfo.renderPass = renderPass;
    passInfo.framebuffer = framebuffer;
    passInfo.renderArea = scissor;
    passInfo.clearValueCount = 0;
    passInfo.pClearValues = nullptr;
    vkCmdBeginRenderPass(cmd, &passInfo, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
  };
  if (objects.merged) {
    if (objects.timestamps) {
      vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, objects.timestamps, 1);
    }
    vkCmdNextSubpass(cmd, VK_SUBPASS_CONTENTS_INLINE);
  } else {
    vkCmdEndRenderPass(cmd);
    if (objects.timestamps) {
      vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, objects.timestamps, 1);
    }
    if (objects.bloom) {
      objects.bloom->record(cmd, objects.slot);
      if (objects.timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, objects.timestamps, 3);
    }
    beginUncleared(output.postPass, output.framebuffers.post);
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, objects.postPipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, objects.postLayout, 0, 1, &objects.postSet, 0, nullptr);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdEndRenderPass(cmd);
  if (objects.fxaaPipeline) {
    // The post pass's render pass made its output visible to this pass's fragment shader
    // (vk_pipeline.h kFxaaInputLayouts).
    beginUncleared(output.fxaaPass, output.fxaaFramebuffer);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, objects.fxaaPipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, objects.fxaaLayout, 0, 1, &objects.fxaaSet, 0,
                            nullptr);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRenderPass(cmd);
  }
  if (objects.timestamps) {
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, objects.timestamps, 2);
  }

  if (output.directImage) {
    const VkImageMemoryBarrier done =
        appImageBarrier(*output.directImage, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, output.directImage->newLayout,
                        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, kAnyAccess);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &done);
  }
}

void recordReadback(VkCommandBuffer cmd, bool merged, bool readBackHdr, const RenderTargets& targets) {
  // The render pass left LDR (and, merged, a stored HDR) in TRANSFER_SRC_OPTIMAL; on the
  // separate path HDR still needs its transition, after the post pass's sampling of it.
  VkBufferImageCopy region{};
  region.bufferRowLength = 0;  // tightly packed; image row 0 (the top) first
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {targets.forwardWidth, targets.forwardHeight, 1};
  if (readBackHdr && !merged) {
    VkImageMemoryBarrier hdrBarrier{};
    hdrBarrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    hdrBarrier.srcAccessMask = 0;  // write-after-read only needs the execution dependency
    hdrBarrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    hdrBarrier.oldLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    hdrBarrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    hdrBarrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    hdrBarrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    hdrBarrier.image = targets.hdr.image;
    hdrBarrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &hdrBarrier);
  }
  if (readBackHdr) {
    vkCmdCopyImageToBuffer(cmd, targets.hdr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, targets.hdrReadback.buffer, 1,
                           &region);
  }
  region.imageExtent = {targets.width, targets.height, 1};
  vkCmdCopyImageToBuffer(cmd, targets.ldr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, targets.ldrReadback.buffer, 1,
                         &region);
  VkMemoryBarrier hostBarrier{};
  hostBarrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  hostBarrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  hostBarrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &hostBarrier, 0, nullptr,
                       0, nullptr);
}

void recordCopyToAppImage(VkCommandBuffer cmd, const RenderTargets& targets, const AppImage& image) {
  // To TRANSFER_DST (after whatever the app did with it), copy, then to the layout the app
  // asked for, visible to any later command.
  const VkImageMemoryBarrier toCopy = appImageBarrier(image, image.oldLayout, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                                      kAnyAccess, VK_ACCESS_TRANSFER_WRITE_BIT);
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &toCopy);
  VkImageCopy copy{};
  copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.extent = {targets.width, targets.height, 1};
  vkCmdCopyImage(cmd, targets.ldr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  const VkImageMemoryBarrier done = appImageBarrier(image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, image.newLayout,
                                                    VK_ACCESS_TRANSFER_WRITE_BIT, kAnyAccess);
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &done);
}

}  // namespace facet::runtime::vulkan
