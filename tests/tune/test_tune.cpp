// matc tune's library (tune/): the budgets and the tuning file (their errors at a JSON pointer),
// the candidates, and the search and the gate rendered on a small space of a tiny grid.
#include <gtest/gtest.h>

#include <expat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "facet/eval/configurations.h"
#include "facet/ir/check.h"
#include "facet/lint/lint.h"
#include "facet/tune/choices.h"
#include "facet/tune/report.h"
#include "facet/tune/search.h"
#include "test_support.h"

namespace {

using facet::permutations::Tier;
using facet::permutations::TierConfig;
namespace tune = facet::tune;

facet::ir::Material example(const std::string& name) {
  facet::ir::SourceFile file{name + ".mat",
                             facet::test::readText(facet::test::examplePath("materials/" + name + ".mat"))};
  facet::ir::Diagnostics diags(file);
  auto m = facet::ir::compileSource(file, diags);
  EXPECT_TRUE(m) << diags.format();
  return m ? *m : facet::ir::Material{};
}

std::string budgetError(const std::string& text) {
  std::string error;
  EXPECT_FALSE(tune::parseBudgets("b.json", text, &error)) << text;
  return error;
}

// A small space: each tier as shipped and its single-option swaps of the specular and diffuse
// axes (eval's configurations), without repeats, in mediump: under fp16 emulation none renders
// reference exactly.
std::vector<TierConfig> smallSpace(const facet::ir::Material& m) {
  std::vector<TierConfig> out;
  for (const facet::eval::Configuration& c : facet::eval::configurations(m, {Tier::High, Tier::Mid, Tier::Low}))
    if ((!c.swap() || c.axis == "specular" || c.axis == "diffuse") && c.tier != Tier::Reference &&
        std::find(out.begin(), out.end(), c.config) == out.end())
      out.push_back(c.config);
  return out;
}

// An SVG read with expat: whether it is well-formed XML, how many of each element it has and the
// text of its <text> elements.
struct SvgContents {
  bool wellFormed = false;
  std::string root;
  std::map<std::string, int> elements;
  std::vector<std::string> texts;
};

SvgContents readSvg(const std::string& svg) {
  SvgContents out;
  struct State {
    SvgContents* out;
    bool inText = false;
  } state{&out};
  XML_Parser parser = XML_ParserCreate("UTF-8");
  XML_SetUserData(parser, &state);
  XML_SetElementHandler(
      parser,
      [](void* data, const XML_Char* name, const XML_Char**) {
        auto* st = static_cast<State*>(data);
        if (st->out->root.empty()) st->out->root = name;
        ++st->out->elements[name];
        if (std::string(name) == "text") {
          st->inText = true;
          st->out->texts.emplace_back();
        }
      },
      [](void* data, const XML_Char* name) {
        if (std::string(name) == "text") static_cast<State*>(data)->inText = false;
      });
  XML_SetCharacterDataHandler(parser, [](void* data, const XML_Char* text, int length) {
    auto* st = static_cast<State*>(data);
    if (st->inText) st->out->texts.back().append(text, size_t(length));
  });
  out.wellFormed = XML_Parse(parser, svg.data(), int(svg.size()), 1) == XML_STATUS_OK;
  XML_ParserFree(parser);
  return out;
}

tune::TuneOptions tinyGrid() {
  tune::TuneOptions o;
  o.eval.grid.pixelsPerSphere = 8;
  return o;
}

// The small space searched for mid (≥ 36 dB) and low (≥ 28 dB) on the tiny grid: budgets the
// cheap lobes meet, so the searches stop early.
tune::TuneOptions midAndLowSearch(const facet::ir::Material& m) {
  tune::TuneOptions o = tinyGrid();
  o.space = smallSpace(m);
  o.tiers = {Tier::Mid, Tier::Low};
  o.budgets.tiers[Tier::Mid].minPsnrDb = 36;
  o.budgets.tiers[Tier::Low].minPsnrDb = 28;
  return o;
}

}  // namespace

