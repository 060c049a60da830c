#include "vk_textures.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <optional>
#include <unordered_set>

#include "facet/runtime/compressed_texture.h"

#include "vk_check.h"
#include "vk_context.h"

namespace facet::runtime::vulkan {
namespace {

// The same bound as the backend's frame fence: a minute means hung.
constexpr uint64_t kUploadTimeoutNs = 60ull * 1000 * 1000 * 1000;
// bufferOffset of a copy must be a multiple of 4 and of the texel size; 16 covers every format.
constexpr VkDeviceSize kStagingAlignment = 16;

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

VkFormat vulkanFormat(TextureFormat format) {
  switch (format) {
    case TextureFormat::Rgba8Unorm: return VK_FORMAT_R8G8B8A8_UNORM;
    case TextureFormat::Rgba8Srgb: return VK_FORMAT_R8G8B8A8_SRGB;
    case TextureFormat::R8Unorm: return VK_FORMAT_R8_UNORM;
    case TextureFormat::Rg16Float: return VK_FORMAT_R16G16_SFLOAT;
    case TextureFormat::Rgba16Float: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case TextureFormat::Astc4x4Unorm: return VK_FORMAT_ASTC_4x4_UNORM_BLOCK;
    case TextureFormat::Astc4x4Srgb: return VK_FORMAT_ASTC_4x4_SRGB_BLOCK;
    case TextureFormat::Astc5x5Unorm: return VK_FORMAT_ASTC_5x5_UNORM_BLOCK;
    case TextureFormat::Astc5x5Srgb: return VK_FORMAT_ASTC_5x5_SRGB_BLOCK;
    case TextureFormat::Astc6x6Unorm: return VK_FORMAT_ASTC_6x6_UNORM_BLOCK;
    case TextureFormat::Astc6x6Srgb: return VK_FORMAT_ASTC_6x6_SRGB_BLOCK;
    case TextureFormat::Astc8x8Unorm: return VK_FORMAT_ASTC_8x8_UNORM_BLOCK;
    case TextureFormat::Astc8x8Srgb: return VK_FORMAT_ASTC_8x8_SRGB_BLOCK;
  }
  return VK_FORMAT_UNDEFINED;
}

// Whether the device samples this texture's format as it is (with the filter the texture asks
// for): always for the uncompressed formats the runtime makes, for ASTC only where the feature
// is enabled and the format reports it.
bool samplesAsIs(const Context& ctx, const Texture& texture) {
  if (!isCompressed(texture.format)) return true;
  if (!ctx.astcLdr) return false;
  VkFormatProperties props{};
  vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice, vulkanFormat(texture.format), &props);
  VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  if (texture.linearFilter) needed |= VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  return (props.optimalTilingFeatures & needed) == needed;
}

}  // namespace

bool TextureCache::init(const Context* ctx, RetireQueue* retire, std::string* error) {
  ctx_ = ctx;
  retire_ = retire;
  // Uploads are recorded into a command buffer of a transient pool and waited on with a fence.
  if (!createSubmitRecorder(ctx->device, ctx->queueFamily,
                            VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                            &commandPool_, &commandBuffer_, &fence_, error)) {
    return false;
  }

  dummySource_ = emptySlotTexture();
  dummyCubeSource_ = emptySlotTexture(true);
  if (!createEntry(dummySource_, TextureIdentity::of(dummySource_), &dummy_, error) ||
      !createEntry(dummyCubeSource_, TextureIdentity::of(dummyCubeSource_), &dummyCube_, error) ||
      !upload({&dummySource_, &dummyCubeSource_}, {&dummy_, &dummyCube_}, error)) {
    return false;
  }
  // What a draw's slots hold before its textures: the dummy of each slot's sampler type.
  emptySlots_.fill(TextureSlot{dummy_.image.view, dummy_.sampler});
  for (const abi::SamplerDesc& sampler : abi::kFrameSamplers) {
    if (sampler.cube) emptySlots_[sampler.binding] = TextureSlot{dummyCube_.image.view, dummyCube_.sampler};
  }
  return true;
}

