// The outputs of `matc eval`: report.md (a table), report.json (the same data) and plot.svg (error
// against cost, Pareto front marked). Deterministic apart from the timings.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "facet/eval/evaluate.h"
#include "facet/package/package.h"

namespace facet::eval {

std::string reportMarkdown(const EvalReport& report);
nlohmann::ordered_json reportJson(const EvalReport& report);
std::string reportSvg(const EvalReport& report);

// Every file of the report in outDir: report.md, report.json, plot.svg and images/*.png (one per
// configuration with maths of its own and view).
std::vector<package::OutputFile> reportFiles(const EvalReport& report, const std::string& outDir);

// Writes reportFiles() together (package::writeFiles), creating outDir/images first.
bool writeReport(const EvalReport& report, const std::string& outDir, std::string* error);

}  // namespace facet::eval
