#include "vk_app_images.h"

#include <array>
#include <tuple>

#include "facet/runtime/frame_eviction.h"
#include "vk_check.h"
#include "vk_pipeline.h"

namespace facet::runtime::vulkan {
namespace {

void destroyEntryNow(VkDevice device, VkImageView view, Framebuffers framebuffers, bool ownsForward) {
  if (ownsForward && framebuffers.forward) vkDestroyFramebuffer(device, framebuffers.forward, nullptr);
  if (framebuffers.post) vkDestroyFramebuffer(device, framebuffers.post, nullptr);
  if (view) vkDestroyImageView(device, view, nullptr);
}

}  // namespace

bool rendersDirectly(const AppImage& image) {
  if (!(image.usage & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT)) return false;
  return image.format == VK_FORMAT_R8G8B8A8_UNORM || (image.createFlags & VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT);
}

bool checkAppImage(const FrameDesc& frame, const AppImage& image, const char* caller, std::string* error) {
  const std::string size = std::to_string(frame.width) + "x" + std::to_string(frame.height);
  if (!image.image || image.width != frame.width || image.height != frame.height ||
      (image.format != VK_FORMAT_R8G8B8A8_UNORM && image.format != VK_FORMAT_R8G8B8A8_SRGB)) {
    *error = std::string(caller) + ": the app's image must be RGBA8 (UNORM or SRGB) and the frame's size " + size;
    return false;
  }
  if (!rendersDirectly(image) && !(image.usage & VK_IMAGE_USAGE_TRANSFER_DST_BIT)) {
    *error = std::string(caller) +
             ": the app's image needs COLOR_ATTACHMENT usage (and MUTABLE_FORMAT when _SRGB) to be rendered "
             "into, or TRANSFER_DST usage to be copied into";
    return false;
  }
  return true;
}

bool AppImageCache::framebuffersFor(const AppImage& image, const RenderTargets& targets, const TargetConfig& config,
                                    uint64_t frame, Framebuffers* out, std::string* error) {
  const auto key = std::make_tuple(image.image, image.format, image.width, image.height);
  auto found = entries_.find(key);
  if (found != entries_.end()) {
    found->second.lastUsedFrame = frame;
    *out = found->second.framebuffers;
    return true;
  }
  Entry entry;
  entry.lastUsedFrame = frame;
  VkImageViewCreateInfo viewInfo{};
  viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  viewInfo.image = image.image;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = kLdrFormat;  // UNORM even on an _SRGB image: the bytes are already encoded
  viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  if (!check(vkCreateImageView(device_, &viewInfo, nullptr, &entry.view), "vkCreateImageView (app image)", error)) {
    return false;
  }
  bool ok;
  if (config.merged) {
    const std::vector<VkImageView> views = forwardViews(targets, true, entry.view);
    ok = createFramebuffer(device_, config.forwardPass, views.data(), uint32_t(views.size()), image.width, image.height,
                           &entry.framebuffers.forward, error);
  } else {
    entry.framebuffers.forward = targets.forwardFramebuffer;  // the targets' own: HDR and depth
    ok = createFramebuffer(device_, config.postPass, &entry.view, 1, image.width, image.height,
                           &entry.framebuffers.post, error);
  }
  if (!ok) {
    destroyEntryNow(device_, entry.view, entry.framebuffers, config.merged);
    return false;
  }
  entries_.emplace(key, entry);
  *out = entry.framebuffers;
  return true;
}

void AppImageCache::release(const Entry& entry) {
  // Separate path: `forward` is the targets' framebuffer, destroyed with them; `post` is set.
  const bool ownsForward = entry.framebuffers.post == VK_NULL_HANDLE;
  VkDevice device = device_;
  const VkImageView view = entry.view;
  const Framebuffers framebuffers = entry.framebuffers;
  retire_->retire(
      [device, view, framebuffers, ownsForward] { destroyEntryNow(device, view, framebuffers, ownsForward); });
}

void AppImageCache::forget(VkImage image) {
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (std::get<0>(it->first) == image) {
      release(it->second);
      it = entries_.erase(it);
    } else {
      ++it;
    }
  }
}

void AppImageCache::dropAll() {
  for (auto& [key, entry] : entries_) release(entry);
  entries_.clear();
}

void AppImageCache::evictUnused(uint64_t frame) {
  evictUnusedEntries(entries_, frame, [&](const Entry& entry) { release(entry); });
}

void AppImageCache::destroy() {
  for (auto& [key, entry] : entries_) {
    destroyEntryNow(device_, entry.view, entry.framebuffers, entry.framebuffers.post == VK_NULL_HANDLE);
  }
  entries_.clear();
}

}  // namespace facet::runtime::vulkan
