#include "frame_stats.h"

#include <algorithm>
#include <cstdio>

namespace facet::viewer {

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<MedianTime> medianTimes(const std::vector<std::vector<runtime::PassTime>>& frames) {
  std::vector<MedianTime> out;
  if (frames.empty() || frames.front().empty()) return out;
  const size_t passes = frames.front().size();
  std::vector<double> totals;
  for (size_t p = 0; p < passes; ++p) {
    std::vector<double> values;
    for (const auto& frame : frames) {
      if (frame.size() == passes) values.push_back(frame[p].milliseconds);
    }
    out.push_back({frames.front()[p].pass, median(values)});
  }
  for (const auto& frame : frames) {
    double sum = 0;
    for (const runtime::PassTime& t : frame) sum += t.milliseconds;
    totals.push_back(sum);
  }
  out.push_back({"total", median(totals)});
  return out;
}

std::string statsText(const runtime::fg::FrameGraph& graph, const runtime::fg::CompiledGraph& compiled,
                      const std::vector<MedianTime>& times, size_t frames) {
  std::string text = runtime::fg::describe(graph, compiled);
  if (times.empty()) return text + "GPU time: not available from this backend\n";
  char line[160];
  std::snprintf(line, sizeof line, "GPU time, median of %zu frames:", frames);
  text += line;
  for (const MedianTime& t : times) {
    std::snprintf(line, sizeof line, " %s %.3f ms", t.pass.c_str(), t.milliseconds);
    text += line;
  }
  return text + "\n";
}

nlohmann::json statsJson(const runtime::fg::FrameGraph& graph, const runtime::fg::CompiledGraph& compiled,
                         const std::vector<MedianTime>& times, size_t frames) {
  nlohmann::json renderPasses = nlohmann::json::array();
  for (const runtime::fg::RenderPass& rp : compiled.renderPasses) {
    nlohmann::json subpasses = nlohmann::json::array();
    for (uint32_t p : rp.subpasses) subpasses.push_back(graph.pass(p).name);
    nlohmann::json attachments = nlohmann::json::array();
    for (const runtime::fg::Attachment& a : rp.attachments) {
      attachments.push_back({{"resource", graph.resource(a.resource).name},
                             {"load", runtime::fg::toString(a.load)},
                             {"store", runtime::fg::toString(a.store)},
                             {"input_attachment", a.inputAttachment}});
    }
    renderPasses.push_back({{"subpasses", subpasses}, {"attachments", attachments}});
  }
  nlohmann::json resources = nlohmann::json::array();
  for (runtime::fg::ResourceId id = 0; id < graph.resourceCount(); ++id) {
    const runtime::fg::ResourceTraffic& t = compiled.traffic[id];
    resources.push_back({{"name", graph.resource(id).name},
                         {"loaded_bytes", t.loadedBytes},
                         {"stored_bytes", t.storedBytes},
                         {"sampled_bytes", t.sampledBytes},
                         {"transient", t.transient}});
  }
  nlohmann::json gpu = nlohmann::json::object();
  for (const MedianTime& t : times) gpu[t.pass] = t.milliseconds;
  return {{"render_passes", renderPasses},
          {"resources", resources},
          {"loaded_bytes", compiled.loadedBytes()},
          {"stored_bytes", compiled.storedBytes()},
          {"sampled_bytes", compiled.sampledBytes()},
          {"frames_measured", frames},
          {"gpu_median_ms", times.empty() ? nlohmann::json(nullptr) : gpu}};
}

}  // namespace facet::viewer
