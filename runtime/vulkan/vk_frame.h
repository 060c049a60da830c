// One frame's data on the way to the device: checking a FrameDesc, laying its uniforms out in
// one host-visible "arena" buffer, and copying them in. Meshes are not in the arena: they live
// in MeshCache's buffers (vk_meshes.h), uploaded once and shared by every draw of them.
//
// Arena layout: FrameUniforms at offset 0, ShadowUniforms (zero without a shadow pass), one
// FrameUniforms per shadow cascade (its view-projection), then for each draw its ObjectUniforms and
// MaterialParams (unless the draw's parameters are a persistent UniformBlock, kept in
// UniformBlockCache's buffers, vk_uniform_blocks.h), each at a multiple of the uniform offset
// alignment.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/render_backend.h"
#include "vk_meshes.h"

namespace facet::runtime::vulkan {

// Where one draw's data sits in the arena, and what it is drawn with.
struct DrawSlot {
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;         // set 0: the uniform blocks
  VkDescriptorSet textureSet = VK_NULL_HANDLE;  // set 1 (abi::kTextureSet): the 16 samplers
  VkDeviceSize frameOffset = 0;                 // its FrameUniforms: the camera's, or a cascade's
  VkDeviceSize objectOffset = 0;
  VkBuffer materialBuffer = VK_NULL_HANDLE;  // a persistent block's buffer; null: the arena
  VkDeviceSize materialOffset = 0;           // in the arena; 0 in a persistent block's buffer
  VkDeviceSize materialSize = 0;             // >= 16 bytes: an empty MaterialParams binds 16 zero bytes
  VkDeviceSize instanceOffset = 0;           // the draw's InstanceTransforms in the arena (binding 2)
  uint32_t instanceCount = 0;
  MeshLocation mesh;  // the draw's mesh buffer (MeshCache), filled by the backend
};

// The shadow pass's own checks (checkFrame makes them too): shadowPassError with the largest
// atlas the device can make and render into. The frame the backend draws is withShadowDraws'.
bool checkShadow(const ShadowPassDesc& shadow, const VkPhysicalDeviceLimits& limits, std::string* error);

// Where the shadow pass's blocks sit in the arena (the layout above).
struct ShadowBlocks {
  VkDeviceSize uniformsOffset = 0;           // ShadowUniforms, bound to every draw's set 0
  std::vector<VkDeviceSize> cascadeOffsets;  // one FrameUniforms per cascade
};

// Rejects what the device cannot draw or would read out of bounds: an empty or oversized frame,
// null meshes or programs, instance counts out of bounds (instanceCountError), partial vertices, indices past the last
// vertex, oversized params, and malformed texture bindings (checkFrameTextures in vk_textures.h);
// with a shadow pass, an atlas the device cannot make, cascade viewports outside it and caster
// indices out of range (the casters themselves are checked as draws, withShadowDraws).
bool checkFrame(const FrameDesc& frame, const VkPhysicalDeviceLimits& limits, std::string* error);

// Fills the uniform offsets of slots (one per draw; pipeline, sets, mesh and materialBuffer are
// left alone; draws with a persistent materialBlock get no material space in the arena) and
// returns the arena size the frame needs.
// `frame` is withShadowDraws' (the casters' slots get their cascade's frameOffset).
VkDeviceSize layoutFrame(const FrameDesc& frame, const VkPhysicalDeviceLimits& limits, std::vector<DrawSlot>* slots,
                         ShadowBlocks* shadow);

// Copies the frame into the mapped arena at the offsets of layoutFrame, converting the
// view-projection to Vulkan's clip space on the way, and telling masked materials whether their
// coverage goes to alpha to coverage (abi::FrameUniforms::cameraPosition.w).
// The cascades' blocks get the camera's block with the cascade's view-projection converted by
// glToVulkanDepthClip.
void writeFrame(const FrameDesc& frame, const std::vector<DrawSlot>& slots, const ShadowBlocks& shadow,
                bool alphaToCoverage, void* arena);

}  // namespace facet::runtime::vulkan