void TextureCache::destroy() {
  if (!ctx_ || !ctx_->device) return;
  for (auto& entry : textures_) destroyEntry(&entry.second);
  textures_.clear();
  for (Entry& entry : abandoned_) destroyEntry(&entry);
  abandoned_.clear();
  destroyEntry(&dummy_);
  destroyEntry(&dummyCube_);
  for (auto& [key, sampler] : bindingSamplers_) vkDestroySampler(ctx_->device, sampler, nullptr);
  bindingSamplers_.clear();
  destroyHostBuffer(ctx_->device, &staging_);
  if (fence_) vkDestroyFence(ctx_->device, fence_, nullptr);
  fence_ = VK_NULL_HANDLE;
  // Destroying the pool frees its command buffer.
  if (commandPool_) vkDestroyCommandPool(ctx_->device, commandPool_, nullptr);
  commandPool_ = VK_NULL_HANDLE;
  commandBuffer_ = VK_NULL_HANDLE;
  ctx_ = nullptr;
}

void TextureCache::destroyEntry(Entry* entry) {
  if (entry->sampler) vkDestroySampler(ctx_->device, entry->sampler, nullptr);
  entry->sampler = VK_NULL_HANDLE;
  destroyImage(ctx_->device, &entry->image);
}

void TextureCache::retireEntry(const Entry& entry) {
  VkDevice device = ctx_->device;
  retire_->retire([device, sampler = entry.sampler, image = entry.image]() mutable {
    if (sampler) vkDestroySampler(device, sampler, nullptr);
    destroyImage(device, &image);
  });
}

bool TextureCache::createEntry(const Texture& texture, const TextureIdentity& key, Entry* out, std::string* error) {
  const VkFormat format = vulkanFormat(texture.format);
  VkFormatProperties props{};
  vkGetPhysicalDeviceFormatProperties(ctx_->physicalDevice, format, &props);
  VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  if (texture.linearFilter) needed |= VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((props.optimalTilingFeatures & needed) != needed) {
    *error = "texture format " + std::to_string(static_cast<int>(format)) + " cannot be sampled" +
             (texture.linearFilter ? " with linear filtering" : "") + " on this device";
    return false;
  }

  Entry entry;
  entry.key = key;
  entry.lastUsedFrame = frameNumber_;
  const auto levels = static_cast<uint32_t>(texture.levels.size());
  if (!createImage(*ctx_, texture.width, texture.height, format,
                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
                   &entry.image, error, levels, texture.cube)) {
    return false;
  }

  const VkFilter filter = texture.linearFilter ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  // A cube map is filtered across its faces; its wrap flags do not apply (render_backend.h).
  const VkSamplerAddressMode address =
      texture.repeat && !texture.cube ? VK_SAMPLER_ADDRESS_MODE_REPEAT : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSamplerCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = texture.linearFilter ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = address;
  info.addressModeV = texture.clampT ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : address;
  info.addressModeW = address;
  info.minLod = 0.0f;
  info.maxLod = static_cast<float>(levels - 1);
  if (!check(vkCreateSampler(ctx_->device, &info, nullptr, &entry.sampler), "vkCreateSampler", error)) {
    entry.sampler = VK_NULL_HANDLE;
    destroyEntry(&entry);
    return false;
  }
  *out = entry;
  return true;
}

