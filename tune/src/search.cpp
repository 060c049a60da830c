#include "facet/tune/search.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numeric>
#include <thread>

#include "facet/eval/configurations.h"
#include "facet/lint/lint.h"

namespace facet::tune {
namespace {

using permutations::Tier;
using permutations::TierConfig;

// "specular=lut diffuse=vertex": the axes where `config` differs from reference as shipped.
std::string nameOf(const TierConfig& config, const TierConfig& reference) {
  std::string name;
  for (const eval::Axis& axis : eval::axes()) {
    const std::string mine = axis.get(config);
    if (mine != axis.get(reference)) name += (name.empty() ? "" : " ") + std::string(axis.name) + "=" + mine;
  }
  return name.empty() ? "reference" : name;
}

std::vector<std::string> besideGpus(const std::string& target) {
  std::vector<std::string> out;
  for (const compiler::GpuCalibration& g : compiler::gpuCalibrations())
    if (g.gpu != target) out.push_back(g.gpu);
  return out;
}

// lint's budget rules over the candidate's <tier>.dir1 stages (the cost model's figures of both;
// costFragment and costVertex are that variant's), for each tier searched.
void checkLintBudgets(const std::string& material, const TuneOptions& options, Scored* s) {
  if (!options.lintBudgets) return;
  lint::LintOptions rules;
  rules.budgets = &*options.lintBudgets;
  for (Tier t : options.tiers) {
    lint::VariantFigures figures;
    figures.key = std::string(permutations::toString(t)) + ".dir1";
    figures.vertex.mobile = s->result.costVertex;
    figures.fragment.mobile = s->result.costFragment;
    std::vector<ir::Diagnostic> findings;
    lint::lintVariant(material, figures, rules, &findings);
    for (const ir::Diagnostic& d : findings)
      if (d.code == "budget") s->lintBreaches[t].push_back(d.message);
  }
}

Scored score(const eval::ConfigurationResult& r, const compiler::GpuCalibration& gpu, const TuneReport& report,
             const TuneOptions& options) {
  Scored s;
  s.result = r;
  s.cost = oneNumberCost(r, gpu, report.verticesPerPixel);
  for (const std::string& name : report.beside)
    s.besideFragment.push_back(
        compiler::calibratedEstimate(r.costFragment.counts, *compiler::findGpuCalibration(name)));
  checkLintBudgets(report.material, options, &s);
  return s;
}

// The tier may take the candidate as far as lint's budgets go.
bool fitsLint(const Scored& s, Tier tier) { return s.lintBreaches.find(tier) == s.lintBreaches.end(); }

// Among the fully measured: a screened candidate's PSNR is only bounded.
void markPareto(std::vector<Scored>* front) {
  for (Scored& a : *front) {
    a.pareto = !a.result.psnrAtMost;
    for (const Scored& b : *front) {
      if (!a.pareto) break;
      if (b.result.psnrAtMost) continue;
      const bool noWorse = b.cost.total <= a.cost.total && b.result.error.psnr >= a.result.error.psnr;
      const bool better = b.cost.total < a.cost.total || b.result.error.psnr > a.result.error.psnr;
      if (noWorse && better) {
        a.pareto = false;
        break;
      }
    }
  }
}

std::string describeBudget(const TierBudget& b) {
  char text[160];
  std::snprintf(text, sizeof text, "PSNR ≥ %.1f dB%s", b.minPsnrDb, b.noEnergyGain ? ", no energy gain" : "");
  std::string out = text;
  if (b.maxCost) {
    std::snprintf(text, sizeof text, ", cost ≤ %.3f", *b.maxCost);
    out += text;
  }
  return out;
}

// The session every search and re-score measures with: fp16 emulated (a mobile GPU's mediump),
// untimed (the cost model is the speed figure), reference rendered first.
std::unique_ptr<eval::Session> startSession(const ir::Material& material, const TuneOptions& options,
                                            const compiler::GpuCalibration** gpu, TuneReport* report,
                                            eval::EvalError* error) {
  *gpu = targetGpu(options.gpu, &error->message);
  if (!*gpu) return nullptr;
  eval::EvalOptions evalOptions = options.eval;
  evalOptions.fp16Emulation = true;
  evalOptions.timingFrames = 0;
  evalOptions.brdfSweep = false;
  std::unique_ptr<eval::Session> session = eval::Session::start(material, evalOptions, error);
  if (!session) return nullptr;
  report->material = material.name;
  report->gpu = options.gpu;
  report->beside = besideGpus(options.gpu);
  report->verticesPerPixel = options.budgets.verticesPerPixel;
  report->lintBudgets = options.lintBudgets.has_value();
  report->referenceFurnaceGain = session->report().results[0].furnaceGain;
  return session;
}

}  // namespace

Cost oneNumberCost(const eval::ConfigurationResult& result, const compiler::GpuCalibration& gpu,
                   double verticesPerPixel) {
  Cost c;
  c.fragment = compiler::calibratedEstimate(result.costFragment.counts, gpu);
  c.vertex = result.costVertex.cycles;
  c.total = c.fragment + verticesPerPixel * c.vertex;
  return c;
}

const compiler::GpuCalibration* targetGpu(const std::string& name, std::string* error) {
  const compiler::GpuCalibration* gpu = compiler::findGpuCalibration(name);
  if (gpu && std::string(gpu->measure).find("cycles") != std::string::npos) return gpu;
  std::string known;
  for (const compiler::GpuCalibration& g : compiler::gpuCalibrations())
    if (std::string(g.measure).find("cycles") != std::string::npos)
      known += (known.empty() ? "" : ", ") + std::string(g.gpu);
  *error =
      "--gpu: '" + name + "' cannot be a target: " +
      (gpu ? "its calibrated figure is " + std::string(gpu->measure) + ", not cycles (it is reported beside the target)"
           : std::string("not a calibrated GPU")) +
      " (targets: " + known + ")";
  return nullptr;
}

TierConfig withAxesOf(const ir::Material& material, TierConfig base, const TierConfig& axes) {
  for (const eval::Axis& axis : eval::axes())
    if (!axis.appliesToMaterial || axis.appliesToMaterial(material)) axis.set(&base, axis.get(axes));
  return base;
}

std::vector<TierConfig> candidates(const ir::Material& material) {
  const TierConfig reference = eval::configurations(material, {}, false).at(0).config;
  std::vector<const eval::Axis*> used;
  for (const eval::Axis& axis : eval::axes())
    if (!axis.appliesToMaterial || axis.appliesToMaterial(material)) used.push_back(&axis);
  std::vector<TierConfig> out;
  std::vector<size_t> choice(used.size(), 0);
  while (true) {
    TierConfig c = reference;
    for (size_t a = 0; a < used.size(); ++a) used[a]->set(&c, used[a]->options[choice[a]]);
    for (const eval::Axis* axis : used)
      if (axis->applies && !axis->applies(c)) axis->set(&c, axis->get(reference));
    if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
    size_t a = used.size();
    while (a > 0 && ++choice[a - 1] == used[a - 1]->options.size()) choice[--a] = 0;
    if (a == 0) break;
  }
  return out;
}

std::vector<TierConfig> neighbourhood(const ir::Material& material, const std::vector<Tier>& tiers, int maxChanges) {
  std::vector<TierConfig> all = candidates(material);
  if (maxChanges < 0) return all;
  std::vector<TierConfig> shipped;
  for (Tier t : tiers)
    shipped.push_back(withAxesOf(material, all.at(0), eval::configurations(material, {t}, false).at(1).config));
  auto near = [&](const TierConfig& c) {
    for (const TierConfig& s : shipped) {
      int changes = 0;
      for (const eval::Axis& axis : eval::axes()) changes += axis.get(c) != axis.get(s);
      if (changes <= maxChanges) return true;
    }
    return false;
  };
  std::erase_if(all, [&](const TierConfig& c) { return !near(c); });
  return all;
}

namespace {
// A tier may take a candidate of this cost (its optional cap).
bool withinCap(const TierBudget& budget, double cost) { return !budget.maxCost || cost <= *budget.maxCost; }
// The tier may take the candidate whatever its error: within its cost cap and its lint budgets.
bool mayTake(const TierOutcome& o, const Scored& s) { return withinCap(o.budget, s.cost.total) && fitsLint(s, o.tier); }
}  // namespace

bool meets(const Scored& s, const TierBudget& budget, double referenceFurnaceGain) {
  if (!(s.result.error.psnr >= budget.minPsnrDb)) return false;
  if (budget.noEnergyGain && eval::furnaceGainsEnergy(s.result.furnaceGain, referenceFurnaceGain)) return false;
  return withinCap(budget, s.cost.total);
}

std::optional<TuneReport> tune(const ir::Material& material, const TuneOptions& options, eval::EvalError* error) {
  TuneReport report;
  const compiler::GpuCalibration* gpu = nullptr;
  std::unique_ptr<eval::Session> session = startSession(material, options, &gpu, &report, error);
  if (!session) return std::nullopt;
  auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };

  // Every candidate costed, in parallel: each result lands at its own index, so the order and the
  // choice do not depend on the thread count.
  const TierConfig reference = session->report().results[0].configuration.config;
  std::vector<eval::Configuration> configs;
  for (const TierConfig& c :
       options.space.empty() ? neighbourhood(material, options.tiers, options.maxChanges) : options.space) {
    eval::Configuration config;
    config.tier = Tier::High;  // the images depend on the TierConfig alone, not on the tier's name
    config.config = c;
    config.name = nameOf(c, reference);
    config.change = "candidate";
    configs.push_back(std::move(config));
  }
  report.candidates = configs.size();
  std::vector<eval::ConfigurationResult> costed(configs.size());
  std::vector<eval::EvalError> errors(configs.size());
  std::vector<char> ok(configs.size(), 0);
  std::atomic<size_t> next{0};
  const auto costStart = std::chrono::steady_clock::now();
  const unsigned threads = std::max(1u, options.jobs ? options.jobs : std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (size_t i; (i = next++) < configs.size();) ok[i] = session->cost(configs[i], &costed[i], &errors[i]);
    });
  for (std::thread& t : pool) t.join();
  for (size_t i = 0; i < configs.size(); ++i)
    if (!ok[i]) {
      *error = errors[i];
      return std::nullopt;
    }
  char costedLine[128];
  std::snprintf(costedLine, sizeof costedLine, "%zu candidates costed on %s in %.1f s", configs.size(),
                options.gpu.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - costStart).count());
  say(costedLine);

  std::vector<Scored> scored;
  for (const eval::ConfigurationResult& r : costed) scored.push_back(score(r, *gpu, report, options));
  std::vector<size_t> order(scored.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return scored[a].cost.total < scored[b].cost.total; });

  for (Tier t : options.tiers) {
    TierOutcome o;
    o.tier = t;
    o.budget = options.budgets.forMaterial(material.name, t);
    const eval::Configuration shipped = eval::configurations(material, {t}, false).at(1);
    eval::ConfigurationResult r;
    if (!session->measure(shipped, &r, error)) return std::nullopt;
    o.shipped = score(r, *gpu, report, options);
    report.tiers.push_back(std::move(o));
  }

  // A candidate rendered and scored. screen: stop after the first view where the rest could not
  // lift the PSNR to an open tier's budget (within its cap), so that it would decide no choice.
  auto render = [&](size_t i, bool screen, Scored* s) {
    eval::ConfigurationResult r;
    eval::MeasureOptions how;
    how.costed = &costed[i];
    how.images = false;
    how.reuseIdenticalViews = options.reuseIdenticalViews;
    if (screen)
      how.worthFinishing = [&](double psnrAtMost) {
        for (const TierOutcome& o : report.tiers)
          if (!o.chosen && mayTake(o, scored[i]) && psnrAtMost >= o.budget.minPsnrDb) return true;
        return false;
      };
    // The furnace only where the error would meet an open tier's budget: elsewhere it decides nothing.
    how.furnaceWanted = [&](const eval::ConfigurationResult& scoredViews) {
      for (const TierOutcome& o : report.tiers)
        if (!o.chosen && fitsLint(scored[i], o.tier) && scoredViews.error.psnr >= o.budget.minPsnrDb) return true;
      return false;
    };
    if (!session->measure(configs[i], &r, error, how)) return false;
    *s = score(r, *gpu, report, options);
    const char* reused = r.viewsReused > 0 ? "  (an earlier candidate's render: the same build)" : "";
    char line[320];
    if (r.psnrAtMost)
      std::snprintf(line, sizeof line, "[%zu] %.3f ≤%5.1f dB  %s (first view)%s", report.rendered + 1, s->cost.total,
                    *r.psnrAtMost, s->result.configuration.name.c_str(), reused);
    else
      std::snprintf(line, sizeof line, "[%zu] %.3f  %5.1f dB  %s%s", report.rendered + 1, s->cost.total,
                    s->result.error.psnr, s->result.configuration.name.c_str(), reused);
    say(line);
    return true;
  };

  // Cheapest first; a candidate is rendered only while some tier without a choice could take it
  // (its cost within that tier's cap, its variant within the tier's lint budgets): the first that
  // meets a tier's budget is its cheapest.
  auto wanted = [&](size_t i) {
    for (const TierOutcome& o : report.tiers)
      if (!o.chosen && mayTake(o, scored[i])) return true;
    return false;
  };
  std::vector<size_t> frontCandidate;  // report.front[k] is candidate frontCandidate[k]
  for (size_t k = 0; k < order.size(); ++k) {
    const size_t i = order[k];
    bool anyOpen = false, anyWithinCap = false;
    for (const TierOutcome& o : report.tiers) {
      if (o.chosen) continue;
      anyOpen = true;
      anyWithinCap = anyWithinCap || withinCap(o.budget, scored[i].cost.total);
    }
    if (!anyOpen) break;
    if (!wanted(i)) {
      report.overLintBudgets += anyWithinCap ? 1 : 0;
      continue;
    }
    // The next candidate this one's render leaves wanted (unless it closes a tier) is built
    // meanwhile on the other core: the build and lavapipe's compile of this one overlap.
    if (threads > 1)
      for (size_t later = k + 1; later < order.size(); ++later)
        if (wanted(order[later])) {
          session->buildAhead(configs[order[later]]);
          break;
        }
    Scored s;
    if (!render(i, options.screen, &s)) return std::nullopt;
    ++report.rendered;
    report.reused += s.result.viewsReused > 0 ? 1 : 0;
    frontCandidate.push_back(i);
    for (TierOutcome& o : report.tiers) {
      if (o.chosen || s.result.psnrAtMost || !fitsLint(s, o.tier) || !meets(s, o.budget, report.referenceFurnaceGain))
        continue;
      o.chosen = s;
      o.chosen->result.configuration.config =
          withAxesOf(material, o.shipped->result.configuration.config, s.result.configuration.config);
      // Nothing strictly cheaper than the tier as shipped meets the budget and it does: it stays
      // (a candidate of equal cost is another spelling of the same shader, e.g. SH bands on a metal).
      if (s.cost.total >= o.shipped->cost.total && fitsLint(*o.shipped, o.tier) &&
          meets(*o.shipped, o.budget, report.referenceFurnaceGain))
        o.chosen = o.shipped;
    }
    report.front.push_back(std::move(s));
  }

  // A tier without a choice reports the most accurate rendered within its cap (the first of equals,
  // cheapest first): a screened candidate whose bound reaches the best measured is measured in full.
  for (TierOutcome& o : report.tiers) {
    if (o.chosen) continue;
    auto measuredBest = [&]() -> const Scored* {
      const Scored* best = nullptr;
      for (const Scored& s : report.front)
        if (!s.result.psnrAtMost && mayTake(o, s) && (!best || s.result.error.psnr > best->result.error.psnr))
          best = &s;
      return best;
    };
    for (size_t k = 0; k < report.front.size(); ++k) {
      const Scored* best = measuredBest();
      const Scored& s = report.front[k];
      if (!s.result.psnrAtMost || !mayTake(o, s) || (best && *s.result.psnrAtMost < best->result.error.psnr)) continue;
      Scored full;
      if (!render(frontCandidate[k], false, &full)) return std::nullopt;
      report.front[k] = std::move(full);
    }
    if (const Scored* best = measuredBest()) o.best = *best;
  }
  for (const Scored& s : report.front) report.screened += s.result.psnrAtMost ? 1 : 0;
  for (TierOutcome& o : report.tiers) {
    if (o.chosen) {
      o.best.reset();
      continue;
    }
    char text[512];
    if (o.best)
      std::snprintf(text, sizeof text,
                    "tier %s: no configuration meets its budget (%s): the best reached is %.2f dB at cost %.3f (%s)",
                    permutations::toString(o.tier), describeBudget(o.budget).c_str(), o.best->result.error.psnr,
                    o.best->cost.total, o.best->result.configuration.name.c_str());
    else
      std::snprintf(text, sizeof text, "tier %s: no configuration meets its budget (%s): none is within its cost cap%s",
                    permutations::toString(o.tier), describeBudget(o.budget).c_str(),
                    report.lintBudgets ? " and lint's budgets" : "");
    o.failure = text;
  }
  markPareto(&report.front);
  return report;
}

