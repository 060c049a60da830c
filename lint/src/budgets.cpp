#include "facet/lint/budgets.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

#include "facet/compiler/cost_figures.h"
#include "facet/lint/lint.h"
#include "facet/permutations/variant_key.h"
#include "facet/scene/json_document.h"

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

// RFC 6901: '~' and '/' in a key are written ~0 and ~1.
std::string child(const std::string& pointer, const std::string& key) {
  std::string out = pointer + "/";
  for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return out;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// A budget's floor on the mediump share: "min_" and the figure's name.
std::string minRelaxedPercentKey() {
  return std::string("min_") + compiler::costFigure(compiler::Figure::RelaxedPercent).name;
}

// A name nothing reads would switch its check off without a word (a budget on "alus" limits
// nothing): every name must be one lint knows.
void knownFigure(const std::string& name, const std::string& pointer, bool budget) {
  const std::vector<std::string> names = figureNames();
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  fail(pointer,
       "unknown figure '" + name + "' (known: " + joined(names) + (budget ? ", " + minRelaxedPercentKey() : "") + ")");
}

std::string tierNames() {
  std::vector<std::string> names;
  for (permutations::Tier t : permutations::supportedTiers()) names.push_back(permutations::toString(t));
  return joined(names);
}

void onlyKey(const json& j, const std::string& key, const std::string& pointer) {
  for (const auto& [name, value] : j.items())
    if (name != key) fail(child(pointer, name), "unknown key '" + name + "' (expected only \"" + key + "\")");
}

FigureLimits figures(const json& j, const std::string& pointer) {
  FigureLimits out;
  for (const auto& [name, value] : object(j, pointer).items()) {
    knownFigure(name, child(pointer, name), false);
    out[name] = figure(value, child(pointer, name));
  }
  return out;
}

bool isStage(const std::string& s) { return s == "vertex" || s == "fragment"; }

}  // namespace

std::optional<Budgets> parseBudgets(const std::string& path, const std::string& text, std::string* error) {
  std::optional<json> j = scene::parseJsonDocument(path, text, error);
  if (!j) return std::nullopt;
  try {
    Budgets b;
    object(*j, "");
    if (!j->contains("tiers")) fail("/tiers", "missing: a budget file maps tier names to stage budgets");
    onlyKey(*j, "tiers", "");
    for (const auto& [tier, stages] : object((*j)["tiers"], "/tiers").items()) {
      std::string tp = child("/tiers", tier);
      if (!permutations::tierFromString(tier)) fail(tp, "unknown tier '" + tier + "' (known: " + tierNames() + ")");
      for (const auto& [stage, limits] : object(stages, tp).items()) {
        std::string sp = child(tp, stage);
        if (!isStage(stage)) fail(sp, "expected \"vertex\" or \"fragment\"");
        StageBudget& sb = b.tiers[tier][stage];
        for (const auto& [name, value] : object(limits, sp).items()) {
          if (name == minRelaxedPercentKey()) {
            sb.minRelaxedPercent = figure(value, child(sp, name));
            continue;
          }
          knownFigure(name, child(sp, name), true);
          sb.max[name] = figure(value, child(sp, name));
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
  std::optional<json> j = scene::parseJsonDocument(path, text, error);
  if (!j) return std::nullopt;
  try {
    Baseline b;
    object(*j, "");
    if (!j->contains("materials")) fail("/materials", "missing: a baseline maps materials to variant figures");
    onlyKey(*j, "materials", "");
    for (const auto& [material, variants] : object((*j)["materials"], "/materials").items()) {
      const std::string mp = child("/materials", material);
      for (const auto& [key, stages] : object(variants, mp).items()) {
        const std::string kp = child(mp, key);
        // A key no variant has would never be compared: a baseline that checks nothing.
        if (!permutations::VariantKey::parse(key))
          fail(kp, "'" + key + "' is not a variant key (<tier>.dir<0|1>[.pt<1|2|4>], tiers: " + tierNames() + ")");
        for (const auto& [stage, values] : object(stages, kp).items()) {
          std::string sp = child(kp, stage);
          if (!isStage(stage)) fail(sp, "expected \"vertex\" or \"fragment\"");
          b.materials[material][key][stage] = figures(values, sp);
        }
      }
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
