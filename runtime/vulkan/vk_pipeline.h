// Render passes, descriptor set layouts, pipeline layouts and graphics pipelines of the two
// passes. Each function creates one object; the caller owns and destroys it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/frame_graph.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/vertex_packing.h"

namespace facet::runtime::vulkan {

inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // VulkanOptions::hdrFormat's default
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr VkFormat kLdrFormat = VK_FORMAT_R8G8B8A8_UNORM;
inline constexpr VkFormat kShadowAtlasFormat = VK_FORMAT_D16_UNORM;  // ShadowPassDesc's atlas

// Load and store operations of one attachment, as the frame graph derived them.
struct AttachmentOps {
  VkAttachmentLoadOp load = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  VkAttachmentStoreOp store = VK_ATTACHMENT_STORE_OP_DONT_CARE;
};
AttachmentOps toVulkan(const fg::Attachment& attachment);

// MSAA of the forward pass (render_path.h): with more than one sample, its colour and depth are
// multisampled attachments (cleared, never stored: transient) and the colour is resolved inside
// the render pass (pResolveAttachments) into the single-sample HDR attachment the post pass reads.
// The multisampled colour is the render pass's last attachment, so attachments 0..2 keep their
// meaning at every sample count.
// With renderToSingleSampled (VK_EXT_multisampled_render_to_single_sampled, the mobile form) there
// is no multisampled attachment at all: HDR and depth are single-sample images and subpass 0
// renders `count` samples into them, the driver resolving at the end of the subpass (on a tiler the
// samples never leave tile memory and need no allocation).
struct ForwardSamples {
  VkSampleCountFlagBits count = VK_SAMPLE_COUNT_1_BIT;
  AttachmentOps colour;  // of the multisampled colour (the resolve target's are `hdr`'s)
  PFN_vkCreateRenderPass2KHR renderToSingleSampled = nullptr;
  // Merged path with resolveAttachment(): the post subpass reads the multisampled colour as its
  // input attachment (subpassInputMS, every sample tone-mapped) instead of the resolved HDR, which
  // is still resolved for a readback.
  bool postReadsSamples = false;
  // An explicit multisampled colour attachment, resolved through pResolveAttachments.
  bool resolveAttachment() const { return count != VK_SAMPLE_COUNT_1_BIT && !renderToSingleSampled; }
};

// Separate path, render pass 1: the forward pass into RGBA16F colour (left in
// SHADER_READ_ONLY_OPTIMAL for the post pass to sample) and D32 depth. Attachments: 0 HDR,
// 1 depth, 2 the multisampled HDR (MSAA only).
bool createForwardRenderPass(VkDevice device, VkFormat hdrFormat, AttachmentOps hdr, AttachmentOps depth,
                             ForwardSamples samples, VkRenderPass* out, std::string* error);
// Where the LDR attachment starts and ends. The backend's own LDR target: undefined (every pixel
// is written) to TRANSFER_SRC_OPTIMAL for readback. The app's image (vulkan_backend.h):
// COLOR_ATTACHMENT_OPTIMAL throughout, the transitions from and to the app's layouts being
// barriers recorded around the pass (vk_commands.h). Layouts do not enter render pass
// compatibility, so the pipelines and framebuffers of one serve the other.
struct LdrLayouts {
  VkImageLayout initial = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImageLayout final = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
};
inline constexpr LdrLayouts kAppImageLdrLayouts{VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
// FXAA: the post pass's output is the tone-mapped image the FXAA pass samples.
inline constexpr LdrLayouts kFxaaInputLayouts{VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};

// Separate path, render pass 2: the post pass into RGBA8.
bool createPostRenderPass(VkDevice device, AttachmentOps ldr, LdrLayouts layouts, VkRenderPass* out,
                          std::string* error);
// Merged path: one render pass, attachments 0 HDR, 1 depth, 2 LDR, 3 the multisampled HDR (MSAA
// only, resolved into 0 at the end of subpass 0). Subpass 0 is the forward
// pass (colour HDR, depth); subpass 1 the post pass (input attachment HDR; colour slots
// {unused, LDR}, so LDR is location 1 as in the GLES and Metal fetch forms), joined by
// a BY_REGION dependency so a tiler keeps HDR in tile memory. HDR ends in TRANSFER_SRC_OPTIMAL
// when it is stored for readback; LDR as `layouts` say.
bool createMergedRenderPass(VkDevice device, VkFormat hdrFormat, AttachmentOps hdr, AttachmentOps depth,
                            AttachmentOps ldr, ForwardSamples samples, LdrLayouts layouts, VkRenderPass* out,
                            std::string* error);

// The shadow pass (docs/shadows.md): one D16 depth attachment, cleared to 1 and stored, left in
// SHADER_READ_ONLY_OPTIMAL for the forward pass's receivers; its dependencies order it after the
// previous frame's reads of the atlas and before this frame's.
bool createShadowRenderPass(VkDevice device, VkRenderPass* out, std::string* error);

// Set 0 of material shaders: FrameUniforms, ObjectUniforms, MaterialParams, ShadowUniforms
// (shader_abi.h).
bool createForwardSetLayout(VkDevice device, VkDescriptorSetLayout* out, std::string* error);
// Set 0 of the post shaders: the HDR colour, as a combined image sampler (separate path) or an
// input attachment (merged path), and the bindings of the variant's effects (vk_post_inputs.h).
bool createPostSetLayout(VkDevice device, VkDescriptorType hdrType,
                         const std::vector<VkDescriptorSetLayoutBinding>& effectBindings, VkDescriptorSetLayout* out,
                         std::string* error);
// Set 1 (abi::kTextureSet) of material shaders: bindings 0..15 (frame textures, then material
// textures), all combined image samplers visible to both stages. Fixed rather than reflected per
// shader, so one pipeline layout serves every material; a binding a draw does not provide is
// bound to a 1x1 dummy texture (partially bound descriptors are not in Vulkan 1.1 core).
bool createTextureSetLayout(VkDevice device, VkDescriptorSetLayout* out, std::string* error);
// setLayouts[i] becomes set i.
bool createPipelineLayout(VkDevice device, const std::vector<VkDescriptorSetLayout>& setLayouts, VkPipelineLayout* out,
                          std::string* error);

enum class PipelineKind {
  Forward,  // abi vertex stream, depth test LESS + write
  Post,     // no vertex input (gl_VertexIndex full-screen triangle), no depth
  Depth,    // the shadow pass: abi vertex stream, no colour, depth LESS + write, dynamic depth bias
};

struct PipelineDesc {
  PipelineKind kind = PipelineKind::Forward;
  Blending blending = Blending::Opaque;                     // forward pipelines only
  bool cullBackFaces = false;                               // forward and depth pipelines only
  bool atFarPlane = false;                                  // forward pipelines only: DrawItem::atFarPlane
  VertexLayout vertexLayout = VertexLayout::FullPrecision;  // forward pipelines only: the streams' formats
  const std::vector<uint32_t>* vertexSpirv = nullptr;
  const std::vector<uint32_t>* fragmentSpirv = nullptr;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  uint32_t subpass = 0;
  uint32_t colourSlots = 1;                               // colour attachments of that subpass (merged post subpass: 2)
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // the subpass's attachments' (forward: MSAA)
  // Masked materials under MSAA: the fragment's alpha (its coverage, output_blending.glsl) masks
  // the samples it writes, so an alpha-tested edge is antialiased like a geometric one.
  bool alphaToCoverage = false;
  // Post pipelines only: src · (1 − constant alpha) + dst · constant alpha, the constant a dynamic
  // state (the bloom upsample, chunks/bloom.glsl).
  bool constantBlend = false;
  // Post pipelines only: the per-sample form's sample count (abi::kPostSampleCountConstantId);
  // 0 for shaders without the constant.
  uint32_t postSampleCount = 0;
  const char* what = "";  // names the shaders in error messages
};

// The Vulkan format of a stream attribute (vertex_packing.h).
VkFormat vertexFormat(VertexFormat format);
// Whether the device's vertex fetch reads every format of the layout; false with *error naming
// the first one it cannot.
bool supportsVertexLayout(VkPhysicalDevice device, VertexLayout layout, std::string* error);

// Viewport and scissor are dynamic state, so a pipeline does not depend on the frame size.
bool createGraphicsPipeline(VkDevice device, const PipelineDesc& desc, VkPipeline* out, std::string* error);

}  // namespace facet::runtime::vulkan
