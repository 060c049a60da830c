// `matc lint`'s output formats: compiler-style text, JSON, and SARIF 2.1.0 (what CI systems read
// to annotate a material's line). docs/lint.md shows each.
#pragma once

#include <string>
#include <vector>

#include "facet/ir/diagnostics.h"
#include "facet/lint/lint.h"

namespace facet::lint {

struct LintedFile {
  ir::SourceFile file;
  MaterialLint result;
};

// Diagnostics as the compiler prints them (file:line:col: severity: message [rule], with the
// line and a caret), then a table of every variant's figures.
std::string formatText(const std::vector<LintedFile>& files);
// {"files": [{"path", "material", "diagnostics": [...], "variants": [...]}], "errors", "warnings"}
std::string formatJson(const std::vector<LintedFile>& files);
// One run of tool "matc lint"; columns count Unicode code points, as the compiler's do.
std::string formatSarif(const std::vector<LintedFile>& files, const std::string& toolVersion);

}  // namespace facet::lint
