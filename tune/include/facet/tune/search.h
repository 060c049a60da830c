// `matc tune`'s search (docs/tune.md): every combination of eval's configuration axes
// (eval::axes()) is costed by the cost model without rendering, ordered by the one-number cost,
// and rendered and scored with eval's machinery (eval::Session) in that order, only while it could
// still be cheaper than what already meets an open tier's budget; each tier gets the cheapest that
// meets its budget.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "facet/eval/evaluate.h"
#include "facet/lint/budgets.h"
#include "facet/tune/budgets.h"

namespace facet::tune {

// The one number a configuration costs (docs/tune.md, "The cost"): on one target GPU, the
// calibrated estimate of the fragment stage of the sun + IBL variant <tier>.dir1
// (compiler::calibratedEstimate, fitted against Mesa) plus verticesPerPixel × the cost model's
// cycles of its vertex stage (the calibration fits no vertex stage).
struct Cost {
  double fragment = 0;
  double vertex = 0;
  double total = 0;
};
Cost oneNumberCost(const eval::ConfigurationResult& result, const compiler::GpuCalibration& gpu,
                   double verticesPerPixel);
// The GPUs a cost can be taken on: the calibrated ones whose figure is cycles (not Adreno's
// instructions). Returns nullptr and *error for another name.
const compiler::GpuCalibration* targetGpu(const std::string& name, std::string* error);

// `base` with every axis of eval::axes() that applies to the material as `axes` has it: a tier's
// choice keeps the rest (its shadow filter, a clear coat the material does not write) as shipped.
permutations::TierConfig withAxesOf(const ir::Material& material, permutations::TierConfig base,
                                    const permutations::TierConfig& axes);

// Every combination of the axes that apply to the material, in a fixed order; an axis that does
// not apply to a combination (energy compensation without split-sum) keeps reference's choice.
std::vector<permutations::TierConfig> candidates(const ir::Material& material);

// The candidates within `maxChanges` axes of one of `tiers` as shipped (-1: all of them), in
// candidates() order.
std::vector<permutations::TierConfig> neighbourhood(const ir::Material& material,
                                                    const std::vector<permutations::Tier>& tiers, int maxChanges);

struct TuneOptions {
  std::vector<permutations::Tier> tiers = {permutations::Tier::High, permutations::Tier::Mid, permutations::Tier::Low};
  Budgets budgets = defaultBudgets();
  std::string gpu = "mali-g57";
  unsigned jobs = 0;  // threads costing candidates (0: one per core); the result is the same for any
  // The space: the combinations that change at most this many axes from a tuned tier as shipped
  // (neighbourhood()); -1: every combination (docs/tune.md, "Time": the whole product renders
  // hundreds of configurations for a high tier).
  int maxChanges = 2;
  // The space searched instead, when not empty. Tests search a few.
  std::vector<permutations::TierConfig> space;
  // Render a candidate's second view and furnace only where the first view's error leaves it able
  // to meet an open tier's budget (eval::MeasureOptions::worthFinishing). The choice and every
  // reported figure of a fully measured candidate are the same either way; false renders all of it.
  bool screen = true;
  // A candidate whose views' build is byte for byte one an earlier candidate rendered (a metal's
  // SH bands and diffuse, which its shaders never read) takes that render's figures
  // (eval::MeasureOptions::reuseIdenticalViews): the same figures, so the same choice and reports;
  // false renders every candidate.
  bool reuseIdenticalViews = true;
  // `matc lint`'s budgets (Budgets::lintBudgetsPath): a tier may take only a candidate whose
  // <tier>.dir1 stages fit its tier's budget there, so that no tuned package fails the lint gate.
  // dir1 is the variant with the most work of those lint builds (the sun's terms over dir0's).
  std::optional<lint::Budgets> lintBudgets;
  eval::EvalOptions eval;  // the grid; fp16 emulation is turned on, timing and the BRDF sweep off
  std::function<void(const std::string&)> progress;
};

struct Scored {
  eval::ConfigurationResult result;
  Cost cost;
  std::vector<double> besideFragment;  // the other calibrated GPUs' fragment estimates, in TuneReport::beside order
  bool pareto = false;                 // among the fully measured: nothing both cheaper and more accurate
  // Per tier searched, the lint budgets its <tier>.dir1 breaks (lint's messages); absent: it fits,
  // or no lint budgets were given. Such a candidate is not that tier's to take.
  std::map<permutations::Tier, std::vector<std::string>> lintBreaches;
};

struct TierOutcome {
  permutations::Tier tier = permutations::Tier::High;
  TierBudget budget;
  std::optional<Scored> shipped;  // the tier as shipped (preset + the material's overrides); unset in rescore()
  std::optional<Scored> chosen;   // the cheapest that meets the budget; unset: none does
  std::optional<Scored> best;     // none does: the most accurate rendered and within the cap
  std::string failure;            // none does: the diagnostic
};

struct TuneReport {
  std::string material;
  std::string gpu;
  std::vector<std::string> beside;  // other calibrated GPUs reported beside the target
  double verticesPerPixel = 0;
  bool lintBudgets = false;  // the choices also fit lint's budgets (TuneOptions::lintBudgets)
  double referenceFurnaceGain = 0;
  size_t candidates = 0, rendered = 0;
  size_t screened = 0;  // of the rendered, stopped after the first view (ConfigurationResult::psnrAtMost)
  // Costed and not rendered because every open tier whose cap it is within may not take it (its lint budgets).
  size_t overLintBudgets = 0;
  // Of the rendered, those whose views took an earlier render's figures (TuneOptions::reuseIdenticalViews);
  // the reports leave it out: their figures are the same either way.
  size_t reused = 0;
  std::vector<TierOutcome> tiers;
  std::vector<Scored> front;  // every rendered candidate, in cost order, the screened ones too
};

// A configuration meets a budget: its PSNR, its furnace figure (against reference's) and its cost.
bool meets(const Scored& s, const TierBudget& budget, double referenceFurnaceGain);

// Fails on a build error, no Vulkan device or an unknown GPU.
std::optional<TuneReport> tune(const ir::Material& material, const TuneOptions& options, eval::EvalError* error);

// The committed choices re-scored (the gate): each tier's configuration measured again under its
// own tier, with the budget it must meet. Same failures as tune().
std::optional<TuneReport> rescore(const ir::Material& material,
                                  const std::vector<std::pair<permutations::Tier, permutations::TierConfig>>& choices,
                                  const TuneOptions& options, eval::EvalError* error);

}  // namespace facet::tune
