// How lint's and eval's reports show per-GPU figures, written once for both.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "facet/gpu_stats/mesa_compile.h"

namespace facet::gpu_stats {

// "2.42 cycles (fma), 270 instructions, 2 threads" (Mali) or "230 instructions, 16 waves" (Adreno).
std::string describe(const StageStats& s);

// {"gpu", "renderer", "unavailable"?, "shaders": {pair: {stage: {"instructions", "cycles"?, ...}}}}.
nlohmann::json toJson(const GpuStats& g);

// One line saying where a report's figures come from: the cost model only, or also which GPUs
// Mesa measured, and why a named GPU was not (one clause per GPU).
std::string sourceNote(const std::vector<GpuStats>& gpus);

}  // namespace facet::gpu_stats
