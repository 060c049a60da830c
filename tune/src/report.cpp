#include "facet/tune/report.h"

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "facet/eval/configurations.h"
#include "facet/eval/scatter_plot.h"

namespace facet::tune {
namespace {

using json = nlohmann::json;

std::string fixed(double v, int digits) {
  if (std::isinf(v)) return "∞";
  if (std::isnan(v)) return "–";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

// The axes where `config` differs from `from`: "specular fused_hammon → lut, sh_bands 3 → 2".
std::string changes(const permutations::TierConfig& from, const permutations::TierConfig& to) {
  std::string out;
  for (const eval::Axis& axis : eval::axes()) {
    const std::string a = axis.get(from), b = axis.get(to);
    if (a != b) out += (out.empty() ? "" : ", ") + std::string(axis.name) + " " + a + " → " + b;
  }
  return out.empty() ? "as shipped" : out;
}

std::string costDefinition(const TuneReport& r) {
  return r.gpu + " cycles per pixel: the calibrated estimate of the fragment stage of <tier>.dir1 + " +
         fixed(r.verticesPerPixel, 3) + " vertices per pixel × the cost model's vertex cycles";
}

std::string budgetText(const TierBudget& b) {
  std::string out = "≥ " + fixed(b.minPsnrDb, 1) + " dB";
  if (b.noEnergyGain) out += ", no energy gain";
  if (b.maxCost) out += ", cost ≤ " + fixed(*b.maxCost, 3);
  return out;
}

// lint's budget findings from the variant on: "mid.dir1 fragment stage: textures 6 exceeds the mid budget 4".
std::string lintFigures(const std::vector<std::string>& messages) {
  std::string out;
  for (const std::string& m : messages) {
    const size_t variant = m.find("variant ");
    out += (out.empty() ? "" : "; ") + (variant == std::string::npos ? m : m.substr(variant + 8));
  }
  return out;
}

json scoredJson(const Scored& s, const TuneReport& r) {
  json j = json::object();
  j["name"] = s.result.configuration.name;
  json config = json::object();
  for (const eval::Axis& axis : eval::axes()) config[axis.name] = axis.get(s.result.configuration.config);
  j["config"] = config;
  j["cost"] = s.cost.total;
  j["fragment"] = s.cost.fragment;
  j["vertex_model_cycles"] = s.cost.vertex;
  json beside = json::object();
  for (size_t i = 0; i < r.beside.size() && i < s.besideFragment.size(); ++i) beside[r.beside[i]] = s.besideFragment[i];
  j["fragment_beside"] = beside;
  // Screened (the first view only): null, and the bound on the whole figure.
  j["psnr_db"] = std::isinf(s.result.error.psnr) || s.result.psnrAtMost ? json(nullptr) : json(s.result.error.psnr);
  if (s.result.psnrAtMost) j["psnr_db_at_most"] = *s.result.psnrAtMost;
  j["white_furnace_gain"] = std::isnan(s.result.furnaceGain) ? json(nullptr) : json(s.result.furnaceGain);
  j["pareto"] = s.pareto;
  if (!s.lintBreaches.empty()) {
    json breaches = json::object();
    for (const auto& [tier, messages] : s.lintBreaches) breaches[permutations::toString(tier)] = messages;
    j["lint_breaches"] = breaches;  // the tiers that may not take it: lint's budget findings
  }
  return j;
}

}  // namespace

std::vector<std::string> summaryLines(const TuneReport& r) {
  std::vector<std::string> out;
  for (const TierOutcome& o : r.tiers) {
    const std::string tier = permutations::toString(o.tier);
    if (!o.chosen) {
      out.push_back(o.failure);
      continue;
    }
    std::string line = tier + ": ";
    if (o.shipped)
      line += fixed(o.shipped->cost.total, 3) + " → " + fixed(o.chosen->cost.total, 3) + " " + r.gpu + " cycles, " +
              fixed(o.shipped->result.error.psnr, 1) + " → " + fixed(o.chosen->result.error.psnr, 1) + " dB (" +
              budgetText(o.budget) +
              "): " + changes(o.shipped->result.configuration.config, o.chosen->result.configuration.config);
    else
      line += fixed(o.chosen->cost.total, 3) + " " + r.gpu + " cycles, " + fixed(o.chosen->result.error.psnr, 1) +
              " dB: meets " + budgetText(o.budget);
    out.push_back(line);
  }
  return out;
}

std::string markdownReport(const TuneReport& r) {
  std::string md = "# matc tune: " + r.material + "\n\n";
  md += "Cost: " + costDefinition(r) +
        " (docs/tune.md). Error: PSNR against `reference` on the evaluation grid, "
        "both views, mediump rounded to binary16 (`--fp16-emulation`). White furnace: reference " +
        fixed(r.referenceFurnaceGain, 3) + ".\n\n";
  md += std::to_string(r.candidates) + " candidates costed, " + std::to_string(r.rendered) + " rendered (" +
        std::to_string(r.screened) +
        " of them only in the first view: the second could not have brought them to an open tier's budget; "
        "their dB is that bound, ≤).\n\n";
  if (r.lintBudgets)
    md +=
        "A tier takes only a configuration whose <tier>.dir1 fits that tier's `matc lint` budgets (the "
        "budgets file's `lint_budgets`); below, a candidate over one names the tier and the figure it breaks. " +
        std::to_string(r.overLintBudgets) +
        " candidates were not rendered: each was over the lint budgets of every tier still open that could take "
        "it.\n\n";
  md +=
      "| tier | budget | before: cost | dB | after: cost | dB | furnace | change "
      "|\n|---|---|--:|--:|--:|--:|--:|---|\n";
  for (const TierOutcome& o : r.tiers) {
    md += "| " + std::string(permutations::toString(o.tier)) + " | " + budgetText(o.budget) + " | ";
    md += o.shipped ? fixed(o.shipped->cost.total, 3) + " | " + fixed(o.shipped->result.error.psnr, 1) : "– | –";
    if (o.chosen)
      md += " | " + fixed(o.chosen->cost.total, 3) + " | " + fixed(o.chosen->result.error.psnr, 1) + " | " +
            fixed(o.chosen->result.furnaceGain, 3) + " | " +
            (o.shipped ? changes(o.shipped->result.configuration.config, o.chosen->result.configuration.config)
                       : o.chosen->result.configuration.name) +
            " |\n";
    else
      md += " | – | – | – | **" + o.failure + "** |\n";
  }
  if (!r.front.empty()) {
    md += "\n## Rendered candidates, cheapest first (★ on the front: nothing both cheaper and more accurate)\n\n";
    md += "| cost | fragment | vertex (model) |";
    for (const std::string& g : r.beside) md += " " + g + " fragment |";
    md += " dB | furnace | configuration (changes from reference) |\n|--:|--:|--:|";
    for (size_t i = 0; i < r.beside.size(); ++i) md += "--:|";
    md += "--:|--:|---|\n";
    for (const Scored& s : r.front) {
      md += "| " + fixed(s.cost.total, 3) + (s.pareto ? " ★" : "") + " | " + fixed(s.cost.fragment, 3) + " | " +
            fixed(s.cost.vertex, 3) + " |";
      // append, not `" " + std::string&&`: GCC 12 at -O3 reports a false -Wrestrict on that form.
      for (double b : s.besideFragment) md.append(" ").append(fixed(b, 3)).append(" |");
      md.append(s.result.psnrAtMost ? " ≤ " + fixed(*s.result.psnrAtMost, 1) : " " + fixed(s.result.error.psnr, 1));
      md.append(" | ").append(fixed(s.result.furnaceGain, 3));
      md.append(" | ").append(s.result.configuration.name);
      for (const auto& [tier, messages] : s.lintBreaches)
        md.append(" (over lint's ")
            .append(permutations::toString(tier))
            .append(" budget: ")
            .append(lintFigures(messages))
            .append(")");
      md.append(" |\n");
    }
  }
  return md;
}

std::string jsonReport(const TuneReport& r) {
  json j = json::object();
  j["material"] = r.material;
  j["gpu"] = r.gpu;
  j["cost"] = costDefinition(r);
  j["vertices_per_pixel"] = r.verticesPerPixel;
  j["beside"] = r.beside;
  j["reference_white_furnace_gain"] = r.referenceFurnaceGain;
  j["candidates"] = r.candidates;
  j["rendered"] = r.rendered;
  j["screened"] = r.screened;
  j["over_lint_budgets"] = r.overLintBudgets;
  j["tiers"] = json::array();
  for (const TierOutcome& o : r.tiers) {
    json t = json::object();
    t["tier"] = permutations::toString(o.tier);
    t["min_psnr_db"] = o.budget.minPsnrDb;
    t["no_energy_gain"] = o.budget.noEnergyGain;
    t["max_cost"] = o.budget.maxCost ? json(*o.budget.maxCost) : json(nullptr);
    t["before"] = o.shipped ? scoredJson(*o.shipped, r) : json(nullptr);
    t["after"] = o.chosen ? scoredJson(*o.chosen, r) : json(nullptr);
    t["best_reached"] = o.best ? scoredJson(*o.best, r) : json(nullptr);
    t["failure"] = o.failure.empty() ? json(nullptr) : json(o.failure);
    j["tiers"].push_back(t);
  }
  j["front"] = json::array();
  for (const Scored& s : r.front) j["front"].push_back(scoredJson(s, r));
  return j.dump(2) + "\n";
}

std::string plotSvg(const TuneReport& r) {
  eval::ScatterPlot plot;
  plot.title = r.material + ": PSNR against cost of the rendered candidates (red: Pareto front)";
  plot.note =
      "square: a tier as shipped; diamond: tuned (or the best reached); dashed: the budgets; "
      "hollow: first view only, at its PSNR's bound";
  plot.xLabel =
      "cost: " + r.gpu + " cycles per pixel (fragment + " + fixed(r.verticesPerPixel, 2) + " × vertex, docs/tune.md)";
  plot.yLabel = "PSNR against reference, dB (fp16 emulated, both views)";
  // The candidates' names are long: tooltips, so that the tiers' labels stay readable.
  for (const Scored& s : r.front)
    plot.points.push_back({s.cost.total, s.result.psnrAtMost ? *s.result.psnrAtMost : s.result.error.psnr,
                           s.result.configuration.name, s.pareto, false, bool(s.result.psnrAtMost)});
  // One colour per tier (matplotlib's blue, green, purple: none is the front's red).
  const char* colours[] = {"#1f77b4", "#2ca02c", "#9467bd"};
  for (size_t t = 0; t < r.tiers.size(); ++t) {
    const TierOutcome& o = r.tiers[t];
    const std::string tier = permutations::toString(o.tier);
    const std::string colour = colours[t % 3];
    if (o.shipped)
      plot.marks.push_back({o.shipped->cost.total, o.shipped->result.error.psnr, tier + " as shipped", colour,
                            eval::PlotMark::Shape::Square});
    if (o.chosen || o.best) {
      const Scored& after = o.chosen ? *o.chosen : *o.best;
      plot.marks.push_back({after.cost.total, after.result.error.psnr,
                            tier + (o.chosen ? " tuned" : " best reached, misses its budget"), colour,
                            eval::PlotMark::Shape::Diamond});
    }
    plot.lines.push_back({true, o.budget.minPsnrDb, tier + " ≥ " + fixed(o.budget.minPsnrDb, 1) + " dB", colour});
    if (o.budget.maxCost)
      plot.lines.push_back({false, *o.budget.maxCost, tier + " cost ≤ " + fixed(*o.budget.maxCost, 3), colour});
  }
  return eval::scatterPlotSvg(plot);
}

std::vector<package::OutputFile> reportFiles(const TuneReport& report, const std::string& outDir) {
  auto bytes = [](const std::string& s) { return std::vector<uint8_t>(s.begin(), s.end()); };
  const std::filesystem::path dir(outDir);
  return {{(dir / "report.md").string(), bytes(markdownReport(report))},
          {(dir / "report.json").string(), bytes(jsonReport(report))},
          {(dir / "plot.svg").string(), bytes(plotSvg(report))}};
}

}  // namespace facet::tune
