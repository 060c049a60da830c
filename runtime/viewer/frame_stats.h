// facet-view --stats: per-pass GPU time (median over the measured frames) and the frame graph's
// render passes and DRAM traffic, as text or JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "facet/runtime/frame_graph.h"
#include "facet/runtime/render_backend.h"

namespace facet::viewer {

struct MedianTime {
  std::string pass;
  double milliseconds = 0;
};

// The median of the values (0 for none).
double median(std::vector<double> values);
// The median of each pass over frames (every frame lists the same passes in the same order);
// empty when the backend gave no times. A "total" entry sums the passes frame by frame.
std::vector<MedianTime> medianTimes(const std::vector<std::vector<runtime::PassTime>>& frames);

std::string statsText(const runtime::fg::FrameGraph& graph, const runtime::fg::CompiledGraph& compiled,
                      const std::vector<MedianTime>& times, size_t frames);
nlohmann::json statsJson(const runtime::fg::FrameGraph& graph, const runtime::fg::CompiledGraph& compiled,
                         const std::vector<MedianTime>& times, size_t frames);

}  // namespace facet::viewer