bool TextureCache::upload(const std::vector<const Texture*>& sources, const std::vector<Entry*>& targets,
                          std::string* error) {
  VkDevice device = ctx_->device;
  // Staging layout: every level of every texture, each at an aligned offset.
  std::vector<VkDeviceSize> offsets;
  VkDeviceSize size = 0;
  for (const Texture* texture : sources) {
    for (const std::vector<uint8_t>& level : texture->levels) {
      size = alignUp(size, kStagingAlignment);
      offsets.push_back(size);
      size += level.size();
    }
  }
  if (!createHostBuffer(*ctx_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, &staging_, error)) {
    return false;
  }
  auto* mapped = static_cast<uint8_t*>(staging_.mapped);
  size_t next = 0;
  for (const Texture* texture : sources) {
    for (const std::vector<uint8_t>& level : texture->levels) {
      std::memcpy(mapped + offsets[next++], level.data(), level.size());
    }
  }

  std::vector<VkImageMemoryBarrier> barriers(targets.size());
  for (size_t t = 0; t < targets.size(); ++t) {
    VkImageMemoryBarrier& barrier = barriers[t];
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcAccessMask = 0;
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // fresh image: nothing to keep
    barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = targets[t]->image.image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, targets[t]->image.mipLevels, 0, targets[t]->image.layers};
  }

  bool ok = check(vkResetCommandBuffer(commandBuffer_, 0), "vkResetCommandBuffer", error);
  VkCommandBufferBeginInfo beginInfo{};
  beginInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  ok = ok && check(vkBeginCommandBuffer(commandBuffer_, &beginInfo), "vkBeginCommandBuffer", error);
  if (!ok) {
    destroyHostBuffer(device, &staging_);
    return false;
  }
  vkCmdPipelineBarrier(commandBuffer_, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr,
                       0, nullptr, static_cast<uint32_t>(barriers.size()), barriers.data());
  next = 0;
  for (size_t t = 0; t < targets.size(); ++t) {
    const Texture& texture = *sources[t];
    std::vector<VkBufferImageCopy> regions(texture.levels.size());
    for (size_t level = 0; level < regions.size(); ++level) {
      VkBufferImageCopy& region = regions[level];
      region.bufferOffset = offsets[next++];
      // Tightly packed, row 0 first: texel (s, t) of the data lands at image (x, y) = (s, t),
      // and Vulkan's texture coordinate t = 0 is image row 0, as the contract's rows are.
      region.bufferRowLength = 0;
      region.bufferImageHeight = 0;
      // A cube map's six faces follow each other in the level's bytes: one region, six layers.
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<uint32_t>(level), 0, targets[t]->image.layers};
      region.imageExtent = {mipExtent(texture.width, level), mipExtent(texture.height, level), 1};
    }
    vkCmdCopyBufferToImage(commandBuffer_, staging_.buffer, targets[t]->image.image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, static_cast<uint32_t>(regions.size()), regions.data());
  }
  for (VkImageMemoryBarrier& barrier : barriers) {
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    barrier.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  }
  // The frame's draws are submitted later on the same queue, so this barrier's second scope
  // covers their shader reads.
  vkCmdPipelineBarrier(commandBuffer_, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0, nullptr, 0,
                       nullptr, static_cast<uint32_t>(barriers.size()), barriers.data());
  if (!check(vkEndCommandBuffer(commandBuffer_), "vkEndCommandBuffer", error) ||
      !check(vkResetFences(device, 1, &fence_), "vkResetFences", error)) {
    destroyHostBuffer(device, &staging_);
    return false;
  }

  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commandBuffer_;
  if (!check(vkQueueSubmit(ctx_->queue, 1, &submit, fence_), "vkQueueSubmit (texture upload)", error) ||
      !check(vkWaitForFences(device, 1, &fence_, VK_TRUE, kUploadTimeoutNs), "vkWaitForFences (texture upload)",
             error)) {
    // The staging buffer and images may still be in use: kept until destroy().
    deviceFailed_ = true;
    return false;
  }
  destroyHostBuffer(device, &staging_);
  return true;
}

void TextureCache::releasePending(std::vector<std::pair<const Texture*, Entry>>* pending) {
  for (auto& item : *pending) {
    if (deviceFailed_) {
      abandoned_.push_back(item.second);
    } else {
      destroyEntry(&item.second);
    }
  }
  pending->clear();
}

bool TextureCache::bindingSampler(const TextureSampler& sampler, std::string* error) {
  if (bindingSamplers_.count(sampler.key())) return true;
  const auto address = [](TextureWrap wrap) {
    switch (wrap) {
      case TextureWrap::Repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
      case TextureWrap::MirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
      case TextureWrap::ClampToEdge: break;
    }
    return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  };
  VkSamplerCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  info.magFilter = sampler.magLinear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  info.minFilter = sampler.minLinear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  info.mipmapMode =
      sampler.mipmaps && sampler.mipLinear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = address(sampler.wrapS);
  info.addressModeV = address(sampler.wrapT);
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.minLod = 0.0f;
  // Without mipmaps, level 0 only: GL's GL_NEAREST / GL_LINEAR minification, emulated as the
  // Vulkan specification's note on VkSamplerCreateInfo says (mipmap mode nearest, minLod 0,
  // maxLod 0.25).
  info.maxLod = sampler.mipmaps ? VK_LOD_CLAMP_NONE : 0.25f;
  VkSampler made = VK_NULL_HANDLE;
  if (!check(vkCreateSampler(ctx_->device, &info, nullptr, &made), "vkCreateSampler", error)) return false;
  bindingSamplers_[sampler.key()] = made;
  return true;
}

