// matc lint: wiring of facet_lint (docs/lint.md). Reads the inputs, lints each material, prints
// the report, and maintains the baseline file.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "facet/cli/inputs.h"
#include "facet/cli/outputs.h"
#include "facet/compiler/build.h"
#include "facet/gpu_stats/mesa_compile.h"
#include "facet/ir/check.h"
#include "facet/lint/report.h"
#include "facet/package/package.h"
#include "facet/tune/choices.h"

namespace facet::matc {
namespace {

namespace fs = std::filesystem;

// A folder stands for every .mat file in it (not recursive), sorted so output is stable.
bool expandInputs(const std::vector<std::string>& inputs, std::vector<std::string>* files) {
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (!fs::is_directory(input, ec)) {
      files->push_back(input);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(input, ec))
      if (entry.path().extension() == ".mat" && entry.is_regular_file(ec)) found.push_back(entry.path().string());
    if (ec) {
      cli::printError("cannot list '" + input + "': " + ec.message());
      return false;
    }
    if (found.empty()) {
      cli::printError("'" + input + "' holds no .mat files");
      return false;
    }
    std::sort(found.begin(), found.end());
    files->insert(files->end(), found.begin(), found.end());
  }
  return true;
}

std::vector<uint8_t> bytesOf(const std::string& text) { return {text.begin(), text.end()}; }

bool readJsonFile(const std::string& path, std::string* text) {
  ir::SourceFile file;  // the same size and regular-file checks as materials
  if (!cli::readSource(path, &file)) return false;
  *text = std::move(file.text);
  return true;
}

}  // namespace

int lintCommand(const LintArgs& args) {
  lint::LintOptions options;
  if (int status = cli::parseTiers(args.tiers, &options.tiers); status != 0) return status;
  options.pointLightCounts = args.pointLights;
  options.shadowCascadeCounts = args.shadows;
  options.spotShadows = args.spotShadows;
  options.baselineTolerance = args.tolerancePercent / 100.0;
  if (!args.gpu.empty()) {
    std::string error;
    if (!gpu_stats::parseGpuList(args.gpu, &options.gpus, &error)) {
      cli::printError("--gpu: " + error);
      return 2;
    }
    options.mesaTool.prefix = args.mesaPrefix;
  }
  if (args.updateBaseline && args.baseline.empty()) {
    cli::printError("--update-baseline needs --baseline FILE: the file to write");
    return 2;
  }

  std::vector<std::string> files;
  if (!expandInputs(args.inputs, &files)) return 1;
  std::vector<cli::NamedFile> inputs, outputs;
  for (const std::string& path : files) inputs.push_back({"the input material", path});
  if (!args.config.empty()) inputs.push_back({"the --config file", args.config});
  if (!args.output.empty()) outputs.push_back({"-o", args.output});
  // --update-baseline reads the baseline and writes it again: then it is an output, and only that.
  if (args.updateBaseline)
    outputs.push_back({"--baseline with --update-baseline", args.baseline});
  else if (!args.baseline.empty())
    inputs.push_back({"the --baseline file", args.baseline});
  if (!cli::outputsSpareInputs(inputs, outputs)) return 1;

  std::optional<lint::Budgets> budgets;
  if (!args.config.empty()) {
    std::string text, error;
    if (!readJsonFile(args.config, &text)) return 1;
    budgets = lint::parseBudgets(args.config, text, &error);
    if (!budgets) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    options.budgets = &*budgets;
  }
  std::optional<lint::Baseline> baseline;
  if (!args.baseline.empty() && fs::exists(args.baseline)) {
    std::string text, error;
    if (!readJsonFile(args.baseline, &text)) return 1;
    baseline = lint::parseBaseline(args.baseline, text, &error);
    if (!baseline) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
  } else if (!args.baseline.empty() && !args.updateBaseline) {
    cli::printError("baseline '" + args.baseline + "' does not exist; create it with --update-baseline");
    return 1;
  }
  // While rewriting the baseline, its old figures are not held against the new ones.
  if (baseline && !args.updateBaseline) options.baseline = &*baseline;

  std::vector<lint::LintedFile> linted;
  for (const std::string& path : files) {
    lint::LintedFile f;
    if (!cli::readSource(path, &f.file)) return 1;
    // The tiers `matc compile` ships: the material's tuning file's when it has one (lintMaterial
    // reports a material that does not compile).
    lint::LintOptions shipped = options;
    ir::Diagnostics quiet(f.file);
    if (std::optional<ir::Material> material = ir::compileSource(f.file, quiet)) {
      if (!tune::shippedTuningForCommand(path, "", args.noTuning, *material, &shipped.tunedTiers)) return 1;
    }
    f.result = lint::lintMaterial(f.file, shipped);
    linted.push_back(std::move(f));
  }

  std::string report = args.format == "json"    ? lint::formatJson(linted)
                       : args.format == "sarif" ? lint::formatSarif(linted, compiler::compilerVersion())
                                                : lint::formatText(linted);
  // The report and the baseline land together: neither is written when the other cannot be.
  std::vector<package::OutputFile> written;
  if (args.output.empty())
    std::fputs(report.c_str(), stdout);
  else
    written.push_back({args.output, bytesOf(report)});
  if (args.updateBaseline) {
    lint::Baseline updated = baseline.value_or(lint::Baseline{});
    for (const lint::LintedFile& f : linted) {
      if (f.result.material.empty() || f.result.variants.empty()) continue;
      auto& variants = updated.materials[f.result.material];
      variants.clear();
      for (const lint::VariantFigures& v : f.result.variants)
        for (auto [stage, figures] : {std::pair{"vertex", &v.vertex}, {"fragment", &v.fragment}})
          for (const auto& [name, value] : lint::namedFigures(*figures)) variants[v.key][stage][name] = value;
    }
    written.push_back({args.baseline, bytesOf(lint::writeBaseline(updated))});
  }
  if (!cli::writeOutputs({}, written)) return 1;
  if (args.updateBaseline) std::fprintf(stderr, "matc lint: wrote baseline %s\n", args.baseline.c_str());

  bool failed = false;
  for (const lint::LintedFile& f : linted)
    for (const ir::Diagnostic& d : f.result.diagnostics)
      failed = failed || d.severity == ir::Severity::Error || args.werror;
  return failed ? 1 : 0;
}

}  // namespace facet::matc
