// facet-eval's command: `matc eval` (docs/eval.md), in a program of its own (main.cpp) because it
// links the renderer, which matc must not.
#pragma once

#include <string>
#include <vector>

namespace facet::eval {

struct EvalArgs {
  std::string input;
  std::string scene;               // scene file instead of the built-in evaluation grid
  std::string out;                 // default: <input stem>.eval next to the current folder
  std::vector<std::string> tiers;  // tiers whose configurations are measured; default: all
  int frames = 5;                  // timed frames per view (median); 0: no timing
  int spherePixels = 64;           // grid: pixels per sphere (the image is columns × rows of these)
  bool noSwaps = false;            // the tiers as shipped only
  bool validation = false;
  bool fp16Emulation = false;
  bool shadows = false;  // grid: also the "shadowed" view
  int groundTruth = 0;   // samples of the ground truth (0: not measured)
  std::string gpu;       // "mali-g57,adreno-630": per-GPU figures from Mesa (docs/mesa-statistics.md)
  std::string mesaPrefix;
};
// 0 with the report written, 1 for input errors, 2 for usage errors.
int evalCommand(const EvalArgs& args);

}  // namespace facet::eval
