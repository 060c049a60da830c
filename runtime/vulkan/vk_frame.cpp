#include "vk_frame.h"

#include <algorithm>
#include <cstring>
#include <unordered_set>

#include "facet/abi/shader_abi.h"
#include "vk_convert.h"
#include "vk_textures.h"
#include "vk_uniform_blocks.h"

namespace facet::runtime::vulkan {
namespace {

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

}  // namespace

bool checkShadow(const ShadowPassDesc& shadow, const VkPhysicalDeviceLimits& limits, std::string* error) {
  const uint32_t maxAtlasSize =
      std::min({limits.maxImageDimension2D, limits.maxFramebufferWidth, limits.maxFramebufferHeight});
  *error = shadowPassError(shadow, maxAtlasSize);
  return error->empty();
}

bool checkFrame(const FrameDesc& frame, const VkPhysicalDeviceLimits& limits, std::string* error) {
  const uint32_t maxSize = limits.maxImageDimension2D;
  if (frame.width == 0 || frame.height == 0 || frame.width > maxSize || frame.height > maxSize) {
    *error = "frame size " + std::to_string(frame.width) + "x" + std::to_string(frame.height) + " is outside 1.." +
             std::to_string(maxSize);
    return false;
  }
  // The casters are read through the views' indices: those are checked first.
  if (frame.shadow && !checkShadow(*frame.shadow, limits, error)) return false;
  if (std::string why = instanceCountError(frame); !why.empty()) {
    *error = why;
    return false;
  }
  std::unordered_set<const Mesh*> checkedMeshes;
  const FrameDraws draws(frame);
  for (size_t i = 0; i < draws.size(); ++i) {
    const DrawItem& draw = draws[i];
    const std::string which = "draw " + std::to_string(i) + ": ";
    if (!draw.mesh || !draw.program) {
      *error = which + "mesh or program is null";
      return false;
    }
    if (materialBytes(draw).size() > limits.maxUniformBufferRange) {
      *error = which + "materialParams is larger than maxUniformBufferRange";
      return false;
    }
    // A mesh shared by many draws is checked once, at its first draw.
    if (!checkedMeshes.insert(draw.mesh).second) continue;
    const size_t floats = draw.mesh->vertices.size();
    if (floats % abi::kVertexFloats != 0) {
      *error = which + "vertex data is not a whole number of " + std::to_string(abi::kVertexFloats) + "-float vertices";
      return false;
    }
    const size_t vertexCount = floats / abi::kVertexFloats;
    for (uint32_t index : draw.mesh->indices) {
      if (index >= vertexCount) {
        *error = which + "index " + std::to_string(index) + " is out of range (" + std::to_string(vertexCount) +
                 " vertices)";
        return false;
      }
    }
  }
  return checkFrameTextures(frame, limits.maxImageDimension2D, error);
}

VkDeviceSize layoutFrame(const FrameDesc& frame, const VkPhysicalDeviceLimits& limits, std::vector<DrawSlot>* slots,
                         ShadowBlocks* shadow) {
  const VkDeviceSize alignment = std::max<VkDeviceSize>(limits.minUniformBufferOffsetAlignment, 16);
  VkDeviceSize size = alignUp(sizeof(abi::FrameUniforms), alignment);
  // Every draw's set 0 binds ShadowUniforms (the layout has the binding): zeros without a pass.
  shadow->uniformsOffset = size;
  size = alignUp(size + sizeof(abi::ShadowUniforms), alignment);
  shadow->cascadeOffsets.clear();
  if (frame.shadow) {
    for (size_t c = 0; c < frame.shadow->cascades.size(); ++c) {
      shadow->cascadeOffsets.push_back(size);
      size = alignUp(size + sizeof(abi::FrameUniforms), alignment);
    }
  }
  const FrameDraws draws(frame);
  slots->resize(draws.size());
  size_t next = draws.forwardCount();
  for (size_t c = 0; c < shadow->cascadeOffsets.size(); ++c) {
    for (size_t k = 0; k < frame.shadow->cascades[c].casters.size(); ++k) {
      (*slots)[next++].frameOffset = shadow->cascadeOffsets[c];
    }
  }
  for (size_t i = 0; i < draws.size(); ++i) {
    const DrawItem& draw = draws[i];
    DrawSlot& slot = (*slots)[i];
    slot.materialSize = materialRange(materialBytes(draw).size());
    slot.objectOffset = size;
    size = alignUp(size + sizeof(abi::ObjectUniforms), alignment);
    // The instance stream reads the arena as a vertex buffer: 16-byte alignment suits its vec4s.
    slot.instanceOffset = size;
    slot.instanceCount = static_cast<uint32_t>(draw.instances.size());
    size = alignUp(size + draw.instances.size() * sizeof(abi::InstanceTransform), alignment);
    // A persistent block (material instance) lives in its own buffer, not the arena.
    if (draw.materialBlock) continue;
    slot.materialOffset = size;
    size = alignUp(size + slot.materialSize, alignment);
  }
  return size;
}

void writeFrame(const FrameDesc& frame, const std::vector<DrawSlot>& slots, const ShadowBlocks& shadow,
                bool alphaToCoverage, void* arena) {
  auto* base = static_cast<uint8_t*>(arena);
  abi::FrameUniforms frameUniforms = frame.frame;
  glToVulkanClip(frame.frame.viewProjection, frameUniforms.viewProjection);
  frameUniforms.cameraPosition[3] = alphaToCoverage ? 1.0f : 0.0f;
  std::memcpy(base, &frameUniforms, sizeof(frameUniforms));
  const abi::ShadowUniforms shadowUniforms = frame.shadow ? frame.shadow->uniforms : abi::ShadowUniforms{};
  std::memcpy(base + shadow.uniformsOffset, &shadowUniforms, sizeof(shadowUniforms));
  for (size_t c = 0; c < shadow.cascadeOffsets.size(); ++c) {
    // A masked caster's alpha test discards by its coverage alone: no alpha to coverage in the
    // single-sample atlas.
    abi::FrameUniforms cascadeUniforms = frame.frame;
    glToVulkanDepthClip(frame.shadow->cascades[c].viewProjection, cascadeUniforms.viewProjection);
    cascadeUniforms.cameraPosition[3] = 0.0f;
    setVertexSlopeBias(frame.shadow->cascades[c], 1.0f, &cascadeUniforms);
    std::memcpy(base + shadow.cascadeOffsets[c], &cascadeUniforms, sizeof(cascadeUniforms));
  }
  const FrameDraws draws(frame);
  for (size_t i = 0; i < draws.size(); ++i) {
    const DrawItem& draw = draws[i];
    const DrawSlot& slot = slots[i];
    const abi::ObjectUniforms object = objectUniforms(slot.mesh.decode);
    std::memcpy(base + slot.objectOffset, &object, sizeof(object));
    std::memcpy(base + slot.instanceOffset, draw.instances.data(),
                draw.instances.size() * sizeof(abi::InstanceTransform));
    if (draw.materialBlock) continue;
    std::memset(base + slot.materialOffset, 0, slot.materialSize);
    if (!draw.materialParams.empty()) {
      std::memcpy(base + slot.materialOffset, draw.materialParams.data(), draw.materialParams.size());
    }
  }
}

}  // namespace facet::runtime::vulkan