TEST(TuneBudgets, DefaultsProjectFileAndPerMaterialEntries) {
  const tune::Budgets d = tune::defaultBudgets();
  EXPECT_EQ(d.tiers.at(Tier::High).minPsnrDb, 50);
  EXPECT_EQ(d.tiers.at(Tier::Mid).minPsnrDb, 40);
  EXPECT_EQ(d.tiers.at(Tier::Low).minPsnrDb, 34);
  EXPECT_TRUE(d.tiers.at(Tier::Low).noEnergyGain);
  EXPECT_FALSE(d.tiers.at(Tier::Low).maxCost);
  EXPECT_EQ(d.verticesPerPixel, tune::kDefaultVerticesPerPixel);

  std::string error;
  auto b = tune::parseBudgets("b.json", R"({
    "materials": {"brushed_gold": {"low": {"min_psnr_db": 30}}},
    "tiers": {"mid": {"min_psnr_db": 38, "max_cost": 1.5}},
    "vertices_per_pixel": 0.25})",
                              &error);
  ASSERT_TRUE(b) << error;
  EXPECT_EQ(b->verticesPerPixel, 0.25);
  EXPECT_EQ(b->forMaterial("red_plastic", Tier::Mid).minPsnrDb, 38);
  EXPECT_EQ(*b->forMaterial("red_plastic", Tier::Mid).maxCost, 1.5);
  EXPECT_EQ(b->forMaterial("red_plastic", Tier::High).minPsnrDb, 50);  // the default stays
  EXPECT_EQ(b->forMaterial("brushed_gold", Tier::Low).minPsnrDb, 30);
  EXPECT_EQ(b->forMaterial("red_plastic", Tier::Low).minPsnrDb, 34);
  EXPECT_TRUE(b->lintBudgetsPath.empty());

  // lint's budgets file, beside the budgets file unless the path is absolute.
  auto named = tune::parseBudgets("project/lint/tune.json", R"({"lint_budgets": "budgets.json"})", &error);
  ASSERT_TRUE(named) << error;
  EXPECT_EQ(named->lintBudgetsPath, "project/lint/budgets.json");
  named = tune::parseBudgets("project/lint/tune.json", R"({"lint_budgets": "/etc/lint.json"})", &error);
  ASSERT_TRUE(named) << error;
  EXPECT_EQ(named->lintBudgetsPath, "/etc/lint.json");
}

TEST(TuneBudgets, BadFilesFailAtTheirJsonPointer) {
  EXPECT_EQ(budgetError(R"({"tiers": {"ultra": {}}})"),
            "b.json: error: /tiers/ultra: unknown tier 'ultra' (known: high, mid, low)");
  EXPECT_EQ(budgetError(R"({"tiers": {"reference": {}}})"),
            "b.json: error: /tiers/reference: unknown tier 'reference' (known: high, mid, low)");
  EXPECT_EQ(budgetError(R"({"tiers": {"mid": {"min_psnr_db": "40"}}})"),
            "b.json: error: /tiers/mid/min_psnr_db: expected a number");
  EXPECT_EQ(
      budgetError(R"({"tiers": {"mid": {"min_psnr": 40}}})"),
      "b.json: error: /tiers/mid/min_psnr: unknown key 'min_psnr' (known: min_psnr_db, max_cost, no_energy_gain)");
  EXPECT_EQ(budgetError(R"({"tiers": {"mid": {"max_cost": -1}}})"),
            "b.json: error: /tiers/mid/max_cost: expected a number from 0 to 1e+06");
  EXPECT_EQ(budgetError(R"({"tiers": {"mid": {"no_energy_gain": 1}}})"),
            "b.json: error: /tiers/mid/no_energy_gain: expected true or false");
  EXPECT_EQ(budgetError(R"({"materials": {"m": {"low": []}}})"), "b.json: error: /materials/m/low: expected an object");
  EXPECT_EQ(budgetError(R"({"vertices_per_pixel": 100})"),
            "b.json: error: /vertices_per_pixel: expected a number from 0 to 16");
  EXPECT_EQ(budgetError(R"({"tier": {}})"),
            "b.json: error: /tier: unknown key 'tier' (known: tiers, materials, vertices_per_pixel, lint_budgets)");
  EXPECT_EQ(budgetError(R"({"lint_budgets": 1})"),
            "b.json: error: /lint_budgets: expected the path of lint's budgets file");
  EXPECT_EQ(budgetError(R"({"lint_budgets": ""})"),
            "b.json: error: /lint_budgets: expected the path of lint's budgets file");
  EXPECT_EQ(budgetError("[]"), "b.json: error: /: expected an object");
  EXPECT_NE(budgetError(R"({"tiers": {}, "tiers": {}})").find("duplicate key"), std::string::npos);
  EXPECT_NE(budgetError(R"({"tiers": )").find("b.json:1:"), std::string::npos);
}

