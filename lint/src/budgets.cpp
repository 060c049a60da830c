#include "facet/lint/budgets.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "facet/runtime/json_document.h"

namespace facet::lint {
namespace {

using json = nlohmann::json;

struct Invalid {
  std::string pointer, message;
};

[[noreturn]] void fail(const std::string& pointer, const std::string& message) { throw Invalid{pointer, message}; }

const json& object(const json& j, const std::string& pointer) {
  if (!j.is_object()) fail(pointer, "expected an object");
  return j;
}

double figure(const json& j, const std::string& pointer) {
  if (!j.is_number()) fail(pointer, "expected a number");
  double v = j.get<double>();
  if (!std::isfinite(v) || v < 0) fail(pointer, "expected a finite number ≥ 0");
  return v;
}

FigureLimits figures(const json& j, const std::string& pointer) {
  FigureLimits out;
  for (const auto& [name, value] : object(j, pointer).items()) out[name] = figure(value, pointer + "/" + name);
  return out;
}

bool isStage(const std::string& s) { return s == "vertex" || s == "fragment"; }

}  // namespace

std::optional<Budgets> parseBudgets(const std::string& path, const std::string& text, std::string* error) {
  std::optional<json> j = runtime::parseJsonDocument(path, text, error);
  if (!j) return std::nullopt;
  try {
    Budgets b;
    object(*j, "");
    if (!j->contains("tiers")) fail("/tiers", "missing: a budget file maps tier names to stage budgets");
    for (const auto& [tier, stages] : object((*j)["tiers"], "/tiers").items()) {
      std::string tp = "/tiers/" + tier;
      for (const auto& [stage, limits] : object(stages, tp).items()) {
        std::string sp = tp + "/" + stage;
        if (!isStage(stage)) fail(sp, "expected \"vertex\" or \"fragment\"");
        StageBudget& sb = b.tiers[tier][stage];
        for (const auto& [name, value] : object(limits, sp).items()) {
          if (name == "min_relaxed_percent") sb.minRelaxedPercent = figure(value, sp + "/" + name);
          else sb.max[name] = figure(value, sp + "/" + name);
        }
      }
    }
    return b;
  } catch (const Invalid& e) {
    *error = path + ": error: " + (e.pointer.empty() ? "/" : e.pointer) + ": " + e.message;
    return std::nullopt;
  }
}

std::optional<Baseline> parseBaseline(const std::string& path, const std::string& text, std::string* error) {
  std::optional<json> j = runtime::parseJsonDocument(path, text, error);
  if (!j) return std::nullopt;
  try {
    Baseline b;
    object(*j, "");
    if (!j->contains("materials")) fail("/materials", "missing: a baseline maps materials to variant figures");
    for (const auto& [material, variants] : object((*j)["materials"], "/materials").items())
      for (const auto& [key, stages] : object(variants, "/materials/" + material).items())
        for (const auto& [stage, values] : object(stages, "/materials/" + material + "/" + key).items()) {
          std::string sp = "/materials/" + material + "/" + key + "/" + stage;
          if (!isStage(stage)) fail(sp, "expected \"vertex\" or \"fragment\"");
          b.materials[material][key][stage] = figures(values, sp);
        }
    return b;
  } catch (const Invalid& e) {
    *error = path + ": error: " + e.pointer + ": " + e.message;
    return std::nullopt;
  }
}

std::string writeBaseline(const Baseline& baseline) {
  json j = json::object();
  j["materials"] = json::object();
  for (const auto& [material, variants] : baseline.materials)
    for (const auto& [key, stages] : variants)
      for (const auto& [stage, values] : stages)
        for (const auto& [name, value] : values) j["materials"][material][key][stage][name] = value;
  return j.dump(2) + "\n";
}

}  // namespace facet::lint
