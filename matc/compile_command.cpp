#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "commands.h"
#include "facet/cli/inputs.h"
#include "facet/cli/outputs.h"
#include "facet/compiler/build.h"
#include "facet/compiler/library_sources.h"
#include "facet/ir/check.h"
#include "facet/ir/lexer.h"
#include "facet/package/package.h"
#include "facet/permutations/variant_key.h"
#include "facet/scene/scene.h"
#include "facet/tune/choices.h"
#include "scene_keys.h"

namespace facet::matc {

namespace {

namespace fs = std::filesystem;

// A path as a Makefile (and Ninja depfile) word: spaces and '#' escaped with '\\', '$' doubled.
std::string makeWord(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

// `output: inputs...` for Ninja/Make: the material, the scene, the tuning file, the matc executable (it embeds the
// templates and chunks) and, while the source tree it was built from exists, every template and
// chunk a built variant used, so editing one rebuilds the package.
std::string depfileText(const std::string& output, const CompileArgs& args, const std::string& tuningFile,
                        const std::set<std::string>& libraryFiles) {
  std::vector<std::string> inputs{args.input};
  if (!args.scene.empty()) inputs.push_back(args.scene);
  if (!tuningFile.empty()) inputs.push_back(tuningFile);
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) inputs.push_back(self.string());
  for (const std::string& name : libraryFiles)
    if (std::string path = compiler::librarySourcePath(name); !path.empty()) inputs.push_back(path);
  std::string text = makeWord(output) + ":";
  for (const std::string& in : inputs) text += " \\\n  " + makeWord(in);
  text += "\n";
  return text;
}

std::vector<uint8_t> bytesOf(const std::string& text) { return {text.begin(), text.end()}; }

// $XDG_CACHE_HOME/facet/matc, else $HOME/.cache/facet/matc (the XDG base directory default), else none.
std::string defaultCacheDir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/facet/matc";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/facet/matc";
  return "";
}

// Tiers from --tiers, and the variants a --scene manifest asks this material for.
int buildOptions(const CompileArgs& args, const ir::Material& material, compiler::BuildOptions* options) {
  if (int status = cli::parseTiers(args.tiers, &options->tiers); status != 0) return status;
  options->pointLightCounts = args.pointLights;
  options->shadowCascadeCounts = args.shadows;
  options->spotShadows = args.spotShadows;
  options->vertexSlopeBias = args.vertexSlopeBias;
  const bool depthPrograms =
      args.spotShadows || std::any_of(args.shadows.begin(), args.shadows.end(), [](int c) { return c > 0; });
  if (args.vertexSlopeBias && args.scene.empty() && !depthPrograms) {
    cli::printError(
        "--vertex-slope-bias: no depth-only program is built without --shadows (a non-zero count), "
        "--spot-shadows or a --scene");
    return 2;
  }
  if (args.scene.empty()) return 0;
  std::string error;
  auto scene = loadSceneManifest(args.scene, &error);
  if (!scene) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  auto keys = sceneKeysFor(*scene, args.scene, material.name, compiler::materialNeeds(material), &error);
  if (!keys) {
    cli::printError(error);
    return 1;
  }
  if (std::find(options->tiers.begin(), options->tiers.end(), keys->front().tier) == options->tiers.end()) {
    cli::printError(args.scene + ": the scene asks for tier '" + scene->tier + "', which this build does not include");
    return 1;
  }
  options->scene = permutations::SceneNeeds{*keys};
  return 0;
}

}  // namespace

