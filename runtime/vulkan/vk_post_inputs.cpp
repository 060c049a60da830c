#include "vk_post_inputs.h"

#include <cstring>

#include "facet/runtime/content_hash.h"
#include "facet/runtime/vignette.h"
#include "vk_check.h"
#include "vk_context.h"

namespace facet::runtime::vulkan {
namespace {

constexpr VkFormat kLutFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // filterable on every Vulkan device
constexpr uint32_t kLutSize = abi::kColorLutSize;
constexpr VkDeviceSize kLutBytes = VkDeviceSize(kLutSize) * kLutSize * kLutSize * 4 * sizeof(uint16_t);
constexpr uint64_t kUploadTimeoutNs = 60ull * 1000 * 1000 * 1000;  // as the frame's fence: a minute means hung

}  // namespace

std::vector<VkDescriptorSetLayoutBinding> PostInputs::bindings(const PostSettings& effects, bool upscale) {
  std::vector<VkDescriptorSetLayoutBinding> out;
  if (effects.colorGrading)
    out.push_back({abi::kPostColorLutBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                   VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  if (effects.bloom)
    out.push_back(
        {abi::kPostBloomBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  if (effects.vignette || effects.bloom || upscale)
    out.push_back(
        {abi::kPostUniformsBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  return out;
}

bool PostInputs::init(const Context* ctx, const PostSettings& effects, bool upscale, uint32_t slots,
                      std::string* error) {
  ctx_ = ctx;
  effects_ = effects;
  upscale_ = upscale;
  written_.assign(slots, VK_NULL_HANDLE);
  VkDevice device = ctx->device;
  if (effects.vignette || effects.bloom || upscale) {
    uniforms_.resize(slots);
    for (HostBuffer& buffer : uniforms_)
      if (!createHostBuffer(*ctx, sizeof(abi::PostUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &buffer, error))
        return false;
  }
  if (!effects.colorGrading) return true;

  VkFormatProperties props{};
  vkGetPhysicalDeviceFormatProperties(ctx->physicalDevice, kLutFormat, &props);
  const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT |
                                      VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((props.optimalTilingFeatures & needed) != needed) {
    *error = "colour grading: RGBA16F 3D images cannot be sampled with linear filtering on this device";
    return false;
  }
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.imageType = VK_IMAGE_TYPE_3D;
  info.format = kLutFormat;
  info.extent = {kLutSize, kLutSize, kLutSize};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  if (!check(vkCreateImage(device, &info, nullptr, &lutImage_), "vkCreateImage (grading LUT)", error)) {
    lutImage_ = VK_NULL_HANDLE;
    return false;
  }
  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(device, lutImage_, &requirements);
  const uint32_t type = ctx->findMemoryType(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkMemoryAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  alloc.allocationSize = requirements.size;
  alloc.memoryTypeIndex = type == UINT32_MAX ? ctx->findMemoryType(requirements.memoryTypeBits, 0) : type;
  if (!check(vkAllocateMemory(device, &alloc, nullptr, &lutMemory_), "vkAllocateMemory (grading LUT)", error)) {
    lutMemory_ = VK_NULL_HANDLE;
    return false;
  }
  if (!check(vkBindImageMemory(device, lutImage_, lutMemory_, 0), "vkBindImageMemory (grading LUT)", error))
    return false;
  VkImageViewCreateInfo view{};
  view.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  view.image = lutImage_;
  view.viewType = VK_IMAGE_VIEW_TYPE_3D;
  view.format = kLutFormat;
  view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  if (!check(vkCreateImageView(device, &view, nullptr, &lutView_), "vkCreateImageView (grading LUT)", error)) {
    lutView_ = VK_NULL_HANDLE;
    return false;
  }
  // Trilinear within the one level, clamped: the shader keeps coordinates on the texel centres
  // of the lattice's ends (chunks/color_grading.glsl).
  VkSamplerCreateInfo sampler{};
  sampler.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  sampler.magFilter = VK_FILTER_LINEAR;
  sampler.minFilter = VK_FILTER_LINEAR;
  sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sampler.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler.maxLod = 0.0f;
  if (!check(vkCreateSampler(device, &sampler, nullptr, &lutSampler_), "vkCreateSampler (grading LUT)", error)) {
    lutSampler_ = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

void PostInputs::destroy() {
  if (!ctx_ || !ctx_->device) return;
  VkDevice device = ctx_->device;
  if (lutSampler_) vkDestroySampler(device, lutSampler_, nullptr);
  if (lutView_) vkDestroyImageView(device, lutView_, nullptr);
  if (lutImage_) vkDestroyImage(device, lutImage_, nullptr);
  if (lutMemory_) vkFreeMemory(device, lutMemory_, nullptr);
  lutSampler_ = VK_NULL_HANDLE;
  lutView_ = VK_NULL_HANDLE;
  lutImage_ = VK_NULL_HANDLE;
  lutMemory_ = VK_NULL_HANDLE;
  for (HostBuffer& buffer : uniforms_) destroyHostBuffer(device, &buffer);
  uniforms_.clear();
  ctx_ = nullptr;
}

// One staging copy into the whole 3D image, leaving it in SHADER_READ_ONLY_OPTIMAL; waited for.
// Frames the app recorded may still sample the old LUT: the queue is drained first (a LUT change
// is a scene edit, not a per-frame event).
bool PostInputs::uploadLut(const ColorLutTexels& lut, std::string* error) {
  VkDevice device = ctx_->device;
  if (lutUploaded_ && !check(vkQueueWaitIdle(ctx_->queue), "vkQueueWaitIdle (grading LUT)", error)) {
    deviceFailed_ = true;
    return false;
  }
  HostBuffer staging;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  bool ok =
      createHostBuffer(*ctx_, kLutBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, &staging, error) &&
      createSubmitRecorder(device, ctx_->queueFamily, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT, &pool, &cmd, &fence, error);
  if (ok) {
    std::memcpy(staging.mapped, lut.rgba.data(), kLutBytes);
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    ok = check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer (grading LUT)", error);
  }
  if (ok) {
    VkImageMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_SHADER_READ_BIT;  // an earlier frame's sampling (waited for; harmless first time)
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // every texel is rewritten
    barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = lutImage_;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &barrier);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {kLutSize, kLutSize, kLutSize};  // x = red, y = green, z = blue: the texels' order
    vkCmdCopyBufferToImage(cmd, staging.buffer, lutImage_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    barrier.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    // The frame is submitted later on the same queue: this covers its post pass's reads.
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &barrier);
    ok = check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer (grading LUT)", error);
  }
  if (ok) {
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    ok = check(vkQueueSubmit(ctx_->queue, 1, &submit, fence), "vkQueueSubmit (grading LUT)", error);
    if (ok &&
        !check(vkWaitForFences(device, 1, &fence, VK_TRUE, kUploadTimeoutNs), "vkWaitForFences (grading LUT)", error)) {
      deviceFailed_ = true;  // the staging buffer may still be read: leak it rather than free it under the device
      return false;
    }
  }
  if (fence) vkDestroyFence(device, fence, nullptr);
  if (pool) vkDestroyCommandPool(device, pool, nullptr);
  destroyHostBuffer(device, &staging);
  return ok;
}

bool PostInputs::prepare(const FrameDesc& frame, VkDescriptorSet set, size_t slot, std::string* error) {
  if (deviceFailed_) {
    *error = "colour grading: an earlier LUT upload did not finish";
    return false;
  }
  if (effects_.colorGrading) {
    const size_t texels = size_t(kLutSize) * kLutSize * kLutSize * 4;
    if (!frame.colorLut || frame.colorLut->rgba.size() != texels) {
      *error = "the post variant grades colour, so the frame needs a colorLut of " + std::to_string(kLutSize) +
               "³ RGBA16F texels" +
               (frame.colorLut ? " (it has " + std::to_string(frame.colorLut->rgba.size() / 4) + ")" : "");
      return false;
    }
    const uint64_t hash = hashBytes(frame.colorLut->rgba.data(), kLutBytes);
    if (!lutUploaded_ || hash != lutHash_) {
      if (!uploadLut(*frame.colorLut, error)) return false;
      lutHash_ = hash;
      lutUploaded_ = true;
    }
  }
  VkDescriptorBufferInfo buffer{};
  if (effects_.vignette || effects_.bloom || upscale_) {
    const abi::PostUniforms uniforms =
        postUniformsFor(frame, effects_.bloom || upscale_, effects_.bloom ? &bloom_ : nullptr);
    std::memcpy(uniforms_[slot].mapped, &uniforms, sizeof(abi::PostUniforms));
    buffer = {uniforms_[slot].buffer, 0, sizeof(abi::PostUniforms)};
  }
  if (written_[slot] == set) return true;
  VkDescriptorImageInfo image{lutSampler_, lutView_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  std::vector<VkWriteDescriptorSet> writes;
  for (const VkDescriptorSetLayoutBinding& b : bindings(effects_, upscale_)) {
    if (b.binding == abi::kPostBloomBinding) continue;  // the backend's (setBloom)
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = set;
    write.dstBinding = b.binding;
    write.descriptorCount = 1;
    write.descriptorType = b.descriptorType;
    if (b.descriptorType == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
      write.pBufferInfo = &buffer;
    else
      write.pImageInfo = &image;
    writes.push_back(write);
  }
  if (!writes.empty()) vkUpdateDescriptorSets(ctx_->device, uint32_t(writes.size()), writes.data(), 0, nullptr);
  written_[slot] = set;
  return true;
}

}  // namespace facet::runtime::vulkan
