// facet-eval's command: `matc eval` (docs/eval.md), in the program of its own that links the
// renderer (eval_main.cpp).
#pragma once

#include <string>
#include <vector>

namespace facet::matc {

// What `matc eval` does, as `matc --help` and facet-eval's own help say it.
inline constexpr const char* kEvalSummary =
    "render every tier and single-option swap on lavapipe; report error against reference and cost (docs/eval.md)";

struct EvalArgs {
  std::string input;
  std::string scene;       // scene file instead of the built-in evaluation grid
  std::string out;         // default: <input stem>.eval next to the current folder
  std::vector<std::string> tiers;  // tiers whose configurations are measured; default: all
  int frames = 5;          // timed frames per view (median); 0: no timing
  int spherePixels = 64;   // grid: pixels per sphere (the image is columns × rows of these)
  bool noSwaps = false;    // the tiers as shipped only
  bool validation = false;
  bool fp16Emulation = false;
  std::string gpu;         // as LintArgs::gpu
  std::string mesaPrefix;
};
// 0 with the report written, 1 for input errors, 2 for usage errors.
int evalCommand(const EvalArgs& args);

}  // namespace facet::matc