TEST(TuneChoices, WrittenDeterministicallyAndReadBack) {
  const facet::ir::Material m = example("red_plastic");
  tune::Choices c;
  c.material = "red_plastic";
  c.gpu = "mali-g57";
  c.verticesPerPixel = 0.1;
  TierConfig low = facet::eval::configurations(m, {Tier::Low}, false).at(1).config;
  low.shBands = 3;
  c.tiers.push_back({Tier::Low, low, 1.23456, 37.04});
  const std::string text = tune::writeChoices(c);
  EXPECT_EQ(text, tune::writeChoices(c));
  EXPECT_NE(text.find("\"cost\": 1.235"), std::string::npos) << text;
  std::string error;
  auto back = tune::parseChoices("t.json", text, m, &error);
  ASSERT_TRUE(back) << error;
  ASSERT_EQ(back->tiers.size(), 1u);
  EXPECT_EQ(back->tiers[0].tier, Tier::Low);
  EXPECT_TRUE(back->tiers[0].config == low);
  EXPECT_EQ(back->gpu, "mali-g57");

  auto bad = [&](const std::string& t) {
    std::string e;
    EXPECT_FALSE(tune::parseChoices("t.json", t, m, &e)) << t;
    return e;
  };
  EXPECT_EQ(bad(R"({"material": "red_plastic", "tiers": {"mid": {"config": {"specular": "phong"}}}})"),
            "t.json: error: /tiers/mid/config/specular: unknown option 'phong' (known: ggx_smith, ggx_fastv, "
            "fused_hammon, zioma, lut)");
  EXPECT_EQ(bad(R"({"material": "red_plastic", "tiers": {"mid": {"config": {"shading": "x"}}}})"),
            "t.json: error: /tiers/mid/config/shading: unknown axis 'shading'");
  EXPECT_EQ(bad(R"({"material": "brushed_gold", "tiers": {}})"),
            "t.json: error: /material: the file tunes 'brushed_gold', not 'red_plastic'");
  EXPECT_EQ(bad(R"({"material": "red_plastic"})"), "t.json: error: /tiers: missing: the tuned tiers");
  // Figures in the budgets' ranges: a cost of 1e306 would be written back as null.
  EXPECT_EQ(bad(R"({"material": "red_plastic", "tiers": {"high": {"cost": 1e306}}})"),
            "t.json: error: /tiers/high/cost: expected a number from 0 to 1e+06");
  EXPECT_EQ(bad(R"({"material": "red_plastic", "vertices_per_pixel": -1, "tiers": {}})"),
            "t.json: error: /vertices_per_pixel: expected a number from 0 to 16");
  EXPECT_EQ(tune::choicesPath("examples/materials/red_plastic.mat"), "examples/materials/red_plastic.tuning.json");
}

