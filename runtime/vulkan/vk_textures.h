// Sampled textures of the forward pass (descriptor set abi::kTextureSet): checking the frame's
// TextureBindings, uploading Texture data into device images with all their given mip levels,
// a sampler per texture (or per sampler description a binding gives), a cache so that a texture seen in an earlier
// frame is not uploaded again, and the 1x1 dummy texture bound to every slot a draw leaves empty.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/texture_checks.h"
#include "vk_resources.h"
#include "vk_retire.h"

namespace facet::runtime::vulkan {

class Context;

// Bindings 0..15 of set 1 (kTextureSlots, texture_checks.h): frame textures 0..7, material
// textures 8..15. checkFrameTextures (texture_checks.h) validates bindings before upload.

// What one descriptor of set 1 points at.
struct TextureSlot {
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
};
using TextureSlots = std::array<TextureSlot, kTextureSlots>;

// Device copies of the Textures a backend has drawn with, keyed by the Texture's address.
//
// Cache rule: an entry is reused when the Texture at the same address has the same size, format,
// level sizes, filter and wrap, and the same 64-bit hash of all its level bytes. The hash is one
// pass over the data per frame (a few ms for a 4 MB texture in a debug build); it is what makes a
// texture edited in place, or a new one allocated at a freed one's address, upload again instead
// of sampling stale data. An entry unused for kEvictAfterFrames frames is released.
//
// Uploads are synchronous, like the backend's frames: all new textures of a frame go through one
// staging buffer and one submission, waited for before the frame's own commands are recorded.
class TextureCache {
 public:
  TextureCache() = default;
  TextureCache(const TextureCache&) = delete;
  TextureCache& operator=(const TextureCache&) = delete;

  // Creates the upload command buffer and fence and uploads the dummy texture. ctx and retire
  // must outlive this cache, and destroy() must be called before the device is destroyed.
  // Replaced and evicted textures go through `retire`: frames in flight may sample them.
  bool init(const Context* ctx, RetireQueue* retire, std::string* error);
  // Releases every image, sampler and upload object. The device must be idle. Safe to call on an
  // uninitialised or partly initialised cache, and twice.
  void destroy();

  // Makes every texture of the (already checked) frame and its FrameDraws resident and uploaded, then releases the
  // entries that went unused for too long.
  bool prepare(const FrameDesc& frame, std::string* error);

  // The 16 descriptors of one draw: the frame's textures, then the draw's, the dummy elsewhere.
  // Every texture of frame and draw must have been through prepare().
  TextureSlots slotsFor(const FrameDesc& frame, const DrawItem& draw) const;

  // True once an upload submission failed or did not finish; the device may still be using the
  // upload command buffer, so the backend must stop.
  bool deviceFailed() const { return deviceFailed_; }

  // ASTC textures uploaded as blocks, and decoded to RGBA8 first (the device cannot sample
  // them), since creation.
  uint64_t compressedUploads() const { return compressedUploads_; }
  uint64_t decodedUploads() const { return decodedUploads_; }

 private:
  // Everything the reuse decision compares (see the class comment).
  struct Entry {
    TextureIdentity key;
    Image image;
    VkSampler sampler = VK_NULL_HANDLE;
    uint64_t lastUsedFrame = 0;
  };

  bool createEntry(const Texture& texture, const TextureIdentity& key, Entry* out, std::string* error);
  // Copies the textures' levels into one staging buffer and into their images, leaving every
  // level in SHADER_READ_ONLY_OPTIMAL; one submission, waited for.
  bool upload(const std::vector<const Texture*>& sources, const std::vector<Entry*>& targets, std::string* error);
  void destroyEntry(Entry* entry);
  void retireEntry(const Entry& entry);
  void releasePending(std::vector<std::pair<const Texture*, Entry>>* pending);

  const Context* ctx_ = nullptr;
  RetireQueue* retire_ = nullptr;
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  HostBuffer staging_;  // exists only during an upload (or after one that did not finish)
  bool deviceFailed_ = false;
  uint64_t compressedUploads_ = 0;
  uint64_t decodedUploads_ = 0;

  Texture dummySource_;  // 1x1 RGBA8 (0, 0, 0, 1): what GL returns for an incomplete texture
  Entry dummy_;
  // The same as a cube map, for the ABI's cube slots (abi::SamplerDesc::cube: the environment):
  // a view's type must match the shader's sampler, even for the dummy.
  Texture dummyCubeSource_;
  Entry dummyCube_;
  TextureSlots emptySlots_{};  // every slot's dummy, by its ABI sampler type (init)
  std::unordered_map<const Texture*, Entry> textures_;
  // The samplers bindings ask for (TextureBinding::sampler), by TextureSampler::key(): at most
  // one per distinct description (144 in all), kept until destroy().
  std::unordered_map<uint32_t, VkSampler> bindingSamplers_;
  bool bindingSampler(const TextureSampler& sampler, std::string* error);
  // Entries of an upload whose submission did not finish: released only in destroy(), after
  // the backend has waited for the device.
  std::vector<Entry> abandoned_;
  uint64_t frameNumber_ = 0;
};

}  // namespace facet::runtime::vulkan
