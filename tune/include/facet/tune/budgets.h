// `matc tune`'s error budgets (docs/tune.md): per tier the least PSNR against `reference` a
// configuration must reach on the evaluation grid (fp16-emulated, both views), no white-furnace
// gain, and an optional cap on the one-number cost; the defaults, a project's JSON file over them,
// and per-material entries of that file over both.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "facet/permutations/variant_key.h"

namespace facet::tune {

struct TierBudget {
  double minPsnrDb = 0;
  bool noEnergyGain = true;       // the white furnace: no gain over reference (eval::furnaceGainsEnergy)
  std::optional<double> maxCost;  // the one-number cost (cost.h) may not exceed this
};

// The one-number cost's vertex weight: vertices shaded per pixel shaded (cost.h, docs/tune.md).
inline constexpr double kDefaultVerticesPerPixel = 0.1;

struct Budgets {
  std::map<permutations::Tier, TierBudget> tiers;  // high, mid, low
  double verticesPerPixel = kDefaultVerticesPerPixel;
  // material name -> tier -> its budget (complete: the file's tier budget with the entry's keys over it)
  std::map<std::string, std::map<permutations::Tier, TierBudget>> materials;
  // "lint_budgets": `matc lint`'s budgets file, which every chosen tier must also fit (TuneOptions::
  // lintBudgets), its path resolved against the budgets file's folder; empty: none named.
  std::string lintBudgetsPath;

  // The budget of `tier` for `material`: its own entry, else the project's, else the default.
  TierBudget forMaterial(const std::string& material, permutations::Tier tier) const;
};

// high ≥ 50 dB, mid ≥ 40, low ≥ 34; no energy gain; no cost cap (docs/tune.md says why).
Budgets defaultBudgets();

// A budgets file over the defaults (lint's budgets file it names is not read here). On failure nullopt with
// *error = "<path>: error: <JSON pointer>: <what>" (or the JSON reader's "<path>:<line>:<col>: ...").
std::optional<Budgets> parseBudgets(const std::string& path, const std::string& text, std::string* error);

}  // namespace facet::tune
