// `matc lint`: the precision and instruction-count check CI runs on materials
// (docs/lint.md). One call lints one material: the language's own diagnostics, the precision
// rules over its IR (precision_rules.h), and per built variant the static cost and interface
// figures of its optimised SPIR-V against GLES 3.0's limits, the tier budgets and a baseline.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "facet/compiler/cost_figures.h"
#include "facet/compiler/spirv_interface.h"
#include "facet/gpu_stats/mesa_compile.h"
#include "facet/ir/diagnostics.h"
#include "facet/lint/budgets.h"
#include "facet/lint/shadow_precision.h"
#include "facet/permutations/tiers.h"
#include "facet/permutations/variant_key.h"

namespace facet::lint {

// The mobile cost model's estimate (as `matc eval` reports it), the instruction counts of the
// same walk of the SPIR-V, and the stage's interface.
using StageFigures = compiler::StageFigures;

struct VariantFigures {
  std::string key;  // e.g. "high.dir1"
  StageFigures vertex, fragment;
  ShadowPrecision shadow;  // what feeds its depth compares (receiver variants; none elsewhere)
};

struct LintOptions {
  std::vector<permutations::Tier> tiers = permutations::supportedTiers();
  std::vector<int> pointLightCounts{0};
  const Budgets* budgets = nullptr;    // per-tier limits (budgets.h); none: no budget rules
  const Baseline* baseline = nullptr;  // committed figures; none: no regression rule
  double baselineTolerance = 0.05;     // a figure may grow by this fraction over the baseline
  // Sun-shadow receivers to build and check, as `matc compile --shadows` (0: none).
  std::vector<int> shadowCascadeCounts{0};
  bool spotShadows = false;  // spot-shadow receivers (.sp1), as `matc compile --spot-shadows`
  // Per-GPU figures from Mesa's compilers (docs/mesa-statistics.md), e.g. {"mali-g57"}; none:
  // the cost model's figures only. Informational: no rule reads them.
  std::vector<std::string> gpus;
  gpu_stats::MesaTool mesaTool;
  // The tiers the material ships from its tuning file (compiler::BuildOptions::tunedTiers), so that
  // the figures are those of the package `matc compile` builds. Empty: the presets.
  std::map<permutations::Tier, permutations::TierConfig> tunedTiers;
};

struct MaterialLint {
  std::string material;  // the material's name ("" when it did not parse)
  // Every finding, in the compiler's diagnostic type; findings about a variant rather than a
  // line have loc.line == 0 and name the variant in their message.
  std::vector<ir::Diagnostic> diagnostics;
  std::vector<VariantFigures> variants;
  std::vector<gpu_stats::GpuStats> gpuStats;  // one per LintOptions::gpus, same order
  bool hasErrors() const;
};

// Lints one material file held in memory. Never throws; a material that does not compile yields
// its diagnostics and no figures.
MaterialLint lintMaterial(const ir::SourceFile& file, const LintOptions& options);

// The rules over one compiled variant's figures (GLES limits, highp inputs, budgets, baseline),
// appended to *diagnostics. lintMaterial calls it for every variant it builds.
void lintVariant(const std::string& material, const VariantFigures& figures, const LintOptions& options,
                 std::vector<ir::Diagnostic>* diagnostics);

// The figures budgets and baselines may use (names in compiler/cost_figures.h), in a stable order.
std::span<const compiler::Figure> baselineFigures();
// Their values for a variant stage, by name, in that order, as reports print them (reportedValue).
std::vector<std::pair<std::string, double>> namedFigures(const StageFigures& stage);
// Their names, in the same order.
std::vector<std::string> figureNames();

}  // namespace facet::lint
