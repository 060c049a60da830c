// The configurations `matc eval` measures: every tier as shipped (its preset with the material's
// overrides) and every single-option swap of it, one choice of one axis replaced.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "facet/ir/module.h"
#include "facet/permutations/tiers.h"

namespace facet::eval {

struct Configuration {
  std::string name;  // "high" (as shipped) or "high:specular=zioma" (a swap)
  permutations::Tier tier = permutations::Tier::High;
  permutations::TierConfig config;  // the maths the variant is built with
  std::string axis;    // "" as shipped; else specular | diffuse | ambient | sh_bands | color_space | precision |
                       // energy_compensation | dominant_direction | clear_coat | anisotropy | ao |
                       // specular_occlusion
  std::string option;  // the option swapped in
  std::string change;  // "as shipped" or e.g. "specular ggx_smith → zioma"
  bool swap() const { return !axis.empty(); }
};

// An axis of TierConfig and its options, by name. The one list `matc eval` swaps through; a new
// choice in permutations/tiers.h is measured once it is added here.
struct Axis {
  const char* name;
  std::vector<std::string> options;
  std::string (*get)(const permutations::TierConfig&);
  void (*set)(permutations::TierConfig*, const std::string&);
  // Whether the axis means anything for this configuration (energy compensation: split-sum only).
  bool (*applies)(const permutations::TierConfig&) = nullptr;
  // Whether the axis means anything for this material (the clear coat: materials writing clearCoat).
  bool (*appliesToMaterial)(const ir::Material&) = nullptr;
};
const std::vector<Axis>& axes();

// For each tier (in the order given): the tier as shipped, then each single-option swap in axes()
// order. `reference` as shipped is always included first, whatever `tiers` says: every error is
// measured against it. swaps = false gives the tiers as shipped only. `tuned`: the tiers of the
// material's tuning file (compiler::BuildOptions::tunedTiers), which ship in place of the presets.
std::vector<Configuration> configurations(const ir::Material& material, const std::vector<permutations::Tier>& tiers,
                                          bool swaps = true,
                                          const std::map<permutations::Tier, permutations::TierConfig>& tuned = {});

// A name safe for file names: "high:specular=zioma" -> "high.specular-zioma".
std::string fileStem(const std::string& configurationName);

}  // namespace facet::eval
