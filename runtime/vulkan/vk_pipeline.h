// Render passes, descriptor set layouts, pipeline layouts and graphics pipelines of the two
// passes. Each function creates one object; the caller owns and destroys it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "facet/render_backend.h"

namespace facet::runtime::vulkan {

inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr VkFormat kLdrFormat = VK_FORMAT_R8G8B8A8_UNORM;

// Forward pass: RGBA16F colour (cleared, stored, left in SHADER_READ_ONLY_OPTIMAL for the post
// pass) and D32 depth (cleared, discarded).
bool createForwardRenderPass(VkDevice device, VkRenderPass* out, std::string* error);
// Post pass: RGBA8 colour (fully overwritten, stored, left in TRANSFER_SRC_OPTIMAL for readback).
bool createPostRenderPass(VkDevice device, VkRenderPass* out, std::string* error);

// Set 0 of material shaders: FrameUniforms, ObjectUniforms, MaterialParams (shader_abi.h).
bool createForwardSetLayout(VkDevice device, VkDescriptorSetLayout* out, std::string* error);
// Set 0 of the post shaders: the HDR colour as a combined image sampler.
bool createPostSetLayout(VkDevice device, VkDescriptorSetLayout* out, std::string* error);
// Set 1 (abi::kTextureSet) of material shaders: bindings 0..15 (frame textures, then material
// textures), all combined image samplers visible to both stages. Fixed rather than reflected per
// shader, so one pipeline layout serves every material; a binding a draw does not provide is
// bound to a 1x1 dummy texture (partially bound descriptors are not in Vulkan 1.1 core).
bool createTextureSetLayout(VkDevice device, VkDescriptorSetLayout* out, std::string* error);
// setLayouts[i] becomes set i.
bool createPipelineLayout(VkDevice device, const std::vector<VkDescriptorSetLayout>& setLayouts,
                          VkPipelineLayout* out, std::string* error);

enum class PipelineKind {
  kForward,  // abi vertex stream, depth test LESS + write
  kPost,     // no vertex input (gl_VertexIndex full-screen triangle), no depth
};

struct PipelineDesc {
  PipelineKind kind = PipelineKind::kForward;
  Blending blending = Blending::Opaque;  // forward pipelines only
  bool cullBackFaces = false;            // forward pipelines only
  const std::vector<uint32_t>* vertexSpirv = nullptr;
  const std::vector<uint32_t>* fragmentSpirv = nullptr;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  const char* what = "";  // names the shaders in error messages
};

// Viewport and scissor are dynamic state, so a pipeline does not depend on the frame size.
bool createGraphicsPipeline(VkDevice device, const PipelineDesc& desc, VkPipeline* out,
                            std::string* error);

}  // namespace facet::runtime::vulkan
