// The tuned tiers of a material as `matc tune --write` records them: a sidecar JSON file beside
// the material, `<stem>.tuning.json` (docs/tune.md, "The tuning file"), which `matc tune --check`
// re-scores. Per tier the configuration by eval's axis names, and the figures it had when tuned.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "facet/ir/module.h"
#include "facet/permutations/tiers.h"

namespace facet::tune {

struct TuneReport;  // search.h: the library matc links for this file has no renderer

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

// An axis the file does not give keeps the tier's choice as shipped. An axis that does not apply
// to the material (the clear coat of one that writes no clearCoat) may only record the tier's own
// option: it changes none of the material's shaders. Errors: "<path>: error: <JSON pointer>: <what>".
std::optional<Choices> parseChoices(const std::string& path, const std::string& text, const ir::Material& material,
                                    std::string* error);

// The tiers a file chose, as compiler::BuildOptions::tunedTiers takes them.
std::map<permutations::Tier, permutations::TierConfig> tunedTiers(const Choices& choices);

// The tuning a build of the material ships with (`matc compile`, `matc lint`, `matc eval`'s tiers
// as shipped): the file `tuningPath` names, else choicesPath(materialPath) when it exists; none
// with noTuning (the presets with the material's `tier` blocks).
struct ShippedTuning {
  std::string path;  // the file read; "" for none
  std::optional<Choices> choices;
  // "<path>: warning: <JSON pointer>: ...": a recorded option that replaces the one a `tier` block
  // of the material names. The file wins (it was searched from the material with its blocks).
  std::vector<std::string> warnings;
};
std::optional<ShippedTuning> shippedTuning(const std::string& materialPath, const std::string& tuningPath,
                                           bool noTuning, const ir::Material& material, std::string* error);
// shippedTuning as the commands that build the material use it (`matc compile`, `lint`, `eval`):
// its warnings and any error printed to stderr, the tiers it chose in *tiers (left as they are
// without a file). Null on error.
std::optional<ShippedTuning> shippedTuningForCommand(const std::string& materialPath, const std::string& tuningPath,
                                                     bool noTuning, const ir::Material& material,
                                                     std::map<permutations::Tier, permutations::TierConfig>* tiers);

}  // namespace facet::tune
