// `matc tune`'s report: report.md (per tier before and after, and the front of the rendered
// candidates), report.json with the same figures and plot.svg (docs/tune.md).
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
// Every rendered candidate's PSNR against its cost, the front, each tier before and after (marked
// and labelled) and the budgets as lines: eval's plot (eval/scatter_plot.h).
std::string plotSvg(const TuneReport& report);
std::vector<package::OutputFile> reportFiles(const TuneReport& report, const std::string& outDir);

}  // namespace facet::tune
