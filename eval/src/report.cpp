#include "facet/eval/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "facet/compiler/cost_figures.h"
#include "facet/eval/scatter_plot.h"
#include "facet/gpu_stats/report.h"
#include "facet/package/package.h"

namespace facet::eval {
namespace {

using Json = nlohmann::ordered_json;

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string psnrText(const ImageMetrics& m) { return m.identical || std::isinf(m.psnr) ? "∞" : fmt("%.1f", m.psnr); }
std::string ratioText(double r) { return r > 0 ? fmt("%.2f", r) : "—"; }

Json errorJson(const ImageMetrics& m) {
  Json j;
  j["psnr_db"] = std::isinf(m.psnr) ? Json(nullptr) : Json(m.psnr);  // null: identical images
  j["identical"] = m.identical;
  j["mean_abs_8bit"] = m.meanAbs;
  j["p99_abs_8bit"] = m.p99Abs;
  j["max_abs_8bit"] = m.maxAbs;
  j["rel_rmse_hdr"] = m.relativeRmse;
  j["pixels"] = m.pixels;
  j["non_finite"] = m.nonFinite;
  return j;
}

// The cost model's figures of a stage (names in compiler/cost_figures.h), then its op classes.
Json costJson(const compiler::MobileStageCost& c) {
  using F = compiler::Figure;
  static constexpr F kFigures[] = {
      F::Cycles,   F::Bound,  F::ArithmeticCycles, F::TextureCycles,   F::VaryingCycles,         F::FmaSlots,
      F::CvtSlots, F::SfuOps, F::TextureSamples,   F::VaryingChannels, F::ScalarTranscendentals, F::ScalarDivisions};
  const compiler::StageFigures stage{c, {}};
  Json j;
  for (F f : kFigures) {
    const compiler::CostFigure& figure = compiler::costFigure(f);
    j[figure.name] = compiler::figureJson<Json>(figure, stage);
  }
  Json classes = Json::object();
  for (size_t k = 0; k < compiler::kOpClassCount; ++k)
    if (c.counts.ops[k] != 0) classes[compiler::toString(compiler::OpClass(k))] = c.counts.ops[k];
  const compiler::CostFigure& fmaRelaxed = compiler::costFigure(F::FmaRelaxed);
  classes[fmaRelaxed.name] = compiler::figureJson<Json>(fmaRelaxed, stage);
  j["op_classes"] = classes;
  return j;
}

Json expansionJson(const compiler::Expansion& e) { return Json{{"fma", e.fma}, {"sfu", e.sfu}}; }

Json weightsJson(const compiler::MobileCostWeights& w) {
  Json j;
  j["fma_per_cycle"] = w.fmaPerCycle;
  j["sfu_fma_slots"] = w.sfuFmaSlots;
  j["textures_per_cycle"] = w.texturesPerCycle;
  j["varying_channels_per_cycle"] = w.varyingChannelsPerCycle;
  j["pipes"] = w.pipes == compiler::ArithmeticPipes::Concurrent ? "concurrent" : "shared";
  j["relaxed_fma_weight"] = w.relaxedFmaWeight;
  Json e;
  e["sfu"] = expansionJson(w.sfu);
  e["exp_log"] = expansionJson(w.expLog);
  e["sqrt"] = expansionJson(w.sqrt);
  e["pow"] = expansionJson(w.pow);
  e["sin_cos"] = expansionJson(w.sinCos);
  e["tan"] = expansionJson(w.tan);
  e["inverse_trig"] = expansionJson(w.inverseTrig);
  e["atan2"] = expansionJson(w.atan2);
  e["hyperbolic"] = expansionJson(w.hyperbolic);
  e["inverse_hyperbolic"] = expansionJson(w.inverseHyperbolic);
  e["division"] = expansionJson(w.division);
  e["integer_division"] = expansionJson(w.integerDivision);
  e["derivative"] = expansionJson(w.derivative);
  j["expansions"] = e;
  return j;
}

// What the lavapipe column holds, for the JSON and the Markdown alike.
std::string timingDescription(const EvalReport& r) {
  if (r.timingClock.empty()) return "time: not measured (--frames 0)";
  return std::string(r.timingClock == "gpu_forward_pass"
                         ? "GPU time of the forward pass (Vulkan timestamps: the material's draws)"
                         : "wall time of RenderBackend::render() (the device reports no GPU time; it includes the "
                           "post pass, the submission and the read-back)") +
         " of the first view, as a ratio to reference's: the median over " + std::to_string(r.timingFrames) +
         " frames, each paired with a frame of reference (after warm-up). lavapipe is Mesa's Vulkan driver running "
         "on the CPU: its time is not a mobile GPU's (mediump runs in fp32, a texture read is a CPU routine)";
}

}  // namespace

Json reportJson(const EvalReport& r) {
  Json j;
  j["material"] = r.material;
  j["scene"] = r.scene;
  j["scene_notes"] = r.sceneNotes;
  j["views"] = r.viewNames;
  j["width"] = r.width;
  j["height"] = r.height;
  j["fp16_emulation"] = r.fp16Emulation;
  j["tuning_file"] = r.tuningFile;
  j["error_measure"] =
      "against reference as shipped, over the pixels the material covers in either image, all views together";
  j["timing"] = Json{{"what", timingDescription(r)},
                     {"clock", r.timingClock},
                     {"frames", r.timingFrames},
                     {"warmup_frames", r.warmupFrames}};
  j["cost_model"] = weightsJson(r.weights);
  if (r.groundTruthSamples > 0)
    j["ground_truth"] = Json{{"what", "reference with its environment integrated per pixel by importance sampling"},
                             {"samples", r.groundTruthSamples},
                             {"quarter_samples_error", errorJson(r.groundTruthConvergence)}};
  Json configs = Json::array();
  for (const ConfigurationResult& c : r.results) {
    Json k;
    k["name"] = c.configuration.name;
    k["tier"] = permutations::toString(c.configuration.tier);
    k["axis"] = c.configuration.axis;
    k["option"] = c.configuration.option;
    k["change"] = c.configuration.change;
    k["tier_config"] = permutations::describe(c.configuration.config);
    k["variant"] = c.variantKey;
    k["same_as"] = c.sameAs;
    k["error"] = errorJson(c.error);
    k["ground_truth_error"] = c.groundTruthError ? errorJson(*c.groundTruthError) : Json(nullptr);
    Json views = Json::array();
    for (const ViewResult& v : c.views)
      views.push_back(Json{{"name", v.name}, {"image", v.image}, {"error", errorJson(v.error)}});
    k["views"] = views;
    k["cost"] = Json{{"fragment", costJson(c.fragment)}, {"vertex", costJson(c.vertex)}};
    k["cycles_vs_high"] = c.cyclesVsHigh > 0 ? Json(c.cyclesVsHigh) : Json(nullptr);
    k["cycles_vs_reference"] = c.cyclesVsReference;
    k["sun_ibl_fragment_cycles"] = c.sunIblFragmentCycles > 0 ? Json(c.sunIblFragmentCycles) : Json(nullptr);
    k["sun_ibl_vs_high"] = c.sunIblVsHigh > 0 ? Json(c.sunIblVsHigh) : Json(nullptr);
    k["lavapipe_ms"] = 1000.0 * c.seconds;
    k["lavapipe_vs_reference"] = c.timeVsReference > 0 ? Json(c.timeVsReference) : Json(nullptr);
    k["pareto"] = c.pareto;
    k["white_furnace_gain"] = c.furnaceGain > 0 ? Json(c.furnaceGain) : Json(nullptr);
    configs.push_back(k);
  }
  j["configurations"] = configs;
  if (!r.brdfSweep.empty() || !r.modelLobeSweep.empty()) {
    auto rowsJson = [](const std::vector<BrdfSweepRow>& rows) {
      Json out = Json::array();
      for (const BrdfSweepRow& b : rows) {
        Json row{{"lobe", b.lobe},
                 {"precision", b.precision},
                 {"configurations", b.configurations},
                 {"roughness", b.roughness},
                 {"relative_rmse_per_roughness", b.rowRelativeRmse},
                 {"mean_relative_rmse", b.meanRelativeRmse},
                 {"relative_rmse_per_roughness_nov_weighted", b.rowScreenRmse},
                 {"mean_relative_rmse_nov_weighted", b.meanScreenRmse},
                 {"worst_relative_rmse", b.worstRelativeRmse},
                 {"worst_roughness", b.worstRoughness},
                 {"non_finite", b.nonFinite},
                 {"beyond_binary16", b.beyondHalf}};
        if (!b.hardCase.empty()) {
          row["hard_cases"] = b.hardCase;
          row["hard_case_psnr_vs_highp"] = std::isfinite(b.hardCasePsnr) ? Json(b.hardCasePsnr) : Json(nullptr);
        }
        out.push_back(row);
      }
      return out;
    };
    Json furnace = Json::array();
    for (const LobeFurnaceRow& f : r.lobeFurnace)
      furnace.push_back(Json{{"lobe", f.lobe},
                             {"precision", f.precision},
                             {"configurations", f.configurations},
                             {"integrand", f.integrand},
                             {"max_albedo", std::isfinite(f.maxAlbedo) ? Json(f.maxAlbedo) : Json(nullptr)},
                             {"at_nov", f.atNoV},
                             {"at_roughness", f.atRoughness},
                             {"at_anisotropy", f.atAnisotropy},
                             {"bound", f.bound > 0 ? Json(f.bound) : Json(nullptr)},
                             {"within_bound", f.withinBound()}});
    j["brdf_domain"] = Json{{"what",
                             "f_s * n.l of each specular lobe against double GGX/Smith/Schlick over n.v x n.l x "
                             "azimuth x roughness x f0; relative RMSE per roughness row"},
                            {"lobes", rowsJson(r.brdfSweep)},
                            {"model_lobes", rowsJson(r.modelLobeSweep)},
                            {"white_furnace", furnace}};
  }
  if (!r.gpuStats.empty()) {
    j["figures"] = gpu_stats::sourceNote(r.gpuStats);
    Json gpus = Json::array();
    for (const gpu_stats::GpuStats& g : r.gpuStats) {
      Json jg = Json::parse(gpu_stats::toJson(g).dump());
      const compiler::GpuCalibration* c = g.unavailable.empty() ? nullptr : compiler::findGpuCalibration(g.gpu);
      if (c) {
        Json estimate{{"measure", c->measure},
                      {"cross_validated_mean_error", c->crossValidatedMeanError},
                      {"cross_validated_max_error", c->crossValidatedMaxError},
                      {"configurations", Json::object()}};
        for (const ConfigurationResult& k : r.results)
          estimate["configurations"][k.configuration.name] = compiler::calibratedEstimate(k.fragment.counts, *c);
        jg["calibrated_estimate"] = estimate;
      }
      gpus.push_back(jg);
    }
    j["gpus"] = gpus;
  }
  return j;
}

namespace {

// The fragment shader of each configuration on each measured GPU (Mali: Mesa's cycle bound and
// its pipe; Adreno: instructions, as ir3 prints no cycles).
std::string gpuMarkdown(const EvalReport& r) {
  std::string s = "\n**Per-GPU figures**: " + gpu_stats::sourceNote(r.gpuStats) +
                  ". Fragment shader of each configuration's variant (GLSL ES 3.00 as shipped), compiled by Mesa; "
                  "Mali: Mesa's cycle bound and the pipe that sets it, Adreno: instructions (docs/mesa-statistics.md). "
                  "A GPU Mesa could not measure gets the calibrated estimate from the op counts instead (\"estimate\": "
                  "Mali cycles, Adreno non-nop instructions; docs/mesa-statistics.md, \"Calibration\").\n";
  struct Column {
    const gpu_stats::GpuStats* measured = nullptr;
    const compiler::GpuCalibration* estimate = nullptr;
    std::string title;
  };
  std::vector<Column> columns;
  for (const gpu_stats::GpuStats& g : r.gpuStats) {
    if (g.unavailable.empty())
      columns.push_back({&g, nullptr, g.gpu});
    else if (const compiler::GpuCalibration* c = compiler::findGpuCalibration(g.gpu))
      columns.push_back({nullptr, c, g.gpu + " (estimate)"});
  }
  if (columns.empty()) return s;
  s += "\n| configuration | variant |";
  for (const Column& col : columns) s += " " + col.title + " |";
  s += "\n|---|---|";
  for (size_t i = 0; i < columns.size(); ++i) s += "--:|";
  s += "\n";
  for (const ConfigurationResult& c : r.results) {
    s += "| " + c.configuration.name + " | " + c.variantKey + " |";
    const std::string& name = c.sameAs.empty() ? c.configuration.name : c.sameAs;
    for (const Column& col : columns) {
      if (col.estimate) {
        s += " " + fmt("%.2f", compiler::calibratedEstimate(c.fragment.counts, *col.estimate)) + " |";
        continue;
      }
      const gpu_stats::StageStats* f = col.measured->find(name, "fragment");
      std::string cell = !f          ? "—"
                         : f->cycles ? fmt("%.2f", *f->cycles) + (f->bound.empty() ? "" : " (" + f->bound + ")")
                                     : fmt("%.0f", f->instructions) + " instr.";
      s += " " + cell + " |";
    }
    s += "\n";
  }
  return s;
}

// The first four configurations' names, then how many more.
std::string configurationNames(const std::vector<std::string>& configurations) {
  std::string names;
  for (size_t i = 0; i < configurations.size() && i < 4; ++i) names += (i ? ", " : "") + configurations[i];
  if (configurations.size() > 4) names += ", +" + std::to_string(configurations.size() - 4);
  return names;
}

// The lobes over the BRDF domain (brdf_sweep.h), one row per (lobe, precision).
std::string brdfSweepMarkdown(const std::vector<BrdfSweepRow>& rows, const BrdfSweepDomain& domain) {
  std::string s =
      "\n**BRDF domain**: each specular lobe on its own (f_s · n·l), run on lavapipe over " +
      std::to_string(domain.cosines) + " n·v × " + std::to_string(domain.cosines) + " n·l × " +
      std::to_string(domain.azimuths.size()) + " azimuths × " + std::to_string(domain.roughnesses) +
      " roughnesses (0.089…1) × " + std::to_string(domain.f0.size()) +
      " f0, against GGX × height-correlated Smith × Schlick in double precision. Relative RMSE per "
      "roughness row (√Σ(f − g)² / √Σg²); mediump lobes run with binary16 rounding (fp16 emulation). "
      "Left out of every row alike: the " +
      std::to_string(rows.empty() ? 0 : rows[0].beyondHalf) +
      " samples where the exact f_s exceeds binary16's 65504 (the roughness floor near the grazing mirror), "
      "where every mediump lobe saturates by design. Weighed by n·v: the same with each sample weighed by n·v, as "
      "a sphere's pixels are (grazing views cover few).\n\n"
      "| lobe | precision | configurations | rel. RMSE, mean over r | worst r (rel. RMSE) | weighed by n·v | "
      "non-finite |\n|---|---|---|--:|--:|--:|--:|\n";
  for (const BrdfSweepRow& b : rows) {
    s += "| " + b.lobe + " | " + b.precision + " | " + configurationNames(b.configurations) + " | " +
         fmt("%.4f", b.meanRelativeRmse) + " | " + fmt("%.3f", b.worstRoughness) + " (" +
         fmt("%.4f", b.worstRelativeRmse) + ") | " + fmt("%.4f", b.meanScreenRmse) + " | " +
         std::to_string(b.nonFinite) + " |\n";
  }
  return s;
}

// The material models' lobes over the BRDF domain (lobe_sweep.h).
std::string modelLobesMarkdown(const EvalReport& r) {
  std::string s =
      "\n**The material models' lobes** over the same domain (the anisotropic lobe also over anisotropy "
      "−1…1 and the view's azimuth about the tangent), each chunk against its double model "
      "(`eval/include/facet/eval/standard_model.h`); `+ base`: the coat over a white Lambertian base "
      "attenuated by 1 − Fc(n·v). Hard cases: the mediump chunk's PSNR against its highp form (peak: the "
      "highp lobe's largest value there).\n\n"
      "| lobe | precision | configurations | rel. RMSE, mean over r | worst r (rel. RMSE) | weighed by n·v | "
      "non-finite | hard cases, PSNR dB |\n|---|---|---|--:|--:|--:|--:|--:|\n";
  for (const BrdfSweepRow& b : r.modelLobeSweep) {
    std::string hard = "—";
    if (!b.hardCase.empty())
      hard = std::isinf(b.hardCasePsnr) && b.hardCasePsnr > 0 ? "∞" : fmt("%.1f", b.hardCasePsnr);
    s += "| " + b.lobe + " | " + b.precision + " | " + configurationNames(b.configurations) + " | " +
         fmt("%.4f", b.meanRelativeRmse) + " | " + fmt("%.3f", b.worstRoughness) + " (" +
         fmt("%.4f", b.worstRelativeRmse) + ") | " + fmt("%.4f", b.meanScreenRmse) + " | " +
         std::to_string(b.nonFinite) + " | " + hard + " |\n";
  }
  return s;
}

// The white furnace of each lobe (lobe_sweep.h): the standard specular lobes' and the models'.
std::string lobeFurnaceMarkdown(const EvalReport& r) {
  std::string s =
      "\nWhite furnace of each lobe: the directional albedo E(n·v, r) = ∫ f · n·l dω of the chunk's output by "
      "quadrature on the GPU (GGX lobes: " +
      std::to_string(r.furnaceDomain.ggxSamples) + " GGX-distributed half vectors; the sheen: a " +
      std::to_string(r.furnaceDomain.sheenSteps) + " × " + std::to_string(r.furnaceDomain.sheenSteps / 2) +
      " grid), n·v from 1e-4 to 1, the largest over the domain and where:\n\n"
      "| lobe | precision | integrand | max albedo | at n·v, r (, anisotropy) | bound |\n|---|---|---|--:|---|---|\n";
  for (const LobeFurnaceRow& f : r.lobeFurnace) {
    std::string at = fmt("%.4g", f.atNoV) + ", " + fmt("%.3f", f.atRoughness);
    if (f.lobe.rfind("anisotropy", 0) == 0) at += ", " + fmt("%.2f", f.atAnisotropy);
    std::string bound = f.bound > 0 ? (f.withinBound() ? "≤ " : "**above** ") + fmt("%.3f", f.bound) : "reported";
    s += "| " + f.lobe + " | " + f.precision + " | " + f.integrand + " | " + fmt("%.5f", f.maxAlbedo) + " | " + at +
         " | " + bound + " |\n";
  }
  return s;
}

// Each configuration against the ground truth beside its error against reference (docs/eval.md,
// "The ground truth").
std::string groundTruthMarkdown(const EvalReport& r) {
  std::string s =
      "\nAgainst the ground truth: reference with its environment integrated per pixel by importance "
      "sampling, " +
      std::to_string(r.groundTruthSamples) + " points per integral (at a quarter of them it differs by " +
      psnrText(r.groundTruthConvergence) + " dB PSNR, relative RMSE " +
      fmt("%.4f", r.groundTruthConvergence.relativeRmse) + ").\n\n";
  s += "Images: `images/ground_truth.<view>.png`.\n\n";
  s += "| configuration | PSNR dB vs ground truth | rel. RMSE vs ground truth | PSNR dB vs reference |\n";
  s += "|---|--:|--:|--:|\n";
  for (const ConfigurationResult& c : r.results) {
    if (!c.groundTruthError) continue;
    s += "| " + c.configuration.name + " | " + psnrText(*c.groundTruthError) + " | " +
         fmt("%.4f", c.groundTruthError->relativeRmse) + " | " + psnrText(c.error) + " |\n";
  }
  return s;
}

}  // namespace

std::string reportMarkdown(const EvalReport& r) {
  std::string s = "# `matc eval`: " + r.material + "\n\n";
  s += "Scene: " + r.scene + ", " + std::to_string(r.width) + "×" + std::to_string(r.height) + " per view; views: ";
  for (size_t i = 0; i < r.viewNames.size(); ++i) s += (i ? ", " : "") + r.viewNames[i];
  s += ".";
  if (r.fp16Emulation) s += " Built with `--fp16-emulation` (mediump SPIR-V rounded to binary16).";
  if (!r.tuningFile.empty()) s += " The tiers as shipped are the tuned ones of `" + r.tuningFile + "`.";
  s += "\n\n";
  for (const std::string& note : r.sceneNotes) s += "- " + note + "\n";
  if (!r.sceneNotes.empty()) s += "\n";
  s += "**Error** against `reference` as shipped, over the pixels the material covers, all views together: "
       "PSNR of the tone-mapped 8-bit image, mean and 99th-percentile absolute error in 8-bit steps, relative "
       "RMSE of the linear HDR image.\n"
       "**Speed**: estimated Valhall-class cycles per fragment and per vertex from the mobile cost model "
       "(docs/eval.md), fragment cycles as a ratio to `high` and `reference` as shipped; and lavapipe's " +
       timingDescription(r) +
       ".\n"
       "★: on the Pareto front (no other configuration has both fewer fragment cycles and a higher PSNR).\n\n";
  s += "| configuration | changes | PSNR dB | mean | p99 | rel. RMSE | frag. cycles | vert. cycles | × high | × "
       "reference "
       "| lavapipe × reference | |\n";
  s += "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|:-:|\n";
  for (const ConfigurationResult& c : r.results) {
    std::string change = c.configuration.change;
    if (!c.sameAs.empty()) change += " (same maths as " + c.sameAs + ")";
    s += "| " + c.configuration.name + " | " + change + " | " + psnrText(c.error) + " | " +
         fmt("%.2f", c.error.meanAbs) + " | " + fmt("%.0f", c.error.p99Abs) + " | " +
         fmt("%.4f", c.error.relativeRmse) + " | " + fmt("%.2f", c.fragment.cycles) + " | " +
         fmt("%.2f", c.vertex.cycles) + " | " + ratioText(c.cyclesVsHigh) + " | " + ratioText(c.cyclesVsReference) +
         " | " + ratioText(c.timeVsReference) + " | " + (c.pareto ? "★" : "") + " |\n";
  }
  // The cost goals are stated for the sun + IBL variant (no point light): the tiers as shipped.
  std::string sunIbl;
  for (const ConfigurationResult& c : r.results) {
    if (c.configuration.swap() || c.sunIblFragmentCycles <= 0) continue;
    sunIbl += (sunIbl.empty() ? "" : ", ") + c.configuration.name + " " + fmt("%.2f", c.sunIblFragmentCycles);
    if (c.sunIblVsHigh > 0) sunIbl += " (" + fmt("%.2f", c.sunIblVsHigh) + "× high)";
  }
  if (!sunIbl.empty())
    s += "\nFragment cycles of the sun + IBL variant (`<tier>.dir1`, no point light; what the tiers' cost goals "
         "refer to), tiers as shipped: " +
         sunIbl + ".\n";
  // The white furnace (lit materials): the configurations that gain energy, and the largest gain.
  std::string gains;
  double largest = 0;
  const double referenceGain = r.results.empty() ? 0.0 : r.results[0].furnaceGain;
  for (const ConfigurationResult& c : r.results) {
    largest = std::max(largest, c.furnaceGain);
    if (furnaceGainsEnergy(c.furnaceGain, referenceGain))
      gains += (gains.empty() ? "" : ", ") + c.configuration.name + " " + fmt("%.3f", c.furnaceGain);
  }
  if (largest > 0)
    s += "\nWhite furnace (the first view's spheres in a constant sky, no lights; the brightest value they cover ÷ "
         "the sky's radiance; energy gain: above " +
         fmt("%.2f", kFurnaceGainLimit) +
         " and above reference's by that "
         "factor): reference " +
         fmt("%.3f", referenceGain) + ", largest " + fmt("%.3f", largest) + "; " +
         (gains.empty() ? std::string("no configuration gains energy") : "energy gain: " + gains) + ".\n";
  if (r.groundTruthSamples > 0) s += groundTruthMarkdown(r);
  if (!r.gpuStats.empty()) s += gpuMarkdown(r);
  if (!r.brdfSweep.empty()) s += brdfSweepMarkdown(r.brdfSweep, r.brdfDomain);
  if (!r.modelLobeSweep.empty()) s += modelLobesMarkdown(r);
  if (!r.lobeFurnace.empty()) s += lobeFurnaceMarkdown(r);
  s += "\nPer view (PSNR dB):\n\n| configuration |";
  for (const std::string& v : r.viewNames) s += " " + v + " |";
  s += "\n|---|";
  for (size_t i = 0; i < r.viewNames.size(); ++i) s += "--:|";
  s += "\n";
  for (const ConfigurationResult& c : r.results) {
    s += "| " + c.configuration.name + " |";
    for (const ViewResult& v : c.views) s += " " + psnrText(v.error) + " |";
    s += "\n";
  }
  s += "\nImages: `images/<configuration>.<view>.png`; the plot of error against cost: `plot.svg`; the same data: "
       "`report.json`.\n";
  return s;
}

std::string reportSvg(const EvalReport& r) {
  ScatterPlot plot;
  plot.title = r.material + ": error against estimated cost (red: Pareto front)";
  plot.xLabel = "estimated fragment cycles (mobile cost model, docs/eval.md)";
  plot.yLabel = "PSNR against reference, dB (higher is better)";
  for (const ConfigurationResult& c : r.results)
    plot.points.push_back({c.fragment.cycles, c.error.psnr, c.configuration.name, c.pareto});
  return scatterPlotSvg(plot);
}

std::vector<package::OutputFile> reportFiles(const EvalReport& report, const std::string& outDir) {
  namespace fs = std::filesystem;
  auto file = [&](const std::string& name, const std::string& text) {
    return package::OutputFile{(fs::path(outDir) / name).string(), std::vector<uint8_t>(text.begin(), text.end())};
  };
  std::vector<package::OutputFile> files{file("report.md", reportMarkdown(report)),
                                         file("report.json", reportJson(report).dump(2) + "\n"),
                                         file("plot.svg", reportSvg(report))};
  for (const ConfigurationResult& r : report.results)
    if (r.sameAs.empty())  // the others show the images of the configuration they are the same as
      for (const ViewResult& v : r.views) files.push_back({(fs::path(outDir) / v.image).string(), v.png});
  for (const ViewResult& v : report.groundTruthViews) files.push_back({(fs::path(outDir) / v.image).string(), v.png});
  return files;
}

bool writeReport(const EvalReport& report, const std::string& outDir, std::string* error) {
  std::error_code ec;
  const std::filesystem::path images = std::filesystem::path(outDir) / "images";
  std::filesystem::create_directories(images, ec);
  if (ec) {
    *error = "cannot create '" + images.string() + "': " + ec.message();
    return false;
  }
  return package::writeFiles(reportFiles(report, outDir), error);
}

}  // namespace facet::eval
