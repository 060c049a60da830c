#include "vk_pipeline.h"

#include <array>
#include <vector>

#include "facet/abi/shader_abi.h"
#include "facet/runtime/texture_checks.h"
#include "vk_check.h"

namespace facet::runtime::vulkan {
namespace {

bool createShaderModule(VkDevice device, const std::vector<uint32_t>* words, const char* stage, const char* what,
                        VkShaderModule* out, std::string* error) {
  if (!words || words->empty()) {
    *error = std::string(what) + ": no Vulkan " + stage + " SPIR-V";
    return false;
  }
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = words->size() * sizeof(uint32_t);
  info.pCode = words->data();
  if (!check(vkCreateShaderModule(device, &info, nullptr, out), "vkCreateShaderModule", error)) {
    *out = VK_NULL_HANDLE;
    *error = std::string(what) + " (" + stage + "): " + *error;
    return false;
  }
  return true;
}

}  // namespace

AttachmentOps toVulkan(const fg::Attachment& attachment) {
  AttachmentOps ops;
  switch (attachment.load) {
    case fg::LoadOp::Load: ops.load = VK_ATTACHMENT_LOAD_OP_LOAD; break;
    case fg::LoadOp::Clear: ops.load = VK_ATTACHMENT_LOAD_OP_CLEAR; break;
    case fg::LoadOp::DontCare: ops.load = VK_ATTACHMENT_LOAD_OP_DONT_CARE; break;
  }
  ops.store = attachment.store == fg::StoreOp::Store ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  return ops;
}

namespace {

VkAttachmentDescription describeAttachment(VkFormat format, AttachmentOps ops, VkImageLayout finalLayout,
                                           VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT) {
  VkAttachmentDescription a{};
  a.format = format;
  a.samples = samples;
  a.loadOp = ops.load;
  a.storeOp = ops.store;
  a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  // Every frame clears or fully overwrites its targets: old contents never matter.
  a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  a.finalLayout = finalLayout;
  return a;
}

// The forward pass's first subpass, after the previous frame: that frame's reads of the HDR
// image (post-pass sampling, readback copy) and its depth writes finish before this frame's
// layout transitions and writes. One dependency for the merged and the separate render path.
VkSubpassDependency previousFrameToForwardPass() {
  VkSubpassDependency d{};
  d.srcSubpass = VK_SUBPASS_EXTERNAL;
  d.dstSubpass = 0;
  d.srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  d.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  d.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  d.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  return d;
}

VkAttachmentReference2 reference2(const VkAttachmentReference& r, VkImageAspectFlags aspect) {
  VkAttachmentReference2 out{};
  out.sType = VK_STRUCTURE_TYPE_ATTACHMENT_REFERENCE_2;
  out.attachment = r.attachment;
  out.layout = r.layout;
  out.aspectMask = aspect;  // read for input attachments only
  return out;
}

// The render pass `info` describes, made by vkCreateRenderPass2 with subpass 0 rendering
// samples.count samples into its single-sample attachments (VkMultisampledRenderToSingleSampledInfoEXT).
bool createRenderingToSingleSampled(VkDevice device, const VkRenderPassCreateInfo& info, const ForwardSamples& samples,
                                    VkRenderPass* out, std::string* error) {
  std::vector<VkAttachmentDescription2> attachments(info.attachmentCount);
  for (uint32_t i = 0; i < info.attachmentCount; ++i) {
    const VkAttachmentDescription& a = info.pAttachments[i];
    VkAttachmentDescription2& b = attachments[i];
    b.sType = VK_STRUCTURE_TYPE_ATTACHMENT_DESCRIPTION_2;
    b.format = a.format;
    b.samples = a.samples;
    b.loadOp = a.loadOp;
    b.storeOp = a.storeOp;
    b.stencilLoadOp = a.stencilLoadOp;
    b.stencilStoreOp = a.stencilStoreOp;
    b.initialLayout = a.initialLayout;
    b.finalLayout = a.finalLayout;
  }
  // Per subpass: its input, colour and depth references (sized up front: the subpasses point into them).
  std::vector<std::vector<VkAttachmentReference2>> inputs(info.subpassCount), colours(info.subpassCount);
  std::vector<VkAttachmentReference2> depths(info.subpassCount);
  std::vector<VkSubpassDescription2> subpasses(info.subpassCount);
  VkMultisampledRenderToSingleSampledInfoEXT multisampled{};
  multisampled.sType = VK_STRUCTURE_TYPE_MULTISAMPLED_RENDER_TO_SINGLE_SAMPLED_INFO_EXT;
  multisampled.multisampledRenderToSingleSampledEnable = VK_TRUE;
  multisampled.rasterizationSamples = samples.count;
  for (uint32_t s = 0; s < info.subpassCount; ++s) {
    const VkSubpassDescription& a = info.pSubpasses[s];
    VkSubpassDescription2& b = subpasses[s];
    b.sType = VK_STRUCTURE_TYPE_SUBPASS_DESCRIPTION_2;
    b.pipelineBindPoint = a.pipelineBindPoint;
    for (uint32_t i = 0; i < a.inputAttachmentCount; ++i)
      inputs[s].push_back(reference2(a.pInputAttachments[i], VK_IMAGE_ASPECT_COLOR_BIT));
    for (uint32_t i = 0; i < a.colorAttachmentCount; ++i)
      colours[s].push_back(reference2(a.pColorAttachments[i], VK_IMAGE_ASPECT_COLOR_BIT));
    b.inputAttachmentCount = a.inputAttachmentCount;
    b.pInputAttachments = inputs[s].data();
    b.colorAttachmentCount = a.colorAttachmentCount;
    b.pColorAttachments = colours[s].data();
    if (a.pDepthStencilAttachment) {
      depths[s] = reference2(*a.pDepthStencilAttachment, VK_IMAGE_ASPECT_DEPTH_BIT);
      b.pDepthStencilAttachment = &depths[s];
    }
  }
  // The extension resolves depth too and requires a mode for it (SAMPLE_ZERO: the one every
  // device supports); depth's storeOp is DONT_CARE (the frame graph), so the result never
  // reaches memory.
  VkSubpassDescriptionDepthStencilResolve depthResolve{};
  depthResolve.sType = VK_STRUCTURE_TYPE_SUBPASS_DESCRIPTION_DEPTH_STENCIL_RESOLVE;
  depthResolve.depthResolveMode = VK_RESOLVE_MODE_SAMPLE_ZERO_BIT;
  depthResolve.stencilResolveMode = VK_RESOLVE_MODE_NONE;
  multisampled.pNext = &depthResolve;
  subpasses[0].pNext = &multisampled;
  std::vector<VkSubpassDependency2> dependencies(info.dependencyCount);
  for (uint32_t i = 0; i < info.dependencyCount; ++i) {
    const VkSubpassDependency& a = info.pDependencies[i];
    VkSubpassDependency2& b = dependencies[i];
    b.sType = VK_STRUCTURE_TYPE_SUBPASS_DEPENDENCY_2;
    b.srcSubpass = a.srcSubpass;
    b.dstSubpass = a.dstSubpass;
    b.srcStageMask = a.srcStageMask;
    b.dstStageMask = a.dstStageMask;
    b.srcAccessMask = a.srcAccessMask;
    b.dstAccessMask = a.dstAccessMask;
    b.dependencyFlags = a.dependencyFlags;
  }
  VkRenderPassCreateInfo2 info2{};
  info2.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO_2;
  info2.attachmentCount = uint32_t(attachments.size());
  info2.pAttachments = attachments.data();
  info2.subpassCount = uint32_t(subpasses.size());
  info2.pSubpasses = subpasses.data();
  info2.dependencyCount = uint32_t(dependencies.size());
  info2.pDependencies = dependencies.data();
  if (!check(samples.renderToSingleSampled(device, &info2, nullptr, out), "vkCreateRenderPass2KHR", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

bool createRenderPass(VkDevice device, const VkRenderPassCreateInfo& info, const ForwardSamples& samples,
                      VkRenderPass* out, std::string* error) {
  if (samples.count != VK_SAMPLE_COUNT_1_BIT && samples.renderToSingleSampled)
    return createRenderingToSingleSampled(device, info, samples, out, error);
  if (!check(vkCreateRenderPass(device, &info, nullptr, out), "vkCreateRenderPass", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

}  // namespace

namespace {

// Who reads the LDR attachment after its render pass: the readback or copy (TRANSFER_SRC), or,
// with FXAA, the FXAA pass's fragment shader (SHADER_READ_ONLY). The readers of the previous
// frame's image must also be done before this frame writes it (write after read).
struct LdrReaders {
  VkPipelineStageFlags stages;
  VkAccessFlags access;
};
LdrReaders ldrReaders(LdrLayouts layouts) {
  if (layouts.final == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
    return {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT};
  return {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT};
}

}  // namespace

bool createMergedRenderPass(VkDevice device, VkFormat hdrFormat, AttachmentOps hdr, AttachmentOps depth,
                            AttachmentOps ldr, ForwardSamples samples, LdrLayouts layouts, VkRenderPass* out,
                            std::string* error) {
  const bool hdrStored = hdr.store == VK_ATTACHMENT_STORE_OP_STORE;
  const bool msaa = samples.resolveAttachment();
  std::array<VkAttachmentDescription, 4> attachments{
      describeAttachment(hdrFormat, hdr,
                         hdrStored ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
      describeAttachment(kDepthFormat, depth, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                         msaa ? samples.count : VK_SAMPLE_COUNT_1_BIT),
      describeAttachment(kLdrFormat, ldr, layouts.final),
      describeAttachment(hdrFormat, samples.colour, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, samples.count)};
  attachments[2].initialLayout = layouts.initial;

  const VkAttachmentReference hdrColour{msaa ? 3u : 0u, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference hdrResolve{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference hdrInput{msaa && samples.postReadsSamples ? 3u : 0u,
                                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  // Colour slot 1, not 0: the post shader writes LDR at location 1 in every API, because Metal
  // and GLES framebuffer fetch read HDR as colour 0 of the same pass (post_tonemap.frag.glsl).
  const std::array<VkAttachmentReference, 2> postColour{
      VkAttachmentReference{VK_ATTACHMENT_UNUSED, VK_IMAGE_LAYOUT_UNDEFINED},
      VkAttachmentReference{2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
  std::array<VkSubpassDescription, 2> subpasses{};
  subpasses[0].pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpasses[0].colorAttachmentCount = 1;
  subpasses[0].pColorAttachments = &hdrColour;
  subpasses[0].pResolveAttachments = msaa ? &hdrResolve : nullptr;
  subpasses[0].pDepthStencilAttachment = &depthRef;
  subpasses[1].pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpasses[1].inputAttachmentCount = 1;
  subpasses[1].pInputAttachments = &hdrInput;
  subpasses[1].colorAttachmentCount = static_cast<uint32_t>(postColour.size());
  subpasses[1].pColorAttachments = postColour.data();

  std::array<VkSubpassDependency, 5> dependencies{};
  dependencies[0] = previousFrameToForwardPass();
  // Before subpass 1: the previous frame's readback copy of LDR (write after read).
  dependencies[1].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].dstSubpass = 1;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | ldrReaders(layouts).stages;
  dependencies[1].srcAccessMask = 0;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  // Forward -> post: each pixel's HDR write before the same pixel's input-attachment read. By
  // region: a tile's post work waits only for that tile's forward work (the framebuffer fetch).
  dependencies[2].srcSubpass = 0;
  dependencies[2].dstSubpass = 1;
  dependencies[2].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[2].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[2].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  dependencies[2].dstAccessMask = VK_ACCESS_INPUT_ATTACHMENT_READ_BIT;
  dependencies[2].dependencyFlags = VK_DEPENDENCY_BY_REGION_BIT;
  // After: the readback copies LDR (or the FXAA pass samples it), and HDR when stored.
  dependencies[3].srcSubpass = 1;
  dependencies[3].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[3].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  dependencies[3].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[3].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | ldrReaders(layouts).stages;
  dependencies[3].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | ldrReaders(layouts).access;
  // When the post subpass reads the samples, subpass 0 is the resolved HDR's last use: its
  // resolve (and final layout transition) before the readback's copy.
  const bool postReadsSamples = msaa && samples.postReadsSamples;
  dependencies[4] = dependencies[3];
  dependencies[4].srcSubpass = 0;
  dependencies[4].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[4].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[4].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = msaa ? 4 : 3;
  info.pAttachments = attachments.data();
  info.subpassCount = static_cast<uint32_t>(subpasses.size());
  info.pSubpasses = subpasses.data();
  info.dependencyCount = postReadsSamples ? 5 : 4;
  info.pDependencies = dependencies.data();
  return createRenderPass(device, info, samples, out, error);
}

bool createForwardRenderPass(VkDevice device, VkFormat hdrFormat, AttachmentOps hdr, AttachmentOps depthOps,
                             ForwardSamples samples, VkRenderPass* out, std::string* error) {
  const bool msaa = samples.resolveAttachment();
  std::array<VkAttachmentDescription, 3> attachments{};
  VkAttachmentDescription& colour = attachments[0];
  colour.format = hdrFormat;
  colour.samples = VK_SAMPLE_COUNT_1_BIT;
  colour.loadOp = hdr.load;
  colour.storeOp = hdr.store;
  colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  colour.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // cleared: old contents don't matter
  colour.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkAttachmentDescription& depth = attachments[1];
  depth.format = kDepthFormat;
  depth.samples = msaa ? samples.count : VK_SAMPLE_COUNT_1_BIT;
  depth.loadOp = depthOps.load;
  depth.storeOp = depthOps.store;
  depth.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  depth.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  attachments[2] =
      describeAttachment(hdrFormat, samples.colour, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, samples.count);

  VkAttachmentReference colourRef{msaa ? 2u : 0u, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference resolveRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colourRef;
  subpass.pResolveAttachments = msaa ? &resolveRef : nullptr;
  subpass.pDepthStencilAttachment = &depthRef;

  std::array<VkSubpassDependency, 2> dependencies{};
  dependencies[0] = previousFrameToForwardPass();
  // After: the post pass samples the colour.
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT;

  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = msaa ? 3 : 2;
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<uint32_t>(dependencies.size());
  info.pDependencies = dependencies.data();
  return createRenderPass(device, info, samples, out, error);
}

bool createPostRenderPass(VkDevice device, AttachmentOps ldr, LdrLayouts layouts, VkRenderPass* out,
                          std::string* error) {
  VkAttachmentDescription colour{};
  colour.format = kLdrFormat;
  colour.samples = VK_SAMPLE_COUNT_1_BIT;
  colour.loadOp = ldr.load;  // the graph: never written before, so don't care
  colour.storeOp = ldr.store;
  colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  colour.initialLayout = layouts.initial;
  colour.finalLayout = layouts.final;

  VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colourRef;

  std::array<VkSubpassDependency, 2> dependencies{};
  // Before: the previous frame's readback copy of this image must finish (write after read).
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask =
      VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | ldrReaders(layouts).stages;
  dependencies[0].srcAccessMask = 0;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  // After: the readback copies it (or the FXAA pass samples it).
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstStageMask = ldrReaders(layouts).stages;
  dependencies[1].dstAccessMask = ldrReaders(layouts).access;

  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = 1;
  info.pAttachments = &colour;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<uint32_t>(dependencies.size());
  info.pDependencies = dependencies.data();
  if (!check(vkCreateRenderPass(device, &info, nullptr, out), "vkCreateRenderPass", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

namespace {

bool createSetLayout(VkDevice device, const VkDescriptorSetLayoutBinding* bindings, uint32_t count,
                     VkDescriptorSetLayout* out, std::string* error) {
  VkDescriptorSetLayoutCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  info.bindingCount = count;
  info.pBindings = bindings;
  if (!check(vkCreateDescriptorSetLayout(device, &info, nullptr, out), "vkCreateDescriptorSetLayout", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

}  // namespace

bool createShadowRenderPass(VkDevice device, VkRenderPass* out, std::string* error) {
  VkAttachmentDescription atlas{};
  atlas.format = kShadowAtlasFormat;
  atlas.samples = VK_SAMPLE_COUNT_1_BIT;
  atlas.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  atlas.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  atlas.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  atlas.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  atlas.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // every texel is cleared
  atlas.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  const VkAttachmentReference depthRef{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.pDepthStencilAttachment = &depthRef;
  const VkPipelineStageFlags depthStages =
      VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  std::array<VkSubpassDependency, 2> dependencies{};
  // The previous frame's receivers read the atlas before this pass clears it: write after read
  // needs the execution dependency only.
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  dependencies[0].dstStageMask = depthStages;
  dependencies[0].srcAccessMask = 0;
  dependencies[0].dstAccessMask =
      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  // This frame's receivers read what the pass wrote.
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = depthStages;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = 1;
  info.pAttachments = &atlas;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = uint32_t(dependencies.size());
  info.pDependencies = dependencies.data();
  if (!check(vkCreateRenderPass(device, &info, nullptr, out), "vkCreateRenderPass", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

bool createForwardSetLayout(VkDevice device, VkDescriptorSetLayout* out, std::string* error) {
  std::array<VkDescriptorSetLayoutBinding, 4> bindings{};
  const uint32_t numbers[] = {abi::kFrameBinding, abi::kObjectBinding, abi::kMaterialBinding, abi::kShadowBinding};
  for (size_t i = 0; i < bindings.size(); ++i) {
    bindings[i].binding = numbers[i];
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  }
  return createSetLayout(device, bindings.data(), uint32_t(bindings.size()), out, error);
}

bool createPostSetLayout(VkDevice device, VkDescriptorType hdrType,
                         const std::vector<VkDescriptorSetLayoutBinding>& effectBindings, VkDescriptorSetLayout* out,
                         std::string* error) {
  std::vector<VkDescriptorSetLayoutBinding> bindings(1);
  bindings[0].binding = abi::kPostHdrBinding;
  bindings[0].descriptorType = hdrType;
  bindings[0].descriptorCount = 1;
  bindings[0].stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
  bindings.insert(bindings.end(), effectBindings.begin(), effectBindings.end());
  return createSetLayout(device, bindings.data(), uint32_t(bindings.size()), out, error);
}

bool createTextureSetLayout(VkDevice device, VkDescriptorSetLayout* out, std::string* error) {
  std::array<VkDescriptorSetLayoutBinding, kTextureSlots> bindings{};
  for (uint32_t i = 0; i < bindings.size(); ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    bindings[i].descriptorCount = 1;
    // The vertex stage too: per-vertex lighting will sample the lookup tables there.
    bindings[i].stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  }
  return createSetLayout(device, bindings.data(), uint32_t(bindings.size()), out, error);
}

bool createPipelineLayout(VkDevice device, const std::vector<VkDescriptorSetLayout>& setLayouts, VkPipelineLayout* out,
                          std::string* error) {
  VkPipelineLayoutCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  info.setLayoutCount = static_cast<uint32_t>(setLayouts.size());
  info.pSetLayouts = setLayouts.data();
  if (!check(vkCreatePipelineLayout(device, &info, nullptr, out), "vkCreatePipelineLayout", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

VkFormat vertexFormat(VertexFormat format) {
  switch (format) {
    case VertexFormat::Float32x2: return VK_FORMAT_R32G32_SFLOAT;
    case VertexFormat::Float32x3: return VK_FORMAT_R32G32B32_SFLOAT;
    case VertexFormat::Float32x4: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case VertexFormat::Snorm16x4: return VK_FORMAT_R16G16B16A16_SNORM;
    case VertexFormat::Unorm16x2: return VK_FORMAT_R16G16_UNORM;
    case VertexFormat::Snorm10x3w2: return VK_FORMAT_A2B10G10R10_SNORM_PACK32;
    case VertexFormat::Unorm8x4: return VK_FORMAT_R8G8B8A8_UNORM;
  }
  return VK_FORMAT_UNDEFINED;
}

bool supportsVertexLayout(VkPhysicalDevice device, VertexLayout layout, std::string* error) {
  for (const StreamAttribute& a : vertexLayout(layout).attributes) {
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(device, vertexFormat(a.format), &properties);
    if ((properties.bufferFeatures & VK_FORMAT_FEATURE_VERTEX_BUFFER_BIT) == 0) {
      *error = "the device cannot fetch vertex format " + std::to_string(int(vertexFormat(a.format))) +
               " (VkFormat) of the " + toString(layout) + " vertex layout; use VertexPacking::FullPrecision";
      return false;
    }
  }
  return true;
}

bool createGraphicsPipeline(VkDevice device, const PipelineDesc& desc, VkPipeline* out, std::string* error) {
  const bool depthOnly = desc.kind == PipelineKind::Depth;
  // Forward and depth pipelines read the mesh streams and test depth.
  const bool forward = desc.kind == PipelineKind::Forward || depthOnly;
  VkShaderModule vertex = VK_NULL_HANDLE;
  VkShaderModule fragment = VK_NULL_HANDLE;
  if (!createShaderModule(device, desc.vertexSpirv, "vertex", desc.what, &vertex, error)) {
    return false;
  }
  if (!createShaderModule(device, desc.fragmentSpirv, "fragment", desc.what, &fragment, error)) {
    vkDestroyShaderModule(device, vertex, nullptr);
    return false;
  }

  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  stages[0].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex;
  stages[0].pName = "main";
  stages[1].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment;
  stages[1].pName = "main";
  const VkSpecializationMapEntry sampleCountEntry{abi::kPostSampleCountConstantId, 0, sizeof(uint32_t)};
  VkSpecializationInfo sampleCount{1, &sampleCountEntry, sizeof(uint32_t), &desc.postSampleCount};
  if (desc.postSampleCount > 0) stages[1].pSpecializationInfo = &sampleCount;

  // The two streams of shader_abi.h in the mesh's packed formats (vertex_packing.h): the
  // shaders read the same vecN from any of them. Attributes the shaders do not read are allowed
  // by Vulkan (they are simply not fetched).
  const VertexLayoutDesc& layout = vertexLayout(desc.vertexLayout);
  // Then the instance stream: fp32 rows, advanced per instance.
  std::array<VkVertexInputBindingDescription, abi::kStreams> bindings{};
  for (uint32_t s = 0; s < abi::kVertexStreams; ++s) bindings[s] = {s, layout.strides[s], VK_VERTEX_INPUT_RATE_VERTEX};
  bindings[abi::kInstanceStream] = {abi::kInstanceStream, sizeof(abi::InstanceTransform),
                                    VK_VERTEX_INPUT_RATE_INSTANCE};
  std::vector<VkVertexInputAttributeDescription> attributes;
  for (const StreamAttribute& a : layout.attributes)
    attributes.push_back({a.location, a.stream, vertexFormat(a.format), a.offset});
  for (const abi::VertexAttribute& a : abi::kInstanceAttributes)
    attributes.push_back(
        {a.location, abi::kInstanceStream, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(a.offsetFloats * sizeof(float))});
  VkPipelineVertexInputStateCreateInfo vertexInput{};
  vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  if (forward) {
    vertexInput.vertexBindingDescriptionCount = static_cast<uint32_t>(bindings.size());
    vertexInput.pVertexBindingDescriptions = bindings.data();
    vertexInput.vertexAttributeDescriptionCount = static_cast<uint32_t>(attributes.size());
    vertexInput.pVertexAttributeDescriptions = attributes.data();
  }

  VkPipelineInputAssemblyStateCreateInfo inputAssembly{};
  inputAssembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  inputAssembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

  VkPipelineViewportStateCreateInfo viewport{};
  viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  VkPipelineRasterizationStateCreateInfo raster{};
  raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  // Back faces of single-sided materials are culled. The clip-space y flip (vk_convert) mirrors
  // framebuffer y, and Vulkan's orientation formula has its own sign for a y-down framebuffer
  // (spec, "Basic Polygon Rasterization"): the two cancel, so GL's counter-clockwise front
  // faces stay counter-clockwise here (tested by Blending and SphereScene on both backends).
  raster.cullMode = forward && desc.cullBackFaces ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  if (depthOnly) {
    // The shadow pass keeps GL's clip y (glToVulkanDepthClip): a triangle facing the sun runs
    // counter-clockwise in GL's y-up window, and the same window coordinates in Vulkan's y-down
    // framebuffer, whose orientation formula has the opposite sign, make it clockwise.
    raster.frontFace = VK_FRONT_FACE_CLOCKWISE;
    // Constant and slope factors come per cascade (vkCmdSetDepthBias in vk_commands.cpp).
    raster.depthBiasEnable = VK_TRUE;
  }
  raster.lineWidth = 1.0f;

  VkPipelineMultisampleStateCreateInfo multisample{};
  multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  multisample.rasterizationSamples = desc.samples;
  multisample.alphaToCoverageEnable =
      desc.kind == PipelineKind::Forward && desc.alphaToCoverage && desc.samples != VK_SAMPLE_COUNT_1_BIT;

  VkPipelineDepthStencilStateCreateInfo depth{};
  depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
  depth.depthTestEnable = VK_TRUE;
  // Blended surfaces test depth against the opaque ones but do not occlude each other.
  // The background (at the far plane) passes where depth is still the cleared 1 and writes none.
  depth.depthWriteEnable = desc.blending == Blending::Opaque && !desc.atFarPlane ? VK_TRUE : VK_FALSE;
  depth.depthCompareOp = desc.atFarPlane ? VK_COMPARE_OP_LESS_OR_EQUAL : VK_COMPARE_OP_LESS;
  depth.minDepthBounds = 0.0f;
  depth.maxDepthBounds = 1.0f;

  VkPipelineColorBlendAttachmentState blendAttachment{};
  blendAttachment.colorWriteMask =
      VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  if (desc.kind == PipelineKind::Forward && desc.blending != Blending::Opaque) {
    // Premultiplied colour: "over" is src + (1 − src.a)·dst, additive is src + dst.
    const VkBlendFactor dst =
        desc.blending == Blending::Transparent ? VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
    blendAttachment.blendEnable = VK_TRUE;
    blendAttachment.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
    blendAttachment.dstColorBlendFactor = dst;
    blendAttachment.colorBlendOp = VK_BLEND_OP_ADD;
    blendAttachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blendAttachment.dstAlphaBlendFactor = dst;
    blendAttachment.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  if (!forward && desc.constantBlend) {
    blendAttachment.blendEnable = VK_TRUE;
    blendAttachment.srcColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_ALPHA;
    blendAttachment.dstColorBlendFactor = VK_BLEND_FACTOR_CONSTANT_ALPHA;
    blendAttachment.colorBlendOp = VK_BLEND_OP_ADD;
    blendAttachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_ALPHA;
    blendAttachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_CONSTANT_ALPHA;
    blendAttachment.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  // The merged post subpass has colour slots {unused, LDR}: one state per slot, the same for both.
  const std::array<VkPipelineColorBlendAttachmentState, 2> blendAttachments{blendAttachment, blendAttachment};
  VkPipelineColorBlendStateCreateInfo blend{};
  blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  blend.attachmentCount = depthOnly ? 0 : desc.colourSlots;
  blend.pAttachments = blendAttachments.data();

  const std::array<VkDynamicState, 3> dynamicStates{
      VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
      depthOnly ? VK_DYNAMIC_STATE_DEPTH_BIAS : VK_DYNAMIC_STATE_BLEND_CONSTANTS};
  VkPipelineDynamicStateCreateInfo dynamic{};
  dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
  dynamic.dynamicStateCount = desc.constantBlend || depthOnly ? 3 : 2;
  dynamic.pDynamicStates = dynamicStates.data();

  VkGraphicsPipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  info.stageCount = static_cast<uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &inputAssembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = forward ? &depth : nullptr;  // the post pass has no depth attachment
  info.pColorBlendState = depthOnly ? nullptr : &blend;  // no colour attachment
  info.pDynamicState = &dynamic;
  info.layout = desc.layout;
  info.renderPass = desc.renderPass;
  info.subpass = desc.subpass;
  VkResult result = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, out);
  // Modules are only needed while the pipeline is created.
  vkDestroyShaderModule(device, vertex, nullptr);
  vkDestroyShaderModule(device, fragment, nullptr);
  if (!check(result, "vkCreateGraphicsPipelines", error)) {
    *out = VK_NULL_HANDLE;
    *error = std::string(desc.what) + ": " + *error;
    return false;
  }
  return true;
}

}  // namespace facet::runtime::vulkan
