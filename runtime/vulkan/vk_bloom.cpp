#include "vk_bloom.h"

#include <array>

#include "facet/abi/shader_abi.h"
#include "facet/runtime/render_backend.h"
#include "vk_check.h"
#include "vk_context.h"
#include "vk_convert.h"
#include "vk_targets.h"

namespace facet::runtime::vulkan {
namespace {

// One colour attachment ending readable by fragment shaders. A downsample overwrites every pixel
// (initial layout undefined); an upsample blends over what the downsample left (loaded).
bool createBloomRenderPass(VkDevice device, VkFormat format, AttachmentOps ops, bool loads, VkRenderPass* out,
                           std::string* error) {
  VkAttachmentDescription colour{};
  colour.format = format;
  colour.samples = VK_SAMPLE_COUNT_1_BIT;
  colour.loadOp = ops.load;
  colour.storeOp = ops.store;
  colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  colour.initialLayout = loads ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
  colour.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colourRef;
  std::array<VkSubpassDependency, 2> dependencies{};
  // Before: the earlier passes' writes of what this one samples (the forward pass's HDR, the level
  // before) and of this image (its downsample, for an upsample) are visible; the earlier reads of
  // this image (the previous frame's passes and readback copy) are done before it is written.
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                                 VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].dstAccessMask =
      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  // After: the next pass (or the post pass) samples it.
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = 1;
  info.pAttachments = &colour;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = uint32_t(dependencies.size());
  info.pDependencies = dependencies.data();
  if (!check(vkCreateRenderPass(device, &info, nullptr, out), "vkCreateRenderPass (bloom)", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

}  // namespace

bool BloomChain::init(const Context* ctx, VkFormat format, const BloomSettings& bloom, AttachmentOps down,
                      AttachmentOps up, uint32_t slots, bool readBack, std::string* error) {
  ctx_ = ctx;
  format_ = format;
  settings_ = bloom;
  readBack_ = readBack;
  VkDevice device = ctx->device;
  const std::array<VkDescriptorSetLayoutBinding, 2> bindings{
      VkDescriptorSetLayoutBinding{abi::kPostHdrBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                   VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      VkDescriptorSetLayoutBinding{abi::kPostUniformsBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                   VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo setInfo{};
  setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  setInfo.bindingCount = uint32_t(bindings.size());
  setInfo.pBindings = bindings.data();
  if (!check(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout_), "vkCreateDescriptorSetLayout",
             error)) {
    setLayout_ = VK_NULL_HANDLE;
    return false;
  }
  if (!createBloomRenderPass(device, format, down, false, &downPass_, error) ||
      !createBloomRenderPass(device, format, up, true, &upPass_, error) ||
      !createPipelineLayout(device, {setLayout_}, &layout_, error))
    return false;
  const BloomShaders& shaders = bloomShaders();
  PipelineDesc desc;
  desc.kind = PipelineKind::Post;
  desc.vertexSpirv = &shaders.vertexSpirv;
  desc.layout = layout_;
  desc.renderPass = downPass_;
  desc.fragmentSpirv = &shaders.downsampleSpirv;
  desc.what = "bloom downsample shaders";
  if (!createGraphicsPipeline(device, desc, &downPipeline_, error)) return false;
  desc.fragmentSpirv = &shaders.thresholdSpirv;
  desc.what = "bloom threshold shaders";
  if (bloom.threshold > 0 && !createGraphicsPipeline(device, desc, &thresholdPipeline_, error)) return false;
  desc.renderPass = upPass_;
  desc.fragmentSpirv = &shaders.upsampleSpirv;
  desc.constantBlend = true;
  desc.what = "bloom upsample shaders";
  if (!createGraphicsPipeline(device, desc, &upPipeline_, error)) return false;

  VkSamplerCreateInfo sampler{};
  sampler.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  sampler.magFilter = VK_FILTER_LINEAR;
  sampler.minFilter = VK_FILTER_LINEAR;
  sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sampler.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  if (!check(vkCreateSampler(device, &sampler, nullptr, &sampler_), "vkCreateSampler (bloom)", error)) {
    sampler_ = VK_NULL_HANDLE;
    return false;
  }
  const uint32_t perSlot = 2 * uint32_t(bloom.levels) - 1;
  const std::array<VkDescriptorPoolSize, 2> sizes{
      VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, perSlot * slots},
      VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, perSlot * slots}};
  VkDescriptorPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  poolInfo.maxSets = perSlot * slots;
  poolInfo.poolSizeCount = uint32_t(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  if (!check(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool (bloom)", error)) {
    pool_ = VK_NULL_HANDLE;
    return false;
  }
  sets_.assign(slots, std::vector<VkDescriptorSet>(perSlot, VK_NULL_HANDLE));
  const std::vector<VkDescriptorSetLayout> layouts(perSlot, setLayout_);
  for (std::vector<VkDescriptorSet>& sets : sets_) {
    VkDescriptorSetAllocateInfo allocInfo{};
    allocInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    allocInfo.descriptorPool = pool_;
    allocInfo.descriptorSetCount = perSlot;
    allocInfo.pSetLayouts = layouts.data();
    if (!check(vkAllocateDescriptorSets(device, &allocInfo, sets.data()), "vkAllocateDescriptorSets (bloom)", error))
      return false;
  }
  return true;
}

void BloomChain::destroyTargets(VkDevice device, Targets* targets) {
  for (VkFramebuffer framebuffer : targets->framebuffers)
    if (framebuffer) vkDestroyFramebuffer(device, framebuffer, nullptr);
  for (Image& image : targets->levels) destroyImage(device, &image);
  destroyHostBuffer(device, &targets->readback);
  *targets = Targets{};
}

void BloomChain::destroy() {
  if (!ctx_) return;
  VkDevice device = ctx_->device;
  destroyTargets(device, &targets_);
  if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
  if (sampler_) vkDestroySampler(device, sampler_, nullptr);
  for (VkPipeline pipeline : {downPipeline_, thresholdPipeline_, upPipeline_})
    if (pipeline) vkDestroyPipeline(device, pipeline, nullptr);
  if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
  if (setLayout_) vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
  if (downPass_) vkDestroyRenderPass(device, downPass_, nullptr);
  if (upPass_) vkDestroyRenderPass(device, upPass_, nullptr);
  ctx_ = nullptr;
}

bool BloomChain::ensureTargets(uint32_t width, uint32_t height, Targets* retired, std::string* error) {
  if (width == width_ && height == height_ && !targets_.levels.empty()) return true;
  *retired = targets_;
  targets_ = Targets{};
  width_ = width;
  height_ = height;
  Targets t;
  const std::vector<ImageSize> sizes = bloomLevelSizes(width, height, settings_.levels);
  t.levels.resize(sizes.size());
  t.framebuffers.assign(sizes.size(), VK_NULL_HANDLE);
  bool ok = true;
  for (size_t i = 0; i < sizes.size() && ok; ++i) {
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    (i == 0 && readBack_ ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    // The downsample and upsample render passes are compatible: one framebuffer serves both.
    ok = createImage(*ctx_, sizes[i].width, sizes[i].height, format_, usage, VK_IMAGE_ASPECT_COLOR_BIT, &t.levels[i],
                     error) &&
         createFramebuffer(ctx_->device, downPass_, &t.levels[i].view, 1, sizes[i].width, sizes[i].height,
                           &t.framebuffers[i], error);
  }
  const VkDeviceSize texelBytes = format_ == VK_FORMAT_B10G11R11_UFLOAT_PACK32 ? 4 : 8;
  ok = ok && (!readBack_ || createHostBuffer(*ctx_, VkDeviceSize{sizes[0].width} * sizes[0].height * texelBytes,
                                             VK_BUFFER_USAGE_TRANSFER_DST_BIT, &t.readback, error));
  if (!ok) {
    destroyTargets(ctx_->device, &t);
    width_ = height_ = 0;
    return false;
  }
  targets_ = t;
  return true;
}

void BloomChain::writeSets(uint32_t slot, VkImageView hdr, VkBuffer postUniforms) {
  const uint32_t n = levelCount();
  std::vector<VkDescriptorImageInfo> images(2 * size_t{n});
  std::vector<VkWriteDescriptorSet> writes;
  const VkDescriptorBufferInfo buffer{postUniforms, 0, sizeof(abi::PostUniforms)};
  const std::vector<VkDescriptorSet>& sets = sets_[slot];
  auto add = [&](VkDescriptorSet set, size_t image, VkImageView view) {
    images[image] = {sampler_, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = set;
    write.dstBinding = abi::kPostHdrBinding;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &images[image];
    writes.push_back(write);
  };
  // Downsample i reads level i − 1 (the HDR image for 0); upsample i (set n + i) reads level i + 1.
  for (uint32_t i = 0; i < n; ++i) add(sets[i], i, i == 0 ? hdr : targets_.levels[i - 1].view);
  for (uint32_t i = 0; i + 1 < n; ++i) add(sets[settings_.levels + i], n + i, targets_.levels[i + 1].view);
  if (thresholdPipeline_) {
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = sets[0];
    write.dstBinding = abi::kPostUniformsBinding;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    write.pBufferInfo = &buffer;
    writes.push_back(write);
  }
  vkUpdateDescriptorSets(ctx_->device, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

void BloomChain::record(VkCommandBuffer cmd, uint32_t slot) const {
  const uint32_t n = levelCount();
  const std::vector<VkDescriptorSet>& sets = sets_[slot];
  auto draw = [&](VkRenderPass pass, uint32_t level, VkPipeline pipeline, VkDescriptorSet set) {
    const Image& image = targets_.levels[level];
    VkRenderPassBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    begin.renderPass = pass;
    begin.framebuffer = targets_.framebuffers[level];
    begin.renderArea = {{0, 0}, {image.width, image.height}};
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(image.width), float(image.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &begin.renderArea);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set, 0, nullptr);
    if (pass == upPass_) {
      // up_i = w · down_i + (1 − w) · tent(up_{i+1}), w = 1 / (n − i): every level ends with
      // weight 1 / n in level 0 (chunks/bloom.glsl).
      const float w = 1.0f / float(n - level);
      const float constants[4] = {w, w, w, w};
      vkCmdSetBlendConstants(cmd, constants);
    }
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRenderPass(cmd);
  };
  for (uint32_t i = 0; i < n; ++i)
    draw(downPass_, i, i == 0 && thresholdPipeline_ ? thresholdPipeline_ : downPipeline_, sets[i]);
  for (uint32_t i = n - 1; i-- > 0;) draw(upPass_, i, upPipeline_, sets[settings_.levels + i]);
}

void BloomChain::recordReadback(VkCommandBuffer cmd) const {
  const Image& image = targets_.levels[0];
  VkImageMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  barrier.srcAccessMask = 0;  // write-after-read of the layout: the execution dependency suffices
  barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  barrier.oldLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image.image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &barrier);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {image.width, image.height, 1};
  vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, targets_.readback.buffer, 1, &region);
  VkMemoryBarrier host{};
  host.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr, 0,
                       nullptr);
}

void BloomChain::readLevel0(std::vector<float>* rgba, uint32_t* width, uint32_t* height) const {
  const Image& image = targets_.levels[0];
  *width = image.width;
  *height = image.height;
  const size_t texels = size_t{image.width} * image.height;
  rgba->resize(texels * 4);
  if (format_ == VK_FORMAT_B10G11R11_UFLOAT_PACK32) {
    const auto* packed = static_cast<const uint32_t*>(targets_.readback.mapped);
    for (size_t i = 0; i < texels; ++i) {
      unpackB10G11R11(packed[i], &(*rgba)[4 * i]);
      (*rgba)[4 * i + 3] = 1.0f;
    }
  } else {
    const auto* halves = static_cast<const uint16_t*>(targets_.readback.mapped);
    for (size_t i = 0; i < texels * 4; ++i) (*rgba)[i] = halfToFloat(halves[i]);
  }
}

}  // namespace facet::runtime::vulkan
