#include "facet/gpu_stats/report.h"

#include <cstdio>

namespace facet::gpu_stats {

std::string describe(const StageStats& s) {
  char buf[160];
  std::string out;
  if (s.cycles) {
    std::snprintf(buf, sizeof buf, "%.2f cycles%s%s%s, ", *s.cycles, s.bound.empty() ? "" : " (", s.bound.c_str(),
                  s.bound.empty() ? "" : ")");
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "%.0f instructions", s.instructions);
  out += buf;
  if (s.threads) out += ", " + std::to_string(*s.threads) + (*s.threads == 1 ? " thread" : " threads");
  if (s.waves) out += ", " + std::to_string(*s.waves) + " waves";
  if (s.spills && *s.spills > 0) out += ", " + std::to_string(*s.spills) + " spills";
  return out;
}

nlohmann::json toJson(const GpuStats& g) {
  nlohmann::json j = {{"gpu", g.gpu}, {"renderer", g.renderer}};
  if (!g.unavailable.empty()) j["unavailable"] = g.unavailable;
  nlohmann::json shaders = nlohmann::json::object();
  for (const auto& [pair, stages] : g.shaders)
    for (const StageStats& s : stages) {
      nlohmann::json st = {{"instructions", s.instructions}};
      if (s.cycles) st["cycles"] = *s.cycles;
      if (!s.bound.empty()) st["bound"] = s.bound;
      if (s.threads) st["threads"] = *s.threads;
      if (s.waves) st["waves"] = *s.waves;
      if (s.spills) st["spills"] = *s.spills;
      shaders[pair][s.stage] = st;
    }
  j["shaders"] = shaders;
  return j;
}

std::string sourceNote(const std::vector<GpuStats>& gpus) {
  std::string measured, missing;
  for (const GpuStats& g : gpus) {
    if (g.unavailable.empty())
      measured += (measured.empty() ? "" : ", ") + g.gpu;
    else
      missing += "; " + g.gpu + " not measured: " + g.unavailable;
  }
  std::string note = "cycles: the mobile cost model (compiler/mobile_cost.h, Valhall-class estimate)";
  if (!measured.empty()) note += "; per-GPU figures: Mesa 22.3's compilers on drm-shim (" + measured + ")";
  return note + missing;
}

}  // namespace facet::gpu_stats