// What fuzz_tune_files checks, on its seeds (the budgets file, the committed tuning files) and every
// input it once got wrong (tests/fuzz/tune_regressions/): each file is refused naming it, or read
// within the documented ranges; a tuning file read writes back to the same text once written.
TEST(TuneFiles, FuzzSeedsAndRegressionsReadOrAreRefused) {
  // The committed tuning files, each read against its own material too.
  std::vector<std::string> files = {facet::test::examplePath("lint/tune_budgets.json")};
  std::vector<facet::ir::Material> materials = {example("red_plastic"), example("brushed_gold")};
  for (const std::string& stem : facet::test::exampleTunedMaterials()) {
    files.push_back(facet::test::examplePath("materials/" + stem + ".tuning.json"));
    if (stem != "red_plastic" && stem != "brushed_gold") materials.push_back(example(stem));
  }
  const size_t seeds = files.size();
  ASSERT_GE(seeds, 4u);  // the budgets file, red_plastic's, brushed_gold's and velvet's tuning files
  const std::string regressions = facet::test::sourceDir() + "/tests/fuzz/tune_regressions";
  for (const auto& entry : std::filesystem::directory_iterator(regressions))
    if (entry.path().filename() != "README.md") files.push_back(entry.path().string());
  std::sort(files.begin() + std::ptrdiff_t(seeds), files.end());
  size_t read = 0;
  for (const std::string& path : files) {
    const std::string text = facet::test::readText(path);
    std::string error;
    if (auto b = tune::parseBudgets(path, text, &error)) {
      ++read;
      EXPECT_TRUE(std::isfinite(b->verticesPerPixel) && b->verticesPerPixel >= 0) << path;
      for (const auto& [tier, t] : b->tiers) {
        EXPECT_TRUE(t.minPsnrDb >= 0 && t.minPsnrDb <= 200) << path;
        EXPECT_TRUE(!t.maxCost || (std::isfinite(*t.maxCost) && *t.maxCost >= 0)) << path;
      }
    } else {
      EXPECT_EQ(error.rfind(path + ":", 0), 0u) << error;
    }
    for (const facet::ir::Material& m : materials) {
      if (auto c = tune::parseChoices(path, text, m, &error)) {
        ++read;
        const std::string written = tune::writeChoices(*c);
        auto again = tune::parseChoices("written.json", written, m, &error);
        ASSERT_TRUE(again) << path << ": " << error << "\n" << written;
        EXPECT_EQ(tune::writeChoices(*again), written) << path;
      } else {
        EXPECT_EQ(error.rfind(path + ":", 0), 0u) << error;
      }
    }
  }
  EXPECT_GE(read, seeds);  // the budgets file and each committed tuning file against its material
}

TEST(TuneSearch, CandidatesAreEveryCombinationOnceWithTheTiersAsShippedAmongThem) {
  const facet::ir::Material m = example("red_plastic");
  const std::vector<TierConfig> all = tune::candidates(m);
  // specular 5 × (diffuse pixel or vertex × SH bands 3 (2, 3, 5), and the irradiance cube, which
  // has no bands) 7 × (split-sum with and without compensation, analytic, two-mip) 4 × colour space
  // 2 × precision 2 × dominant direction 2: no clear coat, anisotropy or ambient occlusion in
  // red_plastic.
  EXPECT_EQ(all.size(), 5u * (2 * 3 + 1) * 4 * 2 * 2 * 2);
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j) ASSERT_FALSE(all[i] == all[j]) << i << " " << j;
  for (const facet::eval::Configuration& c : facet::eval::configurations(m, {Tier::High, Tier::Mid, Tier::Low}, false))
    EXPECT_NE(std::find(all.begin(), all.end(), tune::withAxesOf(m, all[0], c.config)), all.end()) << c.name;
  EXPECT_EQ(tune::candidates(example("car_paint")).size() % all.size(), 0u);  // its clear coat multiplies
  EXPECT_GT(tune::candidates(example("car_paint")).size(), all.size());
}

TEST(TuneSearch, TargetGpuIsACycleCalibration) {
  std::string error;
  EXPECT_TRUE(tune::targetGpu("mali-g57", &error));
  EXPECT_TRUE(tune::targetGpu("mali-g52", &error));
  EXPECT_FALSE(tune::targetGpu("adreno-630", &error));
  EXPECT_NE(error.find("not cycles"), std::string::npos) << error;
  EXPECT_FALSE(tune::targetGpu("mali-t880", &error));
  EXPECT_NE(error.find("not a calibrated GPU"), std::string::npos) << error;
}