int compileCommand(const CompileArgs& args) {
  std::string output = args.output;
  if (output.empty()) output = fs::path(args.input).replace_extension(".matpkg").string();
  std::vector<cli::NamedFile> inputs{{"the input material", args.input}};
  if (!args.scene.empty()) inputs.push_back({"the --scene file", args.scene});
  std::vector<cli::NamedFile> outputs{{args.output.empty() ? "no -o: the input with .matpkg" : "-o", output}};
  if (!args.depfile.empty()) outputs.push_back({"--depfile", args.depfile});
  if (!cli::outputsSpareInputs(inputs, outputs)) return 1;
  ir::SourceFile source;
  std::optional<ir::Material> material = cli::loadMaterial(args.input, &source);
  if (!material) return 1;
  compiler::BuildOptions options;
  std::optional<tune::ShippedTuning> tuning =
      tune::shippedTuningForCommand(args.input, args.tuning, args.noTuning, *material, &options.tunedTiers);
  if (!tuning) return 1;
  if (!tuning->path.empty()) inputs.push_back({"the tuning file", tuning->path});

  options.fp16Emulation = args.fp16Emulation;
  options.emitSources = !args.emitSource.empty();
  options.jobs = args.jobs;
  // A progress line only where someone watches it: stderr on a terminal, redrawn in place and
  // erased at the end; logs and pipes stay quiet.
  const bool progressLine = isatty(fileno(stderr)) != 0;
  if (progressLine)
    options.progress = [&](size_t done, size_t total) {
      std::fprintf(stderr, "\r%s: compiling variants %zu/%zu", material->name.c_str(), done, total);
      std::fflush(stderr);
    };
  if (!args.noCache) {
    // A cache the user named must be usable; the default one only speeds builds up, so a build
    // where it cannot be (a read-only home, a folder of other files there) goes on without it.
    options.cacheDir = args.cacheDir.empty() ? defaultCacheDir() : args.cacheDir;
    std::string error;
    if (!options.cacheDir.empty() && !compiler::prepareVariantCache(options.cacheDir, &error)) {
      if (!args.cacheDir.empty()) {
        cli::printError("--cache: " + error);
        return 2;
      }
      std::fprintf(stderr, "matc: warning: building without the variant cache: %s\n", error.c_str());
      options.cacheDir.clear();
    }
  }
  options.cacheMaxBytes = uint64_t(args.cacheMaxMiB) << 20;
  if (int status = buildOptions(args, *material, &options); status != 0) return status;
  compiler::BuildError buildError;
  std::optional<compiler::BuildResult> built = compiler::buildMaterial(*material, options, &buildError);
  if (progressLine) std::fputs("\r\033[K", stderr);
  if (!built) {
    cli::printBuildError(source, buildError.message, buildError.loc);
    return 1;
  }
  if (built->cacheRejected > 0)
    std::fprintf(stderr,
                 "matc: warning: %zu entr%s of the variant cache %s failed validation (spirv-val, glslang) and %s "
                 "compiled again: something other than matc wrote there\n",
                 built->cacheRejected, built->cacheRejected == 1 ? "y" : "ies", options.cacheDir.c_str(),
                 built->cacheRejected == 1 ? "was" : "were");
  // Every output is known before any is written: the emitted sources are checked like the
  // package and the depfile, then all land together.
  std::vector<package::OutputFile> files{{output, package::write(built->package)}};
  const size_t packageBytes = files[0].bytes.size();
  if (!args.depfile.empty())
    files.push_back({args.depfile, bytesOf(depfileText(output, args, tuning->path, built->libraryFiles))});
  for (const compiler::GeneratedFile& f : built->sources) {
    outputs.push_back({"--emit-source", (fs::path(args.emitSource) / f.name).string()});
    files.push_back({outputs.back().path, bytesOf(f.text)});
  }
  if (!cli::outputsSpareInputs(inputs, outputs) || !cli::writeOutputs({args.emitSource}, files)) return 1;
  size_t variants = built->package.variants.size();
  std::string forScene;
  if (options.scene) {
    const permutations::MaterialNeeds needs = compiler::materialNeeds(*material);
    forScene = " for scene " + args.scene + " (" +
               std::to_string(permutations::enumerate(needs, options.tiers, nullptr, args.pointLights, args.shadows,
                                                      args.spotShadows, args.vertexSlopeBias)
                                  .size()) +
               " without it)";
  }
  std::string cached;
  if (built->cacheHits > 0) cached = " (" + std::to_string(built->cacheHits) + " from the cache)";
  std::string tuned;
  if (!tuning->path.empty()) tuned = ", tiers tuned by " + tuning->path;
  std::printf("%s: %zu variant%s%s, %zu bytes -> %s%s%s\n", material->name.c_str(), variants, variants == 1 ? "" : "s",
              forScene.c_str(), packageBytes, output.c_str(), cached.c_str(), tuned.c_str());
  return 0;
}

}  // namespace facet::matc
