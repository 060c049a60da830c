// Budgets (per tier, per stage: the most a variant may cost) and baselines (the figures a
// material's variants had when last accepted) for `matc lint`. Both are JSON files a project
// commits; formats in docs/lint.md, example in examples/lint/.
#pragma once

#include <map>
#include <optional>
#include <string>

namespace facet::lint {

// figure name (namedFigures() in lint.h) -> limit
using FigureLimits = std::map<std::string, double>;

struct StageBudget {
  FigureLimits max;                         // figure ≤ limit
  std::optional<double> minRelaxedPercent;  // share of float ops in mediump ≥ this
};

struct Budgets {
  // tier name -> stage ("vertex" | "fragment") -> budget
  std::map<std::string, std::map<std::string, StageBudget>> tiers;
};

struct Baseline {
  // material -> variant key -> stage -> figure -> value
  std::map<std::string, std::map<std::string, std::map<std::string, FigureLimits>>> materials;
};

// Parse JSON text; on failure return nullopt with *error = "<path>: error: <json pointer>: ...".
std::optional<Budgets> parseBudgets(const std::string& path, const std::string& text, std::string* error);
std::optional<Baseline> parseBaseline(const std::string& path, const std::string& text, std::string* error);
// Deterministic text (keys sorted, two-space indent, trailing newline): diffs stay readable.
std::string writeBaseline(const Baseline& baseline);

}  // namespace facet::lint