// The cheapest that meets each budget, the same with one and two threads; a raised budget gives a
// configuration at least as accurate, strictly more where the old one fails it; a budget none
// meets names the tier, the best reached and its cost.
TEST(TuneSearch, DeterministicAndARaisedBudgetIsMetByAMoreAccurateConfiguration) {
  const facet::ir::Material m = example("red_plastic");
  tune::TuneOptions o = midAndLowSearch(m);
  o.jobs = 1;
  facet::eval::EvalError error;
  auto one = tune::tune(m, o, &error);
  ASSERT_TRUE(one) << error.message;
  o.jobs = 2;
  auto two = tune::tune(m, o, &error);
  ASSERT_TRUE(two) << error.message;
  ASSERT_EQ(one->tiers.size(), 2u);
  for (size_t t = 0; t < 2; ++t) {
    ASSERT_TRUE(one->tiers[t].chosen) << one->tiers[t].failure;
    ASSERT_TRUE(two->tiers[t].chosen);
    EXPECT_TRUE(one->tiers[t].chosen->result.configuration.config == two->tiers[t].chosen->result.configuration.config);
    EXPECT_EQ(one->tiers[t].chosen->cost.total, two->tiers[t].chosen->cost.total);
    EXPECT_EQ(one->tiers[t].chosen->result.error.psnr, two->tiers[t].chosen->result.error.psnr);
  }
  EXPECT_EQ(tune::markdownReport(*one), tune::markdownReport(*two));
  EXPECT_EQ(tune::jsonReport(*one), tune::jsonReport(*two));
  EXPECT_EQ(tune::plotSvg(*one), tune::plotSvg(*two));
  // Nothing rendered and cheaper meets the budget: the choice is the cheapest that does.
  for (const tune::TierOutcome& t : one->tiers)
    for (const tune::Scored& s : one->front)
      if (s.cost.total < t.chosen->cost.total) {
        EXPECT_FALSE(tune::meets(s, t.budget, one->referenceFurnaceGain)) << s.result.configuration.name;
      }
  EXPECT_LT(one->rendered, o.space.size());  // the pruning rendered fewer than the space holds

  const tune::Scored before = *one->tiers[1].chosen;  // low at 28 dB
  o.budgets.tiers[Tier::Low].minPsnrDb = before.result.error.psnr + 0.5;
  auto raised = tune::tune(m, o, &error);
  ASSERT_TRUE(raised) << error.message;
  ASSERT_TRUE(raised->tiers[1].chosen) << raised->tiers[1].failure;
  EXPECT_GT(raised->tiers[1].chosen->result.error.psnr, before.result.error.psnr);
  EXPECT_GE(raised->tiers[1].chosen->cost.total, before.cost.total);

  o.budgets.tiers[Tier::Low].minPsnrDb = 150;
  auto none = tune::tune(m, o, &error);
  ASSERT_TRUE(none) << error.message;
  ASSERT_FALSE(none->tiers[1].chosen);
  ASSERT_TRUE(none->tiers[1].best);
  EXPECT_NE(none->tiers[1].failure.find("tier low: no configuration meets its budget (PSNR ≥ 150.0 dB"),
            std::string::npos)
      << none->tiers[1].failure;
  EXPECT_NE(none->tiers[1].failure.find("the best reached is"), std::string::npos);
  EXPECT_FALSE(tune::choicesOf(*none));  // nothing partial to --write
}

