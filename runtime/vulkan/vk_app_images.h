// The app's images the post pass renders into directly (vulkan_backend.h, AppImage): an image
// view and the framebuffer(s) holding it, per app image, kept across frames.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <string>

#include "facet/runtime/vulkan_backend.h"
#include "vk_retire.h"
#include "vk_targets.h"

namespace facet::runtime::vulkan {

// The framebuffers one frame's passes render into: merged, `forward` holds HDR, depth and LDR;
// separate, `forward` HDR and depth and `post` LDR.
struct Framebuffers {
  VkFramebuffer forward = VK_NULL_HANDLE;
  VkFramebuffer post = VK_NULL_HANDLE;
};

// True when the post pass can write `image` itself: COLOR_ATTACHMENT usage, and a UNORM view
// possible (an _SRGB image needs MUTABLE_FORMAT: the post shader writes sRGB-encoded bytes,
// which an _SRGB view would encode a second time).
bool rendersDirectly(const AppImage& image);

// Rejects an image that is not RGBA8 (UNORM or SRGB), not the frame's size, or neither
// renderable directly nor a transfer destination; `caller` names the API call in the message.
bool checkAppImage(const FrameDesc& frame, const AppImage& image, const char* caller, std::string* error);

// Keyed by the VkImage and its format and size. Entries hold the HDR and depth views of the
// targets they were made with, so they are all dropped when the targets are recreated
// (dropAll); an entry unused for kEvictAfterFrames frames is dropped (frame_eviction.h).
// Dropped objects go through the RetireQueue: a frame in flight may still use them.
class AppImageCache {
 public:
  AppImageCache() = default;
  AppImageCache(const AppImageCache&) = delete;
  AppImageCache& operator=(const AppImageCache&) = delete;

  void init(VkDevice device, RetireQueue* retire) {
    device_ = device;
    retire_ = retire;
  }
  // The framebuffers of `image` (which rendersDirectly) with `targets`, made on first use.
  // config's render passes are the backend's own: the app-image passes are compatible with them.
  bool framebuffersFor(const AppImage& image, const RenderTargets& targets, const TargetConfig& config, uint64_t frame,
                       Framebuffers* out, std::string* error);
  // Drops the entry of `image`: the app is about to destroy it (a later image may get its handle).
  void forget(VkImage image);
  void dropAll();
  void evictUnused(uint64_t frame);
  // Destroys everything now; the device must be idle.
  void destroy();

  size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    VkImageView view = VK_NULL_HANDLE;
    Framebuffers framebuffers;
    uint64_t lastUsedFrame = 0;
  };
  void release(const Entry& entry);

  VkDevice device_ = VK_NULL_HANDLE;
  RetireQueue* retire_ = nullptr;
  std::map<std::tuple<VkImage, VkFormat, uint32_t, uint32_t>, Entry> entries_;
};

}  // namespace facet::runtime::vulkan
