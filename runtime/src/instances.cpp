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
  for (size_t i = 0; i < frame.draws.size(); ++i) {
    const size_t count = frame.draws[i].instances.size();
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
