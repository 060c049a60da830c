#include "facet/tune/choices.h"

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "facet/eval/configurations.h"
#include "facet/scene/json_document.h"
#include "json_reading.h"

namespace facet::tune {
namespace {

using json = nlohmann::json;
using permutations::Tier;

std::string text(const json& j, const std::string& pointer) {
  if (!j.is_string()) fail(pointer, "expected a string");
  return j.get<std::string>();
}

double rounded(double v) { return std::round(v * 1000) / 1000; }

}  // namespace

std::string choicesPath(const std::string& materialPath) {
  std::filesystem::path p(materialPath);
  return (p.parent_path() / (p.stem().string() + ".tuning.json")).string();
}

std::optional<Choices> choicesOf(const TuneReport& report) {
  Choices c;
  c.material = report.material;
  c.gpu = report.gpu;
  c.verticesPerPixel = report.verticesPerPixel;
  for (const TierOutcome& o : report.tiers) {
    if (!o.chosen) return std::nullopt;
    c.tiers.push_back(
        {o.tier, o.chosen->result.configuration.config, o.chosen->cost.total, o.chosen->result.error.psnr});
  }
  return c;
}

std::string writeChoices(const Choices& choices) {
  json j = json::object();
  j["material"] = choices.material;
  j["gpu"] = choices.gpu;
  j["vertices_per_pixel"] = choices.verticesPerPixel;
  j["tiers"] = json::object();
  for (const TierChoice& t : choices.tiers) {
    json config = json::object();
    for (const eval::Axis& axis : eval::axes()) config[axis.name] = axis.get(t.config);
    json& tier = j["tiers"][permutations::toString(t.tier)];
    tier["config"] = config;
    tier["cost"] = rounded(t.cost);
    tier["psnr_db"] = std::isfinite(t.psnrDb) ? json(rounded(t.psnrDb)) : json(nullptr);
  }
  return j.dump(2) + "\n";
}

std::optional<Choices> parseChoices(const std::string& path, const std::string& source, const ir::Material& material,
                                    std::string* error) {
  std::optional<json> j = scene::parseJsonDocument(path, source, error);
  if (!j) return std::nullopt;
  try {
    Choices c;
    object(*j, "");
    for (const auto& [key, value] : j->items()) {
      const std::string p = child("", key);
      if (key == "material") {
        c.material = text(value, p);
        if (c.material != material.name)
          fail(p, "the file tunes '" + scene::shownValue(c.material) + "', not '" + material.name + "'");
      } else if (key == "gpu") {
        c.gpu = text(value, p);
      } else if (key == "vertices_per_pixel") {
        c.verticesPerPixel = number(value, p, 0, kMaxVerticesPerPixel);
      } else if (key == "tiers") {
        for (const auto& [name, tier] : object(value, p).items()) {
          const std::string tp = child(p, name);
          std::optional<Tier> t = permutations::tierFromString(name);
          if (!t || *t == Tier::Reference) fail(tp, "unknown tier '" + name + "' (known: high, mid, low)");
          TierChoice choice;
          choice.tier = *t;
          choice.config = eval::configurations(material, {*t}, false).at(1).config;  // what no axis names
          for (const auto& [field, v] : object(tier, tp).items()) {
            const std::string fp = child(tp, field);
            if (field == "cost") {
              choice.cost = number(v, fp, 0, kMaxCost);
            } else if (field == "psnr_db") {
              choice.psnrDb = v.is_null() ? INFINITY : number(v, fp, 0, kMaxPsnrDb);  // null: identical
            } else if (field == "config") {
              for (const auto& [axisName, option] : object(v, fp).items()) {
                const std::string ap = child(fp, axisName);
                auto axis = std::find_if(eval::axes().begin(), eval::axes().end(),
                                         [&name = axisName](const eval::Axis& a) { return name == a.name; });
                if (axis == eval::axes().end()) fail(ap, "unknown axis '" + axisName + "'");
                const std::string o = text(option, ap);
                if (std::find(axis->options.begin(), axis->options.end(), o) == axis->options.end()) {
                  std::string known;
                  for (const std::string& k : axis->options) known += (known.empty() ? "" : ", ") + k;
                  fail(ap, "unknown option '" + scene::shownValue(o) + "' (known: " + known + ")");
                }
                axis->set(&choice.config, o);
              }
            } else {
              fail(fp, "unknown key '" + field + "' (known: config, cost, psnr_db)");
            }
          }
          c.tiers.push_back(choice);
        }
      } else {
        fail(p, "unknown key '" + key + "' (known: material, gpu, vertices_per_pixel, tiers)");
      }
    }
    if (!j->contains("tiers")) fail("/tiers", "missing: the tuned tiers");
    std::sort(c.tiers.begin(), c.tiers.end(), [](const TierChoice& a, const TierChoice& b) { return a.tier < b.tier; });
    return c;
  } catch (const Invalid& e) {
    *error = invalidMessage(path, e);
    return std::nullopt;
  }
}

}  // namespace facet::tune
