// The images a frame renders into, their framebuffers, and the host buffers they are copied to
// for readback. Recreated when the frame size changes.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "vk_resources.h"

namespace facet::runtime::vulkan {

class Context;

// How the targets are used, fixed for a backend's life (the frame graph decides it).
struct TargetConfig {
  bool merged = false;        // one render pass: HDR is an input attachment, not sampled
  bool readBackHdr = false;   // HDR is copied to hdrReadback after the frame
  bool hdrTransient = false;  // never loaded or stored: TRANSIENT_ATTACHMENT usage
  bool depthTransient = false;
  // MSAA: the forward pass renders into hdrSamples and depth at this count and resolves into hdr
  // (vk_pipeline.h ForwardSamples); both multisampled images are transient.
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  // VK_EXT_multisampled_render_to_single_sampled: no hdrSamples image, HDR and depth single-sample
  // images the render pass renders `samples` samples into.
  bool renderToSingleSampled = false;
  // The post subpass reads hdrSamples as its input attachment (ForwardSamples::postReadsSamples).
  bool postReadsSamples = false;
  // The backend's own LDR target, its readback buffers and the framebuffers holding it: needed
  // by render() and by copies into app images it cannot render to, not when every frame goes
  // straight into the app's image (then they would be an unused RGBA8 image and buffer).
  bool ownOutput = true;
  VkFormat hdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // or VK_FORMAT_B10G11R11_UFLOAT_PACK32
  VkRenderPass forwardPass = VK_NULL_HANDLE;           // merged: the one render pass
  VkRenderPass postPass = VK_NULL_HANDLE;              // separate path only
  // FXAA: the post pass writes toneMapped (sampled) and the FXAA pass, fxaaPass, writes ldr. Needs
  // ownOutput (the FXAA pass does not write an app's image directly).
  bool fxaa = false;
  VkRenderPass fxaaPass = VK_NULL_HANDLE;
  // Below 1: HDR, depth and the forward framebuffer are scaledSize() of the output (render_path.h).
  double renderScale = 1.0;
};

struct RenderTargets {
  uint32_t width = 0;  // the output's (LDR) size
  uint32_t height = 0;
  uint32_t forwardWidth = 0;  // HDR's and depth's: the output's, or scaled by TargetConfig::renderScale
  uint32_t forwardHeight = 0;
  Image hdr;         // RGBA16F or B10G11R11: forward colour attachment, read by the post pass, maybe copied out
  Image depth;       // D32, at TargetConfig::samples
  Image hdrSamples;  // MSAA only: the forward pass's multisampled colour, resolved into hdr
  Image ldr;         // RGBA8: post pass output (FXAA pass output with FXAA), copied out (ownOutput only)
  Image toneMapped;  // FXAA only: RGBA8, the post pass output the FXAA pass samples
  VkFramebuffer forwardFramebuffer = VK_NULL_HANDLE;  // merged: HDR, depth, LDR (ownOutput only)
  VkFramebuffer postFramebuffer = VK_NULL_HANDLE;     // separate path only (ownOutput only)
  VkFramebuffer fxaaFramebuffer = VK_NULL_HANDLE;     // FXAA only: ldr
  HostBuffer
      hdrReadback;  // width*height texels as stored (8 or 4 bytes), rows top to bottom (when read back; ownOutput only)
  HostBuffer ldrReadback;  // width*height*4 bytes, rows top to bottom (ownOutput only)
};

// The views of the forward render pass's framebuffer in its attachment order (vk_pipeline.h):
// HDR, depth, then (merged) the LDR view `ldr`, then the multisampled HDR when there is one.
std::vector<VkImageView> forwardViews(const RenderTargets& targets, bool merged, VkImageView ldr);

// A framebuffer of `count` views for `pass` (or any render pass compatible with it).
bool createFramebuffer(VkDevice device, VkRenderPass pass, const VkImageView* views, uint32_t count, uint32_t width,
                       uint32_t height, VkFramebuffer* out, std::string* error);

// On failure returns false and leaves *targets destroyed (default-constructed).
bool createRenderTargets(const Context& ctx, uint32_t width, uint32_t height, const TargetConfig& config,
                         RenderTargets* targets, std::string* error);
void destroyRenderTargets(VkDevice device, RenderTargets* targets);

}  // namespace facet::runtime::vulkan
