// The outputs of `matc eval`: report.md (a table), report.json (the same data) and plot.svg (error
// against cost, Pareto front marked). Deterministic apart from the timings.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "facet/eval/evaluate.h"

namespace facet::eval {

std::string reportMarkdown(const EvalReport& report);
nlohmann::ordered_json reportJson(const EvalReport& report);
std::string reportSvg(const EvalReport& report);

// Writes report.md, report.json and plot.svg into outDir (which must exist).
bool writeReport(const EvalReport& report, const std::string& outDir, std::string* error);

}  // namespace facet::eval
