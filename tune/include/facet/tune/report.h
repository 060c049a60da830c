// `matc tune`'s report: report.md (per tier before and after, and the front of the rendered
// candidates) and report.json with the same figures (docs/tune.md).
#pragma once

#include <string>
#include <vector>

#include "facet/package/package.h"
#include "facet/tune/search.h"

namespace facet::tune {

// One line per tier: "high: 1.234 → 1.100 (mali-g57), 63.2 → 52.1 dB, <changes>", or its failure.
std::vector<std::string> summaryLines(const TuneReport& report);

std::string markdownReport(const TuneReport& report);
std::string jsonReport(const TuneReport& report);
std::vector<package::OutputFile> reportFiles(const TuneReport& report, const std::string& outDir);

}  // namespace facet::tune
