// facet-tune: `matc tune` (docs/tune.md) as a program of its own, so that matc links no renderer.
// matc runs it (matc/run_helper_program.cpp) as "<matc> tune": its usage and messages then read as
// matc's, and `matc tune`'s options and exit codes are these.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include "facet/cli/command_line.h"
#include "facet/cli/inputs.h"
#include "facet/cli/outputs.h"
#include "facet/package/atomic_file.h"
#include "facet/tune/choices.h"
#include "facet/tune/report.h"

namespace {

namespace fs = std::filesystem;
using namespace facet;

struct TuneArgs {
  std::string input;
  std::string budgets;  // JSON over the default budgets
  std::string gpu = "mali-g57";
  std::string out;  // default: <input stem>.tune
  bool write = false;
  bool check = false;
  int spherePixels = 64;
  unsigned jobs = 0;
  std::string maxChanges = "2";
  std::string cache;  // variant cache for the candidates' builds ("": matc compile's default)
  bool noCache = false;
};

// matc compile's default cache (matc/compile_command.cpp): $XDG_CACHE_HOME/facet/matc, else
// $HOME/.cache/facet/matc, else none. The entries are content-addressed: tune and compile share them.
std::string defaultCacheDir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/facet/matc";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/facet/matc";
  return "";
}

// A message that names its file ("<file>: error: ..."), printed as a compiler prints it.
void printLocated(const std::string& message) { std::fprintf(stderr, "%s\n", message.c_str()); }

std::optional<std::string> readText(const std::string& what, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad()) {
    printLocated(path + ": error: cannot read " + what);
    return std::nullopt;
  }
  return text.str();
}

void progress(const std::string& line) {
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

// Prints the tiers' lines; the failures as errors naming the material file. 1 if any tier failed.
int finish(const tune::TuneReport& report, const std::string& input) {
  int status = 0;
  const std::vector<std::string> lines = tune::summaryLines(report);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (report.tiers[i].chosen) {
      progress(lines[i]);
    } else {
      printLocated(input + ": error: " + lines[i]);
      status = 1;
    }
  }
  return status;
}

int check(const TuneArgs& args, const ir::Material& material, tune::TuneOptions options) {
  const std::string path = tune::choicesPath(args.input);
  std::optional<std::string> text = readText("the tuning file (written by matc tune --write)", path);
  if (!text) return 1;
  std::string message;
  std::optional<tune::Choices> choices = tune::parseChoices(path, *text, material, &message);
  if (!choices) {
    printLocated(message);
    return 1;
  }
  // The cost the choices were made on: the file's GPU and vertex weight.
  options.gpu = choices->gpu;
  options.budgets.verticesPerPixel = choices->verticesPerPixel;
  std::vector<std::pair<permutations::Tier, permutations::TierConfig>> tiers;
  for (const tune::TierChoice& c : choices->tiers) tiers.emplace_back(c.tier, c.config);
  eval::EvalError error;
  std::optional<tune::TuneReport> report = tune::rescore(material, tiers, options, &error);
  if (!report) {
    cli::printError(args.input + ": " + error.message);
    return 1;
  }
  return finish(*report, path);
}

