// matc's commands. Each returns the process exit code: 0 success, 1 input errors, 2 usage errors.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/permutations/variant_key.h"

namespace facet::matc {

struct CompileArgs {
  std::string input;
  std::string output;      // default: input with .matpkg
  std::string emitSource;  // folder for every generated source, or ""
  std::vector<std::string> tiers;  // tier names; empty: every tier this compiler supports
  std::string scene;       // scene manifest: build only the variants it asks this material for
  std::vector<int> pointLights{0};  // point-light permutations to build without a scene
  bool fp16Emulation = false;  // testing build: mediump SPIR-V rounded to binary16 (docs/fp16-emulation.md)
};
int compileCommand(const CompileArgs& args);

struct InfoArgs {
  std::string input;
  std::string variant;  // with stage + target: print that shader
  std::string stage;
  std::string target;
  std::string scene;    // check the package has the variant this scene asks for
};
int infoCommand(const InfoArgs& args);

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
};
int evalCommand(const EvalArgs& args);

// --tiers names -> tiers (unchanged when names is empty). Non-zero: the exit status of a usage
// error, already printed.
int parseTiers(const std::vector<std::string>& names, std::vector<permutations::Tier>* tiers);

// Prints "matc: error: <message>" to stderr.
void printError(const std::string& message);

}  // namespace facet::matc