std::optional<TuneReport> rescore(const ir::Material& material, const std::vector<std::pair<Tier, TierConfig>>& choices,
                                  const TuneOptions& options, eval::EvalError* error) {
  TuneReport report;
  const compiler::GpuCalibration* gpu = nullptr;
  std::unique_ptr<eval::Session> session = startSession(material, options, &gpu, &report, error);
  if (!session) return std::nullopt;
  const TierConfig reference = session->report().results[0].configuration.config;
  for (const auto& [tier, config] : choices) {
    eval::Configuration c;
    c.tier = tier;
    c.config = config;
    c.name = std::string(permutations::toString(tier)) + " (tuned: " + nameOf(config, reference) + ")";
    c.change = "committed";
    eval::ConfigurationResult r;
    if (!session->measure(c, &r, error)) return std::nullopt;
    ++report.rendered;
    TierOutcome o;
    o.tier = tier;
    o.budget = options.budgets.forMaterial(material.name, tier);
    Scored s = score(r, *gpu, report, options);
    if (meets(s, o.budget, report.referenceFurnaceGain) && fitsLint(s, tier)) {
      o.chosen = s;
    } else if (!fitsLint(s, tier)) {
      o.failure = std::string("tier ") + permutations::toString(tier) +
                  ": the tuned configuration no longer fits its lint budget: " + s.lintBreaches.at(tier).front();
      o.best = s;
    } else {
      char text[512];
      std::snprintf(text, sizeof text,
                    "tier %s: the tuned configuration no longer meets its budget (%s): %.2f dB, furnace %.3f "
                    "(reference %.3f), cost %.3f",
                    permutations::toString(tier), describeBudget(o.budget).c_str(), s.result.error.psnr,
                    s.result.furnaceGain, report.referenceFurnaceGain, s.cost.total);
      o.failure = text;
      o.best = s;
    }
    report.tiers.push_back(std::move(o));
  }
  return report;
}

}  // namespace facet::tune