// A tier takes only what fits its lint budgets. With mid's fragment texture reads capped below
// what the unconstrained choice (the lut lobe's table read) makes, mid moves to a configuration
// within the cap while low, which the cap does not bind, keeps that choice; every cheaper rendered
// candidate that meets mid's error budget is over the cap, and the reports say so.
TEST(TuneSearch, AChoiceFitsItsTiersLintBudgets) {
  const facet::ir::Material m = example("red_plastic");
  tune::TuneOptions o = midAndLowSearch(m);
  facet::eval::EvalError error;
  auto free = tune::tune(m, o, &error);
  ASSERT_TRUE(free) << error.message;
  ASSERT_TRUE(free->tiers[0].chosen) << free->tiers[0].failure;
  ASSERT_TRUE(free->tiers[1].chosen) << free->tiers[1].failure;
  EXPECT_FALSE(free->lintBudgets);
  auto texturesOf = [](const tune::Scored& s) {
    facet::lint::StageFigures fragment;
    fragment.mobile = s.result.costFragment;
    for (const auto& [name, value] : facet::lint::namedFigures(fragment))
      if (name == "textures") return value;
    return -1.0;
  };
  const double freeTextures = texturesOf(*free->tiers[0].chosen);
  ASSERT_GT(freeTextures, 1);

  facet::lint::Budgets lintBudgets;
  lintBudgets.tiers["mid"]["fragment"].max["textures"] = freeTextures - 1;
  o.lintBudgets = lintBudgets;
  auto capped = tune::tune(m, o, &error);
  ASSERT_TRUE(capped) << error.message;
  EXPECT_TRUE(capped->lintBudgets);
  ASSERT_TRUE(capped->tiers[0].chosen) << capped->tiers[0].failure;
  ASSERT_TRUE(capped->tiers[1].chosen) << capped->tiers[1].failure;
  const tune::Scored& mid = *capped->tiers[0].chosen;
  EXPECT_FALSE(mid.result.configuration.config == free->tiers[0].chosen->result.configuration.config);
  EXPECT_LE(texturesOf(mid), freeTextures - 1);
  EXPECT_EQ(mid.lintBreaches.count(Tier::Mid), 0u);
  EXPECT_TRUE(capped->tiers[1].chosen->result.configuration.config ==
              free->tiers[1].chosen->result.configuration.config);
  bool sawBreach = false;
  for (const tune::Scored& s : capped->front) {
    if (!(s.cost.total < mid.cost.total) || s.result.psnrAtMost ||
        !tune::meets(s, capped->tiers[0].budget, capped->referenceFurnaceGain))
      continue;
    ASSERT_EQ(s.lintBreaches.count(Tier::Mid), 1u) << s.result.configuration.name;
    EXPECT_NE(s.lintBreaches.at(Tier::Mid)[0].find("mid.dir1 fragment stage: textures"), std::string::npos)
        << s.lintBreaches.at(Tier::Mid)[0];
    sawBreach = true;
  }
  EXPECT_TRUE(sawBreach);  // low's choice, mid's unconstrained one, is among them
  const std::string md = tune::markdownReport(*capped);
  EXPECT_NE(md.find("(over lint's mid budget: mid.dir1 fragment stage: textures "), std::string::npos) << md;
  EXPECT_NE(tune::jsonReport(*capped).find("\"lint_breaches\""), std::string::npos);

  // A cap nothing fits: no choice for mid, and the diagnostic says why; low is not bound by it.
  lintBudgets.tiers["mid"]["fragment"].max["textures"] = 0;
  o.lintBudgets = lintBudgets;
  auto none = tune::tune(m, o, &error);
  ASSERT_TRUE(none) << error.message;
  EXPECT_FALSE(none->tiers[0].chosen);
  EXPECT_NE(none->tiers[0].failure.find("none is within its cost cap and lint's budgets"), std::string::npos)
      << none->tiers[0].failure;
  EXPECT_TRUE(none->tiers[1].chosen);
  // Once low has its choice, mid may take nothing: the rest are costed, not rendered, and counted.
  EXPECT_GT(none->overLintBudgets, 0u);
  EXPECT_EQ(free->overLintBudgets, 0u);
  EXPECT_NE(tune::markdownReport(*none).find(std::to_string(none->overLintBudgets) + " candidates were not rendered"),
            std::string::npos);
}

