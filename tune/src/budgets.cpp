#include "facet/tune/budgets.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "facet/scene/json_document.h"
#include "json_reading.h"

namespace facet::tune {
namespace {

using json = nlohmann::json;
using permutations::Tier;

// The tiers a budget may name: reference is the ground truth every error is measured against.
Tier tunedTier(const std::string& name, const std::string& pointer) {
  std::optional<Tier> t = permutations::tierFromString(name);
  if (!t || *t == Tier::Reference) fail(pointer, "unknown tier '" + name + "' (known: high, mid, low)");
  return *t;
}

// A tier's keys over `budget`. A key nothing reads would switch its check off without a word.
void readTier(const json& j, const std::string& pointer, TierBudget* budget) {
  for (const auto& [key, value] : object(j, pointer).items()) {
    const std::string p = child(pointer, key);
    if (key == "min_psnr_db") {
      budget->minPsnrDb = number(value, p, 0, kMaxPsnrDb);
    } else if (key == "max_cost") {
      budget->maxCost = number(value, p, 0, kMaxCost);
    } else if (key == "no_energy_gain") {
      if (!value.is_boolean()) fail(p, "expected true or false");
      budget->noEnergyGain = value.get<bool>();
    } else {
      fail(p, "unknown key '" + key + "' (known: min_psnr_db, max_cost, no_energy_gain)");
    }
  }
}

}  // namespace

TierBudget Budgets::forMaterial(const std::string& material, Tier tier) const {
  if (auto m = materials.find(material); m != materials.end())
    if (auto t = m->second.find(tier); t != m->second.end()) return t->second;
  auto t = tiers.find(tier);
  return t != tiers.end() ? t->second : TierBudget{};
}

Budgets defaultBudgets() {
  Budgets b;
  b.tiers[Tier::High].minPsnrDb = 50;
  b.tiers[Tier::Mid].minPsnrDb = 40;
  b.tiers[Tier::Low].minPsnrDb = 34;
  return b;
}

std::optional<Budgets> parseBudgets(const std::string& path, const std::string& text, std::string* error) {
  std::optional<json> j = scene::parseJsonDocument(path, text, error);
  if (!j) return std::nullopt;
  try {
    Budgets b = defaultBudgets();
    object(*j, "");
    for (const auto& [key, value] : j->items()) {
      const std::string p = child("", key);
      if (key == "vertices_per_pixel") {
        b.verticesPerPixel = number(value, p, 0, kMaxVerticesPerPixel);
      } else if (key == "lint_budgets") {
        if (!value.is_string() || value.get<std::string>().empty()) fail(p, "expected the path of lint's budgets file");
        b.lintBudgetsPath = (std::filesystem::path(path).parent_path() / value.get<std::string>()).string();
      } else if (key == "tiers") {
        for (const auto& [tier, budget] : object(value, p).items())
          readTier(budget, child(p, tier), &b.tiers[tunedTier(tier, child(p, tier))]);
      } else if (key != "materials") {
        fail(p, "unknown key '" + key + "' (known: tiers, materials, vertices_per_pixel, lint_budgets)");
      }
    }
    // After "tiers", whatever the file's order: a material's entry starts from the project's budget.
    if (j->contains("materials")) {
      for (const auto& [material, tiers] : object((*j)["materials"], "/materials").items()) {
        const std::string mp = child("/materials", material);
        for (const auto& [tier, budget] : object(tiers, mp).items()) {
          const Tier t = tunedTier(tier, child(mp, tier));
          TierBudget own = b.tiers[t];
          readTier(budget, child(mp, tier), &own);
          b.materials[material][t] = own;
        }
      }
    }
    return b;
  } catch (const Invalid& e) {
    *error = invalidMessage(path, e);
    return std::nullopt;
  }
}

}  // namespace facet::tune
