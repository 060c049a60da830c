// matc eval (facet-eval): wiring only; the evaluation lives in facet_eval (eval/src), docs/eval.md.
#include "eval_command.h"

#include <cstdio>
#include <filesystem>

#include "facet/cli/inputs.h"
#include "facet/cli/outputs.h"
#include "facet/eval/evaluate.h"
#include "facet/eval/report.h"
#include "facet/gpu_stats/report.h"
#include "facet/scene/scene.h"
#include "facet/tune/choices.h"

namespace facet::eval {

namespace {

namespace fs = std::filesystem;

// The files a scene makes the evaluation read: the scene, its images, glTF meshes and grading LUT.
// A scene that does not load names none here; evaluate() reports why.
std::vector<cli::NamedFile> sceneInputs(const std::string& path) {
  if (path.empty()) return {};
  std::vector<cli::NamedFile> files{{"the --scene file", path}};
  std::string ignored;
  std::optional<runtime::Scene> scene = runtime::loadScene(path, &ignored);
  if (!scene) return files;
  const std::string named = "a file of the --scene file";
  for (const runtime::SceneObject& o : scene->objects) {
    if (fs::path(o.mesh).has_extension()) files.push_back({named, o.mesh});
    for (const auto& [param, image] : o.textures) files.push_back({named, image});
  }
  if (scene->environment && !scene->environment->image.empty()) files.push_back({named, scene->environment->image});
  if (!scene->gradingLut.empty()) files.push_back({named, scene->gradingLut});
  return files;
}

}  // namespace

int evalCommand(const EvalArgs& args) {
  eval::EvalOptions options;
  if (int status = cli::parseTiers(args.tiers, &options.tiers); status != 0) return status;
  std::vector<std::string> gpus;
  if (!args.gpu.empty()) {
    std::string message;
    if (!gpu_stats::parseGpuList(args.gpu, &gpus, &message)) {
      cli::printError("--gpu: " + message);
      return 2;
    }
  }
  const std::string outDir = args.out.empty() ? fs::path(args.input).stem().string() + ".eval" : args.out;
  std::vector<cli::NamedFile> inputs = sceneInputs(args.scene);
  inputs.insert(inputs.begin(), {"the input material", args.input});
  // The report's own names are known now, the images' only after the run: both are checked, the
  // first before the run.
  std::vector<cli::NamedFile> outputs;
  for (const char* name : {"report.md", "report.json", "plot.svg"})
    outputs.push_back({"--out", (fs::path(outDir) / name).string()});
  if (!cli::outputsSpareInputs(inputs, outputs)) return 1;
  ir::SourceFile source;
  std::optional<ir::Material> material = cli::loadMaterial(args.input, &source);
  if (!material) return 1;
  // The tiers as shipped are those `matc compile` builds: its tuning file's when it has one.
  std::optional<tune::ShippedTuning> tuning =
      tune::shippedTuningForCommand(args.input, args.tuning, args.noTuning, *material, &options.tunedTiers);
  if (!tuning) return 1;
  options.tuningFile = tuning->path;
  // The folders first, so an --out that cannot be written fails before the run, not after it.
  const std::string imageDir = (fs::path(outDir) / "images").string();
  if (!cli::writeOutputs({imageDir}, {})) return 1;

  options.swaps = !args.noSwaps;
  options.sceneFile = args.scene;
  options.timingFrames = args.frames;
  options.grid.pixelsPerSphere = uint32_t(args.spherePixels);
  options.validation = args.validation;
  options.fp16Emulation = args.fp16Emulation;
  options.shadows = args.shadows;
  options.groundTruthSamples = args.groundTruth;
  options.progress = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  eval::EvalError error;
  std::optional<eval::EvalReport> report = eval::evaluate(*material, options, &error);
  if (!report) {
    cli::printBuildError(source, error.message, error.loc);
    return 1;
  }
  if (!gpus.empty()) {
    gpu_stats::MesaTool tool;
    tool.prefix = args.mesaPrefix;
    eval::addGpuFigures(&*report, gpus, tool);
    std::printf("%s\n", gpu_stats::sourceNote(report->gpuStats).c_str());
  }
  const std::vector<package::OutputFile> files = eval::reportFiles(*report, outDir);
  outputs.clear();
  for (const package::OutputFile& f : files) outputs.push_back({"--out", f.path});
  if (!cli::outputsSpareInputs(inputs, outputs) || !cli::writeOutputs({imageDir}, files)) return 1;
  std::printf("%s: %zu configurations -> %s/report.md, report.json, plot.svg, images/\n", material->name.c_str(),
              report->results.size(), outDir.c_str());
  return 0;
}

}  // namespace facet::eval
