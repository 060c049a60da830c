// The images a frame renders into, their framebuffers, and the host buffers they are copied to
// for readback. Recreated when the frame size changes.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

#include "vk_resources.h"

namespace facet::runtime::vulkan {

class Context;

struct RenderTargets {
  uint32_t width = 0;
  uint32_t height = 0;
  Image hdr;    // RGBA16F: forward colour attachment, sampled by the post pass, copied out
  Image depth;  // D32
  Image ldr;    // RGBA8: post pass output, copied out
  VkFramebuffer forwardFramebuffer = VK_NULL_HANDLE;
  VkFramebuffer postFramebuffer = VK_NULL_HANDLE;
  HostBuffer hdrReadback;  // width*height*4 halves, rows top to bottom
  HostBuffer ldrReadback;  // width*height*4 bytes, rows top to bottom
};

// On failure returns false and leaves *targets destroyed (default-constructed).
bool createRenderTargets(const Context& ctx, uint32_t width, uint32_t height,
                         VkRenderPass forwardPass, VkRenderPass postPass, RenderTargets* targets,
                         std::string* error);
void destroyRenderTargets(VkDevice device, RenderTargets* targets);

}  // namespace facet::runtime::vulkan
