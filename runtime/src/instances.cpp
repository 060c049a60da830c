#include <algorithm>
#include <stdexcept>
#include <string>

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

abi::InstanceTransform instanceTransform(const float model[16]) {
  abi::InstanceTransform out{};
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column) out.rows[row][column] = model[4 * column + row];
  return out;
}

std::string instanceCountError(const FrameDesc& frame) {
  size_t total = 0;
  const FrameDraws draws(frame);
  for (size_t i = 0; i < draws.size(); ++i) {
    const size_t count = draws[i].instances.size();
    const std::string which = "draw " + std::to_string(i) + ": ";
    if (count == 0) return which + "has no instances (a draw of one object is one instance)";
    if (count > abi::kMaxInstancesPerDraw)
      return which + std::to_string(count) + " instances, more than the " + std::to_string(abi::kMaxInstancesPerDraw) +
             " a draw may have; split it into several draws";
    total += count;
    if (total > abi::kMaxInstancesPerFrame)
      return which + "takes the frame to " + std::to_string(total) + " instances, more than the " +
             std::to_string(abi::kMaxInstancesPerFrame) + " a frame may have";
  }
  return "";
}

std::string shadowPassError(const ShadowPassDesc& shadow, uint32_t maxAtlasSize) {
  if (shadow.atlasSize == 0 || shadow.atlasSize > maxAtlasSize)
    return "shadow atlas size " + std::to_string(shadow.atlasSize) + " is outside 1.." + std::to_string(maxAtlasSize);
  for (size_t c = 0; c < shadow.cascades.size(); ++c) {
    const ShadowCascadeDesc& cascade = shadow.cascades[c];
    const std::string which = "shadow cascade " + std::to_string(c) + ": ";
    const uint64_t right = uint64_t{cascade.viewport[0]} + cascade.viewport[2];
    const uint64_t bottom = uint64_t{cascade.viewport[1]} + cascade.viewport[3];
    if (cascade.viewport[2] == 0 || cascade.viewport[3] == 0 || right > shadow.atlasSize || bottom > shadow.atlasSize)
      return which + "viewport is outside the " + std::to_string(shadow.atlasSize) + " texel atlas";
    for (uint32_t caster : cascade.casters) {
      if (caster >= shadow.casters.size())
        return which + "caster " + std::to_string(caster) + " is out of range (" +
               std::to_string(shadow.casters.size()) + " casters)";
    }
  }
  return "";
}

void setVertexSlopeBias(const ShadowCascadeDesc& view, float clipDepthSpan, abi::FrameUniforms* frame) {
  if (view.vertexSlopeBias == 0.0f) return;
  std::copy(view.lightAxis, view.lightAxis + 3, frame->lightDirection);
  frame->lightDirection[3] = view.vertexSlopeBias * clipDepthSpan;
  std::copy(view.lightPosition, view.lightPosition + 4, frame->lightColor);
}

FrameDraws::FrameDraws(const FrameDesc& frame) : frame_(&frame), shadowCount_(shadowDrawCount(frame)) {}

const DrawItem& FrameDraws::operator[](size_t i) const {
  if (i < forwardCount()) return frame_->draws[i];
  size_t k = i - forwardCount();
  for (const ShadowCascadeDesc& view : frame_->shadow->cascades) {
    if (k < view.casters.size()) return frame_->shadow->casters[view.casters[k]];
    k -= view.casters.size();
  }
  throw std::out_of_range("FrameDraws: draw " + std::to_string(i) + " of " + std::to_string(size()));
}

size_t shadowDrawCount(const FrameDesc& frame) {
  size_t count = 0;
  if (frame.shadow) {
    for (const ShadowCascadeDesc& cascade : frame.shadow->cascades) count += cascade.casters.size();
  }
  return count;
}

std::vector<DrawItem> oneDrawPerInstance(const std::vector<DrawItem>& draws) {
  std::vector<DrawItem> split;
  for (const DrawItem& draw : draws)
    for (const abi::InstanceTransform& t : draw.instances) {
      split.push_back(draw);
      split.back().instances = {t};
    }
  return split;
}

}  // namespace facet::runtime
