// The bloom chain on Vulkan (chunks/bloom.glsl, render_path.h): a downsample render pass per
// level from the sampled HDR image, then an upsample render pass per level but the last, blending
// the coarser level's tent into the finer one (constant blend, weight 1 / (levels − i) for the
// finer level); the post pass samples level 0. Each level is a colour image in the HDR format,
// sampled bilinearly and clamped. Render passes, pipelines and the sampler live as long as the
// backend; the images and framebuffers follow the frame size; one descriptor set per pass per
// frame slot, rewritten every frame (the images move on a resize).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/render_path.h"
#include "vk_pipeline.h"
#include "vk_resources.h"

namespace facet::runtime::vulkan {

class Context;

class BloomChain {
 public:
  BloomChain() = default;
  BloomChain(const BloomChain&) = delete;
  BloomChain& operator=(const BloomChain&) = delete;

  // down / up: the ops the frame graph gave a downsample pass's and an upsample pass's image.
  // threshold: the first downsample keeps the part above bloom.threshold (reads the PostUniforms
  // block at abi::kPostUniformsBinding). readBack: level 0 can be copied out (FrameResult::bloom).
  bool init(const Context* ctx, VkFormat format, const BloomSettings& bloom, AttachmentOps down, AttachmentOps up,
            uint32_t slots, bool readBack, std::string* error);
  // The device must be idle (or the objects retired by the caller first).
  void destroy();

  // The images for an HDR image of width × height (bloomLevelSizes): made when the size changes.
  // The old ones are handed to `retire` (frames in flight may still read them).
  struct Targets {
    std::vector<Image> levels;
    std::vector<VkFramebuffer> framebuffers;
    HostBuffer readback;  // level 0, as stored (readBack only)
  };
  bool ensureTargets(uint32_t width, uint32_t height, Targets* retired, std::string* error);
  static void destroyTargets(VkDevice device, Targets* targets);

  // Points slot `slot`'s sets at this frame's images, the HDR view and the slot's PostUniforms
  // buffer (needed with a threshold).
  void writeSets(uint32_t slot, VkImageView hdr, VkBuffer postUniforms);
  // Records every pass, after the forward pass left HDR readable by fragment shaders; leaves level
  // 0 readable by the post pass's fragment shader.
  void record(VkCommandBuffer cmd, uint32_t slot) const;
  // After the post pass: copies level 0 into the readback buffer, visible to the host.
  void recordReadback(VkCommandBuffer cmd) const;
  // Level 0 as RGBA floats, rows top to bottom (readBack only).
  void readLevel0(std::vector<float>* rgba, uint32_t* width, uint32_t* height) const;

  VkImageView level0() const { return targets_.levels.empty() ? VK_NULL_HANDLE : targets_.levels[0].view; }
  VkSampler sampler() const { return sampler_; }
  uint32_t levelCount() const { return uint32_t(targets_.levels.size()); }

 private:
  const Context* ctx_ = nullptr;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  BloomSettings settings_;
  bool readBack_ = false;
  VkRenderPass downPass_ = VK_NULL_HANDLE;
  VkRenderPass upPass_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline downPipeline_ = VK_NULL_HANDLE;
  VkPipeline thresholdPipeline_ = VK_NULL_HANDLE;
  VkPipeline upPipeline_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  // Per slot, settings_.levels downsample sets then settings_.levels − 1 upsample sets.
  std::vector<std::vector<VkDescriptorSet>> sets_;
  uint32_t width_ = 0, height_ = 0;  // the HDR size the targets were made for
  Targets targets_;
};

}  // namespace facet::runtime::vulkan
