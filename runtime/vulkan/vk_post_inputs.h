// What the post pass reads besides HDR, for the effects its variant runs (PostSettings): the
// colour-grading LUT, a 3D RGBA16F image sampled trilinearly (binding abi::kPostColorLutBinding of
// the post set), and the PostUniforms block (binding abi::kPostUniformsBinding). The LUT is
// uploaded when the frame's bytes differ from the last upload's (content hash), after the queue
// is idle (a frame in flight may still sample the old one); the block exists once per frame slot
// (VulkanOptions::framesInFlight) and is rewritten when its slot is reused, by which time the
// frame that used it has finished (vulkan_backend.h's rule).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/render_backend.h"
#include "vk_resources.h"

namespace facet::runtime::vulkan {

class Context;

class PostInputs {
 public:
  PostInputs() = default;
  PostInputs(const PostInputs&) = delete;
  PostInputs& operator=(const PostInputs&) = delete;

  // The post set's bindings besides HDR, for the layout and the pool. upscale: the upscaled form
  // (render scale < 1), which reads the output's size from the PostUniforms block.
  static std::vector<VkDescriptorSetLayoutBinding> bindings(const PostSettings& effects, bool upscale);

  // Creates the LUT image and sampler and the uniform buffers (one per frame slot) the effects
  // need. ctx must outlive this, and destroy() must run before the device is destroyed.
  bool init(const Context* ctx, const PostSettings& effects, bool upscale, uint32_t slots, std::string* error);
  // Safe twice and on a partly initialised object. The device must be idle.
  void destroy();

  // Bloom's parameters, written into the block's `bloom` whatever the frame says (the post set's
  // bloom image, abi::kPostBloomBinding, is the backend's to write: it moves with the frame size).
  void setBloom(const BloomSettings& bloom) { bloom_ = bloom; }
  // The slot's PostUniforms buffer (null when the variant reads no block).
  VkBuffer uniformBuffer(size_t slot) const { return uniforms_.empty() ? VK_NULL_HANDLE : uniforms_[slot].buffer; }

  // Uploads the frame's LUT if it changed, writes its uniforms into `slot`'s buffer, and points
  // `set` (that slot's post set) at both.
  bool prepare(const FrameDesc& frame, VkDescriptorSet set, size_t slot, std::string* error);

 private:
  bool uploadLut(const ColorLutTexels& lut, std::string* error);

  const Context* ctx_ = nullptr;
  PostSettings effects_;
  bool upscale_ = false;
  BloomSettings bloom_;
  VkImage lutImage_ = VK_NULL_HANDLE;
  VkDeviceMemory lutMemory_ = VK_NULL_HANDLE;
  VkImageView lutView_ = VK_NULL_HANDLE;
  VkSampler lutSampler_ = VK_NULL_HANDLE;
  uint64_t lutHash_ = 0;
  bool lutUploaded_ = false;
  std::vector<HostBuffer> uniforms_;  // one per frame slot
  // Per frame slot, the set already pointing at this slot's buffer and the LUT (they never move:
  // a LUT change rewrites the same image), so the descriptors are written once per set.
  std::vector<VkDescriptorSet> written_;
  bool deviceFailed_ = false;  // an upload did not finish: stop
};

}  // namespace facet::runtime::vulkan
