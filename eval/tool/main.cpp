// facet-eval: `matc eval` (docs/eval.md) as a program of its own, so that matc links no renderer.
// matc runs it (matc/run_helper_program.cpp) as "<matc> eval": its usage and its messages then read as
// matc's, and `matc eval`'s options and exit codes are these.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "eval_command.h"
#include "facet/cli/command_line.h"
#include "facet/cli/inputs.h"
#include "facet/package/atomic_file.h"

int main(int argc, char** argv) {
  // Ctrl-C during the report's write leaves no temporary file behind.
  facet::removeTemporaryFilesOnSignals();
  // Run by matc as "<matc> eval", it speaks as matc ("matc: error: ..."); run on its own, as itself.
  facet::cli::setProgramName(std::string_view(argv[0]).ends_with(" eval") ? "matc" : "facet-eval");
  CLI::App app{
      "render every tier and single-option swap on lavapipe; report error against reference and cost (docs/eval.md)"};
  facet::eval::EvalArgs eval;
  app.add_option("input", eval.input, "material source (.mat)")->required();
  app.add_option("--scene", eval.scene, "scene JSON to render instead of the built-in evaluation grid");
  app.add_option("--out", eval.out,
                 "folder for report.md, report.json, plot.svg and images/ (default: <input stem>.eval)");
  app.add_option("--tiers", eval.tiers, "tiers to measure, with their swaps (reference is always measured)")
      ->delimiter(',');
  app.add_option("--frames", eval.frames, "timed frames per view on lavapipe (median; 0: no timing)")
      ->check(CLI::Range(0, 1000));
  app.add_option("--sphere-pixels", eval.spherePixels, "grid: pixels per sphere (default 64)")
      ->check(CLI::Range(8, 512));
  app.add_option("--gpu", eval.gpu,
                 "also report Mesa's figures for these GPUs: mali-g52, mali-g57, adreno-630 (docs/mesa-statistics.md)");
  app.add_option("--mesa-prefix", eval.mesaPrefix,
                 "the Mesa build for --gpu (default: $MESA_PREFIX, else ~/.cache/facet/mesa/install)");
  app.add_flag("--no-swaps", eval.noSwaps, "measure the tiers as shipped only, not their single-option swaps");
  app.add_flag("--validation", eval.validation, "enable Vulkan validation layers; any validation error fails the run");
  app.add_flag("--fp16-emulation", eval.fp16Emulation,
               "build mediump SPIR-V with every result rounded to binary16 (docs/fp16-emulation.md)");
  app.add_flag("--shadows", eval.shadows,
               "grid: also the \"shadowed\" view, the sun casting onto a wall behind the spheres (docs/eval.md)");
  app.add_option("--ground-truth", eval.groundTruth,
                 "also measure every configuration against reference with its environment integrated by "
                 "importance sampling, N points per integral and pixel (docs/eval.md)")
      ->check(CLI::Range(4, 65536));
  if (std::optional<int> exit = facet::cli::parseCommandLine(app, argc, argv)) return *exit;
  return facet::eval::evalCommand(eval);
}