// Screening (a candidate's second view and furnace rendered only where its first view's error
// leaves it able to meet an open budget) changes no choice, no best reached by a tier that finds
// none, and no figure of a fully measured candidate; it stops some candidates after one view.
TEST(TuneSearch, ScreeningOnTheFirstViewChangesNoChoiceAndNoBestReached) {
  const facet::ir::Material m = example("red_plastic");
  tune::TuneOptions o = tinyGrid();
  o.space = smallSpace(m);
  o.tiers = {Tier::High, Tier::Mid, Tier::Low};
  o.budgets.tiers[Tier::High].minPsnrDb = 150;  // none meets it: its best reached is reported
  o.budgets.tiers[Tier::Mid].minPsnrDb = 40;
  o.budgets.tiers[Tier::Low].minPsnrDb = 34;
  facet::eval::EvalError error;
  auto screened = tune::tune(m, o, &error);
  ASSERT_TRUE(screened) << error.message;
  o.screen = false;
  auto full = tune::tune(m, o, &error);
  ASSERT_TRUE(full) << error.message;
  EXPECT_GT(screened->screened, 0u);
  EXPECT_EQ(full->screened, 0u);
  EXPECT_EQ(screened->rendered, full->rendered);
  ASSERT_EQ(screened->tiers.size(), full->tiers.size());
  for (size_t t = 0; t < full->tiers.size(); ++t) {
    const tune::TierOutcome &a = screened->tiers[t], &b = full->tiers[t];
    ASSERT_EQ(bool(a.chosen), bool(b.chosen)) << t;
    ASSERT_EQ(bool(a.best), bool(b.best)) << t;
    EXPECT_EQ(a.failure, b.failure);
    for (auto [x, y] : {std::pair{&a.chosen, &b.chosen}, std::pair{&a.best, &b.best}})
      if (*x) {
        EXPECT_TRUE((*x)->result.configuration.config == (*y)->result.configuration.config) << t;
        EXPECT_EQ((*x)->result.error.psnr, (*y)->result.error.psnr) << t;
        EXPECT_EQ((*x)->cost.total, (*y)->cost.total) << t;
      }
  }
  EXPECT_FALSE(screened->tiers[0].chosen);
  ASSERT_EQ(screened->front.size(), full->front.size());
  for (size_t k = 0; k < full->front.size(); ++k) {
    const tune::Scored &a = screened->front[k], &b = full->front[k];
    EXPECT_EQ(a.result.configuration.name, b.result.configuration.name);
    if (a.result.psnrAtMost) {
      EXPECT_LE(b.result.error.psnr, *a.result.psnrAtMost) << b.result.configuration.name;  // a bound
      EXPECT_LT(*a.result.psnrAtMost, 150.0) << a.result.configuration.name;                // below high's, never met
      EXPECT_LT(*a.result.psnrAtMost, screened->tiers[0].best->result.error.psnr);          // and high's best
    } else {
      EXPECT_EQ(a.result.error.psnr, b.result.error.psnr) << a.result.configuration.name;
    }
  }

  // The plot: well-formed SVG; each tier as shipped (a square) and as tuned, or its best reached
  // (a diamond), labelled; each budget a dashed line; the screened candidates hollow.
  const SvgContents svg = readSvg(tune::plotSvg(*screened));
  ASSERT_TRUE(svg.wellFormed);
  EXPECT_EQ(svg.root, "svg");
  EXPECT_EQ(svg.elements.at("rect"), 1 + 3);  // the background, then one square per tier
  EXPECT_EQ(svg.elements.at("polygon"), 3);
  auto has = [&](const std::string& text) { return std::count(svg.texts.begin(), svg.texts.end(), text) == 1; };
  for (const char* label : {"high as shipped", "high best reached, misses its budget", "mid as shipped", "mid tuned",
                            "low as shipped", "low tuned", "high ≥ 150.0 dB", "mid ≥ 40.0 dB", "low ≥ 34.0 dB"})
    EXPECT_TRUE(has(label)) << label;
  const std::string text = tune::plotSvg(*screened);
  EXPECT_NE(text.find("fill=\"white\" stroke="), std::string::npos);  // a screened candidate, hollow
  EXPECT_NE(text.find("<polyline"), std::string::npos);               // the front
}

