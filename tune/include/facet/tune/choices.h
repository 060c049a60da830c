// The tuned tiers of a material as `matc tune --write` records them: a sidecar JSON file beside
// the material, `<stem>.tuning.json` (docs/tune.md, "The tuning file"), which `matc tune --check`
// re-scores. Per tier the configuration by eval's axis names, and the figures it had when tuned.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/ir/module.h"
#include "facet/permutations/tiers.h"
#include "facet/tune/search.h"

namespace facet::tune {

struct TierChoice {
  permutations::Tier tier = permutations::Tier::High;
  permutations::TierConfig config;
  double cost = 0, psnrDb = 0;  // as tuned (informative: --check measures again)
};

struct Choices {
  std::string material, gpu;
  double verticesPerPixel = 0;
  std::vector<TierChoice> tiers;  // in tier order
};

// "<folder>/<stem>.tuning.json" for "<folder>/<stem>.mat".
std::string choicesPath(const std::string& materialPath);

// The chosen tiers of a report; nullopt when a tier has no choice (nothing partial is recorded).
std::optional<Choices> choicesOf(const TuneReport& report);

// Deterministic text: keys sorted, two-space indent, figures to 3 decimals, a trailing newline.
std::string writeChoices(const Choices& choices);

// An axis the file does not give keeps the tier's choice as shipped. Errors:
// "<path>: error: <JSON pointer>: <what>".
std::optional<Choices> parseChoices(const std::string& path, const std::string& text, const ir::Material& material,
                                    std::string* error);

}  // namespace facet::tune
