// What the post pass reads besides HDR, for the effects its variant runs (PostSettings): the
// colour-grading LUT, a 3D RGBA16F image sampled trilinearly (binding abi::kPostColorLutBinding of
// the post set), and the PostUniforms block (binding abi::kPostUniformsBinding). The LUT is
// uploaded when the frame's bytes differ from the last upload's (content hash); the block is
// rewritten every frame (the backend waits for each frame, so the buffer is idle).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "facet/render_backend.h"
#include "vk_resources.h"

namespace facet::runtime::vulkan {

class Context;

class PostInputs {
 public:
  PostInputs() = default;
  PostInputs(const PostInputs&) = delete;
  PostInputs& operator=(const PostInputs&) = delete;

  // The post set's bindings besides HDR, for the layout and the pool.
  static std::vector<VkDescriptorSetLayoutBinding> bindings(const PostSettings& effects);

  // Creates the LUT image and sampler and the uniform buffer the effects need. ctx must outlive
  // this, and destroy() must run before the device is destroyed.
  bool init(const Context* ctx, const PostSettings& effects, std::string* error);
  // Safe twice and on a partly initialised object. The device must be idle.
  void destroy();

  // Uploads the frame's LUT if it changed, writes its uniforms, and points `set` at both (the
  // first time). The device must be idle (between frames).
  bool prepare(const FrameDesc& frame, VkDescriptorSet set, std::string* error);

 private:
  bool uploadLut(const ColorLutTexels& lut, std::string* error);

  const Context* ctx_ = nullptr;
  PostSettings effects_;
  VkImage lutImage_ = VK_NULL_HANDLE;
  VkDeviceMemory lutMemory_ = VK_NULL_HANDLE;
  VkImageView lutView_ = VK_NULL_HANDLE;
  VkSampler lutSampler_ = VK_NULL_HANDLE;
  uint64_t lutHash_ = 0;
  bool lutUploaded_ = false;
  HostBuffer uniforms_;
  VkDescriptorSet written_ = VK_NULL_HANDLE;  // the set already pointing at these
  bool deviceFailed_ = false;                 // an upload did not finish: stop
};

}  // namespace facet::runtime::vulkan