bool TextureCache::prepare(const FrameDesc& frame, std::string* error) {
  ++frameNumber_;
  const FrameDraws draws(frame);
  for (const DrawItem& draw : draws)
    for (const TextureBinding& binding : draw.textures)
      if (binding.sampler && !bindingSampler(*binding.sampler, error)) return false;
  for (const TextureBinding& binding : frame.frameTextures)
    if (binding.sampler && !bindingSampler(*binding.sampler, error)) return false;
  std::vector<const Texture*> used;
  std::unordered_set<const Texture*> seen;
  const auto collect = [&](const std::vector<TextureBinding>& bindings) {
    for (const TextureBinding& binding : bindings) {
      if (seen.insert(binding.texture).second) used.push_back(binding.texture);
    }
  };
  collect(frame.frameTextures);
  for (const DrawItem& draw : draws) collect(draw.textures);

  std::vector<std::pair<const Texture*, Entry>> pending;
  // What is uploaded for a texture the device cannot sample as it is: its CPU decoding, kept
  // until the upload is done.
  std::vector<std::unique_ptr<Texture>> decoded;
  std::vector<const Texture*> uploadSources;
  for (const Texture* texture : used) {
    TextureIdentity key = TextureIdentity::of(*texture);

    auto found = textures_.find(texture);
    if (found != textures_.end()) {
      if (found->second.key == key) {
        found->second.lastUsedFrame = frameNumber_;
        continue;
      }
      // Changed since its upload; frames in flight may still sample the old copy.
      retireEntry(found->second);
      textures_.erase(found);
    }
    const Texture* source = texture;
    if (!samplesAsIs(*ctx_, *texture)) {
      std::optional<Texture> rgba = decodeCompressedTexture(*texture, error);
      if (!rgba) {
        releasePending(&pending);
        return false;
      }
      decoded.push_back(std::make_unique<Texture>(std::move(*rgba)));
      source = decoded.back().get();
    }
    Entry entry;
    if (!createEntry(*source, key, &entry, error)) {
      releasePending(&pending);
      return false;
    }
    if (isCompressed(texture->format)) ++(source == texture ? compressedUploads_ : decodedUploads_);
    pending.emplace_back(texture, entry);
    uploadSources.push_back(source);
  }

  if (!pending.empty()) {
    std::vector<Entry*> targets;
    for (auto& item : pending) targets.push_back(&item.second);
    if (!upload(uploadSources, targets, error)) {
      releasePending(&pending);
      return false;
    }
    for (auto& item : pending) textures_.emplace(item.first, item.second);
  }

  // Eviction: a texture gone from the scene must not hold device memory forever.
  evictUnusedEntries(textures_, frameNumber_, [&](const Entry& entry) { retireEntry(entry); });
  return true;
}

TextureSlots TextureCache::slotsFor(const FrameDesc& frame, const DrawItem& draw) const {
  TextureSlots slots = emptySlots_;
  const auto assign = [&](const std::vector<TextureBinding>& bindings) {
    for (const TextureBinding& binding : bindings) {
      auto found = textures_.find(binding.texture);
      if (found == textures_.end() || binding.binding >= kTextureSlots) continue;  // checked
      const VkSampler sampler =
          binding.sampler ? bindingSamplers_.at(binding.sampler->key()) : found->second.sampler;  // prepare() made it
      slots[binding.binding] = {found->second.image.view, sampler};
    }
  };
  assign(frame.frameTextures);
  assign(draw.textures);
  return slots;
}

}  // namespace facet::runtime::vulkan
