// matc's commands. Each returns the process exit code: 0 success, 1 input errors, 2 usage errors.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/compiler/build.h"
#include "facet/permutations/variant_key.h"

namespace facet::matc {

struct CompileArgs {
  std::string input;
  std::string output;               // default: input with .matpkg
  std::string emitSource;           // folder for every generated source, or ""
  std::string depfile;              // Makefile-syntax dependency file to write, or ""
  std::vector<std::string> tiers;   // tier names; empty: every tier this compiler supports
  std::string scene;                // scene manifest: build only the variants it asks this material for
  std::vector<int> pointLights{0};  // point-light permutations to build without a scene
  std::vector<int> shadows{0};      // sun shadow-cascade permutations to build without a scene
  bool spotShadows = false;         // also each point-light variant as a spot-shadow receiver (.sp1)
  bool vertexSlopeBias = false;     // also each depth-only program with the vertex-stage slope bias
  unsigned jobs = 0;                // variants compiled at once; 0: one per hardware thread
  std::string cacheDir;             // --cache; "" for the default (defaultCacheDir())
  bool noCache = false;             // --no-cache
  uint32_t cacheMaxMiB = uint32_t(compiler::kDefaultCacheMaxBytes >> 20);  // --cache-max-size
  bool fp16Emulation = false;  // testing build: mediump SPIR-V rounded to binary16 (docs/fp16-emulation.md)
  std::string tuning;          // --tuning: the tiers' tuning file; "": <input stem>.tuning.json if it exists
  bool noTuning = false;       // --no-tuning: the presets with the material's `tier` blocks
};
int compileCommand(const CompileArgs& args);

struct InfoArgs {
  std::string input;
  std::string variant;  // with stage + target: print that shader
  std::string stage;
  std::string target;
  std::string scene;  // check the package has the variant this scene asks for
  bool json = false;  // the summary as JSON
};
int infoCommand(const InfoArgs& args);

struct LintArgs {
  std::vector<std::string> inputs;  // material files, or folders of them
  std::vector<std::string> tiers;
  std::vector<int> pointLights{0};
  std::vector<int> shadows{0};  // sun-shadow receivers to build and check
  bool spotShadows = false;     // spot-shadow receivers (.sp1) to build and check
  std::string config;           // budgets JSON (docs/lint.md), or ""
  std::string baseline;         // baseline JSON, or ""
  bool updateBaseline = false;  // rewrite the baseline from this run's figures
  double tolerancePercent = 5;  // growth over the baseline that is still accepted
  std::string format = "text";  // text | json | sarif
  std::string output;           // report file, or "" for stdout
  bool werror = false;          // warnings fail the run
  std::string gpu;              // "mali-g57,adreno-630": per-GPU figures from Mesa (docs/mesa-statistics.md)
  std::string mesaPrefix;       // the Mesa build, default: mesa_compile.py's (the cache folder)
  bool noTuning = false;        // --no-tuning: the presets, not each material's <stem>.tuning.json
};
int lintCommand(const LintArgs& args);
struct PostArgs {
  std::string cpp;                 // generated C++ source for the runtime
  std::string emitSource;          // folder for every generated shader source, or ""
  std::string toneCurve = "aces";  // compiler::ToneCurve by name
  bool dither = false;
  bool grading = false;  // 3D LUT colour grading
  bool vignette = false;
  bool bloom = false;
  bool everyVariant = false;  // every combination of effects (what the runtime embeds)
};
int postCommand(const PostArgs& args);

// matc eval and matc texture: run `program` (facet-eval, the program that links the renderer,
// eval/tool/; facet-texture, the ASTC encoder, texture/tool/) with `args`, the arguments after
// `command`; `matc` is the path matc was run as, `target` the CMake target that builds the
// program. The process becomes the program, so this returns only when it cannot be run (1, with
// the error printed).
int runHelperProgram(const std::string& matc, const std::string& command, const std::string& program,
                     const std::string& target, const std::vector<std::string>& args);

}  // namespace facet::matc