// A candidate whose views' build is byte for byte an earlier one's takes that render's figures:
// on velvet (cloth) without its sheen, the ambient forms, which then have no specular ambient to
// shape, build the same shaders. Every figure of the reports, and so every choice and best
// reached, is the one rendering each candidate gives.
TEST(TuneSearch, ReusingTheRenderOfAnIdenticalBuildChangesNoChoiceAndNoFigure) {
  const facet::ir::Material m = example("velvet");
  tune::TuneOptions o = tinyGrid();
  o.eval.cacheDir = facet::test::scratchDir("tune-reuse") + "/cache";
  auto axis = [](const std::string& name) {
    for (const facet::eval::Axis& a : facet::eval::axes())
      if (a.name == name) return &a;
    return static_cast<const facet::eval::Axis*>(nullptr);
  };
  const facet::eval::Axis* ambient = axis("ambient");
  const facet::eval::Axis* sheen = axis("sheen");
  ASSERT_TRUE(ambient && sheen);
  for (const facet::eval::Configuration& c : facet::eval::configurations(m, {Tier::Mid, Tier::Low}, false))
    if (c.tier != Tier::Reference)
      for (const std::string& s : sheen->options)
        for (const std::string& a : ambient->options) {
          TierConfig t = c.config;
          sheen->set(&t, s);
          ambient->set(&t, a);
          if (std::find(o.space.begin(), o.space.end(), t) == o.space.end()) o.space.push_back(t);
        }
  o.budgets.tiers[Tier::High].minPsnrDb = 150;  // none meets it: every candidate is rendered
  o.budgets.tiers[Tier::Mid].minPsnrDb = 40;
  o.budgets.tiers[Tier::Low].minPsnrDb = 30;
  facet::eval::EvalError error;
  auto reused = tune::tune(m, o, &error);
  ASSERT_TRUE(reused) << error.message;
  o.reuseIdenticalViews = false;
  auto rendered = tune::tune(m, o, &error);
  ASSERT_TRUE(rendered) << error.message;
  EXPECT_GT(reused->reused, 0u);
  EXPECT_EQ(rendered->reused, 0u);
  EXPECT_EQ(tune::markdownReport(*reused), tune::markdownReport(*rendered));
  EXPECT_EQ(tune::jsonReport(*reused), tune::jsonReport(*rendered));
  EXPECT_EQ(tune::plotSvg(*reused), tune::plotSvg(*rendered));
  ASSERT_EQ(reused->tiers.size(), rendered->tiers.size());
  for (size_t t = 0; t < reused->tiers.size(); ++t) {
    ASSERT_EQ(bool(reused->tiers[t].chosen), bool(rendered->tiers[t].chosen)) << t;
    if (reused->tiers[t].chosen) {
      EXPECT_TRUE(reused->tiers[t].chosen->result.configuration.config ==
                  rendered->tiers[t].chosen->result.configuration.config)
          << t;
    }
  }
  EXPECT_FALSE(reused->tiers[0].chosen);
}

// The gate: committed choices re-scored; a worse configuration in their place fails with figures.
TEST(TuneGate, CommittedChoicesPassAndAWorseOneFailsWithItsFigures) {
  const facet::ir::Material m = example("red_plastic");
  tune::TuneOptions o = tinyGrid();
  const TierConfig high = facet::eval::configurations(m, {Tier::High}, false).at(1).config;
  TierConfig worse = high;
  worse.specular = facet::permutations::SpecularModel::Lut;
  facet::eval::EvalError error;
  auto report = tune::rescore(m, {{Tier::High, high}, {Tier::Low, worse}}, o, &error);
  ASSERT_TRUE(report) << error.message;
  ASSERT_EQ(report->tiers.size(), 2u);
  EXPECT_TRUE(report->tiers[0].chosen) << report->tiers[0].failure;
  // The lut lobe in place of high's GGX: far below high's 50 dB, fine for low's 34 dB.
  EXPECT_TRUE(report->tiers[1].chosen) << report->tiers[1].failure;
  auto failing = tune::rescore(m, {{Tier::High, worse}}, o, &error);
  ASSERT_TRUE(failing) << error.message;
  ASSERT_FALSE(failing->tiers[0].chosen);
  EXPECT_NE(
      failing->tiers[0].failure.find("tier high: the tuned configuration no longer meets its budget (PSNR ≥ 50.0 dB"),
      std::string::npos)
      << failing->tiers[0].failure;
  EXPECT_NE(failing->tiers[0].failure.find(" dB, furnace "), std::string::npos);

  // Within its error budget but over the lint budget the choice was held to: the gate fails too.
  facet::lint::Budgets lintBudgets;
  lintBudgets.tiers["low"]["fragment"].max["textures"] = 1;
  o.lintBudgets = lintBudgets;
  auto overLint = tune::rescore(m, {{Tier::Low, worse}}, o, &error);
  ASSERT_TRUE(overLint) << error.message;
  ASSERT_FALSE(overLint->tiers[0].chosen);
  EXPECT_NE(overLint->tiers[0].failure.find("tier low: the tuned configuration no longer fits its lint budget: "
                                            "material 'red_plastic' variant low.dir1 fragment stage: textures "),
            std::string::npos)
      << overLint->tiers[0].failure;
}
