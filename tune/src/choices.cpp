#include "facet/tune/choices.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

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
          const permutations::TierConfig shipped = choice.config;
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
                if (axis->appliesToMaterial && !axis->appliesToMaterial(material) && o != axis->get(shipped))
                  fail(ap, "'" + material.name + "' has nothing the axis '" + axisName + "' changes: the file can " +
                               "only record the tier's own '" + axis->get(shipped) + "', not '" + o + "'");
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

std::map<permutations::Tier, permutations::TierConfig> tunedTiers(const Choices& choices) {
  std::map<permutations::Tier, permutations::TierConfig> tiers;
  for (const TierChoice& t : choices.tiers) tiers[t.tier] = t.config;
  return tiers;
}

std::optional<ShippedTuning> shippedTuning(const std::string& materialPath, const std::string& tuningPath,
                                           bool noTuning, const ir::Material& material, std::string* error) {
  ShippedTuning out;
  if (noTuning) return out;
  const std::string path = tuningPath.empty() ? choicesPath(materialPath) : tuningPath;
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) {
    if (tuningPath.empty()) return out;  // an untuned material
    *error = path + ": error: cannot open the tuning file: no such file";
    return std::nullopt;
  }
  // A FIFO would block; `matc tune --write` writes about 2 KB (every axis of three tiers), so a
  // file of 1 MiB is no tuning file.
  if (!std::filesystem::is_regular_file(status)) {
    *error = path + ": error: cannot open the tuning file: not a regular file";
    return std::nullopt;
  }
  if (std::filesystem::file_size(path, ec) > (1u << 20)) {
    *error = path + ": error: tuning files are limited to 1 MiB";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad()) {
    *error = path + ": error: cannot read the tuning file";
    return std::nullopt;
  }
  out.choices = parseChoices(path, text.str(), material, error);
  if (!out.choices) return std::nullopt;
  out.path = path;
  for (const TierChoice& t : out.choices->tiers)
    for (const ir::TierOverride& o : material.tierOverrides) {
      if (o.tier != permutations::toString(t.tier)) continue;
      auto axis =
          std::find_if(eval::axes().begin(), eval::axes().end(), [&](const eval::Axis& a) { return o.axis == a.name; });
      if (axis == eval::axes().end() || axis->get(t.config) == o.option) continue;
      out.warnings.push_back(path + ": warning: /tiers/" + o.tier + "/config/" + o.axis + ": '" + axis->get(t.config) +
                             "' replaces the material's `tier " + o.tier + " { " + o.axis + " = " + o.option +
                             " }`: the tuning file wins (tune it again, or remove the block)");
    }
  return out;
}

std::optional<ShippedTuning> shippedTuningForCommand(const std::string& materialPath, const std::string& tuningPath,
                                                     bool noTuning, const ir::Material& material,
                                                     std::map<permutations::Tier, permutations::TierConfig>* tiers) {
  std::string error;
  std::optional<ShippedTuning> tuning = shippedTuning(materialPath, tuningPath, noTuning, material, &error);
  if (!tuning) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return std::nullopt;
  }
  for (const std::string& warning : tuning->warnings) std::fprintf(stderr, "%s\n", warning.c_str());
  if (tuning->choices) *tiers = tunedTiers(*tuning->choices);
  return tuning;
}

}  // namespace facet::tune