int run(const TuneArgs& args) {
  tune::TuneOptions options;
  options.gpu = args.gpu;
  options.jobs = args.jobs;
  options.maxChanges = args.maxChanges == "all" ? -1 : std::stoi(args.maxChanges);
  options.eval.grid.pixelsPerSphere = uint32_t(args.spherePixels);
  options.eval.cacheDir = args.noCache ? "" : args.cache.empty() ? defaultCacheDir() : args.cache;
  options.progress = progress;
  std::string message;
  if (!tune::targetGpu(args.gpu, &message)) {
    cli::printError(message);
    return 2;
  }
  if (!args.budgets.empty()) {
    std::optional<std::string> text = readText("the --budgets file", args.budgets);
    if (!text) return 1;
    std::optional<tune::Budgets> budgets = tune::parseBudgets(args.budgets, *text, &message);
    if (!budgets) {
      printLocated(message);
      return 1;
    }
    options.budgets = *budgets;
    if (!budgets->lintBudgetsPath.empty()) {
      std::optional<std::string> lintText =
          readText("the lint budgets file (lint_budgets in " + args.budgets + ")", budgets->lintBudgetsPath);
      if (!lintText) return 1;
      options.lintBudgets = lint::parseBudgets(budgets->lintBudgetsPath, *lintText, &message);
      if (!options.lintBudgets) {
        printLocated(message);
        return 1;
      }
    }
  }
  ir::SourceFile source;
  std::optional<ir::Material> material = cli::loadMaterial(args.input, &source);
  if (!material) return 1;
  if (args.check) return check(args, *material, options);

  const std::string outDir = args.out.empty() ? fs::path(args.input).stem().string() + ".tune" : args.out;
  std::vector<cli::NamedFile> inputs{{"the input material", args.input}};
  if (!args.budgets.empty()) inputs.push_back({"the --budgets file", args.budgets});
  if (!options.budgets.lintBudgetsPath.empty())
    inputs.push_back({"the lint budgets file", options.budgets.lintBudgetsPath});
  std::vector<cli::NamedFile> outputs{{"--out", (fs::path(outDir) / "report.md").string()},
                                      {"--out", (fs::path(outDir) / "report.json").string()},
                                      {"--out", (fs::path(outDir) / "plot.svg").string()}};
  if (args.write) outputs.push_back({"--write", tune::choicesPath(args.input)});
  if (!cli::outputsSpareInputs(inputs, outputs)) return 1;

  eval::EvalError error;
  std::optional<tune::TuneReport> report = tune::tune(*material, options, &error);
  if (!report) {
    cli::printBuildError(source, error.message, error.loc);
    return 1;
  }
  if (!cli::writeOutputs({outDir}, tune::reportFiles(*report, outDir))) return 1;
  const int status = finish(*report, args.input);
  std::printf(
      "%s: %zu candidates, %zu rendered (%zu only in the first view, %zu the same build as an earlier one) -> "
      "%s/report.md, report.json, plot.svg\n",
      material->name.c_str(), report->candidates, report->rendered, report->screened, report->reused, outDir.c_str());
  if (status != 0) {
    if (args.write) cli::printError(tune::choicesPath(args.input) + ": not written: a tier has no choice");
    return status;
  }
  if (args.write) {
    const std::string text = tune::writeChoices(*tune::choicesOf(*report));
    const std::string path = tune::choicesPath(args.input);
    if (!cli::writeOutputs({}, {{path, std::vector<uint8_t>(text.begin(), text.end())}})) return 1;
    std::printf("tuned tiers -> %s\n", path.c_str());
  }
  return 0;
}

// Tune renders to measure error, never speed, and a cold run spends most of its time in lavapipe
// compiling pipelines. Under GALLIVM_PERF=nopt Mesa's gallivm skips its LLVM optimisation passes;
// it sets no fast-math flags, so the passes may not change a result, and the test
// MatcCli.TuneScoresTheSameWithoutLavapipesOptimisationPasses holds the figures to that. lavapipe keys
// its disk cache by these flags, so `matc eval`'s timed renders never run the unoptimised code
// (docs/tune.md, "Time"). A value the user set is kept.
void compilePipelinesForLatency() { setenv("GALLIVM_PERF", "nopt", /*overwrite=*/0); }

}  // namespace

int main(int argc, char** argv) {
  compilePipelinesForLatency();
  facet::removeTemporaryFilesOnSignals();
  facet::cli::setProgramName(std::string_view(argv[0]).ends_with(" tune") ? "matc" : "facet-tune");
  CLI::App app{"choose each tier's cheapest configuration that meets its error budget (docs/tune.md)"};
  TuneArgs args;
  app.add_option("input", args.input, "material source (.mat)")->required();
  app.add_option("--budgets", args.budgets,
                 "error budgets per tier and material (JSON; examples/lint/tune_budgets.json)");
  app.add_option("--gpu", args.gpu, "the GPU the cost is taken on: mali-g57 (default) or mali-g52");
  app.add_option("--out", args.out, "folder for report.md, report.json and plot.svg (default: <input stem>.tune)");
  app.add_flag("--write", args.write, "record the chosen tiers in <input stem>.tuning.json beside the material");
  app.add_flag("--check", args.check,
               "re-score the tiers recorded in <input stem>.tuning.json against the budgets; fail with the figures");
  app.add_option("--sphere-pixels", args.spherePixels, "grid: pixels per sphere (default 64)")
      ->check(CLI::Range(8, 512));
  app.add_option("-j,--jobs", args.jobs, "threads costing candidates (default: one per core); the choice is the same")
      ->check(CLI::Range(1, 256));
  app.add_option("--max-changes", args.maxChanges,
                 "search the combinations within this many axes of a tier as shipped, or all (default 2)")
      ->check(CLI::IsMember({"0", "1", "2", "3", "4", "5", "6", "7", "8", "all"}));
  CLI::Option* cache =
      app.add_option("--cache", args.cache, "variant cache for the candidates' builds (default: matc compile's)");
  app.add_flag("--no-cache", args.noCache, "neither read nor write the cache")->excludes(cache);
  app.get_option("--write")->excludes(app.get_option("--check"));
  if (std::optional<int> exit = facet::cli::parseCommandLine(app, argc, argv)) return *exit;
  return run(args);
}
