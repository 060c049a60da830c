// matc eval: wiring only; the evaluation lives in eval/ (facet_eval), docs/eval.md.
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "facet/eval/evaluate.h"
#include "facet/eval/report.h"
#include "facet/gpu_stats/report.h"
#include "cli_inputs.h"

namespace facet::matc {

int evalCommand(const EvalArgs& args) {
  eval::EvalOptions options;
  if (int status = parseTiers(args.tiers, &options.tiers); status != 0) return status;
  std::vector<std::string> gpus;
  if (!args.gpu.empty()) {
    std::string message;
    if (!gpu_stats::parseGpuList(args.gpu, &gpus, &message)) {
      printError("--gpu: " + message);
      return 2;
    }
  }
  ir::SourceFile source;
  std::optional<ir::Material> material = loadMaterial(args.input, &source);
  if (!material) return 1;

  options.swaps = !args.noSwaps;
  options.sceneFile = args.scene;
  options.outDir = args.out.empty() ? std::filesystem::path(args.input).stem().string() + ".eval" : args.out;
  options.timingFrames = args.frames;
  options.grid.pixelsPerSphere = uint32_t(args.spherePixels);
  options.validation = args.validation;
  options.fp16Emulation = args.fp16Emulation;
  options.progress = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  eval::EvalError error;
  std::optional<eval::EvalReport> report = eval::evaluate(*material, options, &error);
  if (!report) {
    printBuildError(source, error.message, error.loc);
    return 1;
  }
  if (!gpus.empty()) {
    gpu_stats::MesaTool tool;
    tool.prefix = args.mesaPrefix;
    eval::addGpuFigures(&*report, gpus, tool);
    std::printf("%s\n", gpu_stats::sourceNote(report->gpuStats).c_str());
  }
  std::string message;
  if (!eval::writeReport(*report, options.outDir, &message)) {
    printError(message);
    return 1;
  }
  std::printf("%s: %zu configurations -> %s/report.md, report.json, plot.svg, images/\n", material->name.c_str(),
              report->results.size(), options.outDir.c_str());
  return 0;
}

}  // namespace facet::matc
