#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "facet/compiler/build.h"
#include "facet/package.h"
#include "facet/permutations/variant_key.h"
#include "facet/runtime/scene.h"
#include "material_source.h"
#include "scene_keys.h"

namespace facet::matc {

void printError(const std::string& message) { std::fprintf(stderr, "matc: error: %s\n", message.c_str()); }

namespace {

namespace fs = std::filesystem;

bool writeSources(const std::string& dir, const std::vector<compiler::GeneratedFile>& files) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    printError("cannot create '" + dir + "': " + ec.message());
    return false;
  }
  for (const compiler::GeneratedFile& f : files) {
    std::vector<uint8_t> bytes(f.text.begin(), f.text.end());
    std::string error;
    if (!package::writeFile((fs::path(dir) / f.name).string(), bytes, &error)) {
      printError(error);
      return false;
    }
  }
  return true;
}

// Tiers from --tiers, and the variants a --scene manifest asks this material for.
int buildOptions(const CompileArgs& args, const ir::Material& material, compiler::BuildOptions* options) {
  if (int status = parseTiers(args.tiers, &options->tiers); status != 0) return status;
  options->pointLightCounts = args.pointLights;
  if (args.scene.empty()) return 0;
  std::string error;
  auto scene = runtime::loadScene(args.scene, &error);
  if (!scene) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  auto key = sceneKeyFor(*scene, args.scene, material.name, material.shading == "lit", &error);
  if (!key) {
    printError(error);
    return 1;
  }
  if (std::find(options->tiers.begin(), options->tiers.end(), key->tier) == options->tiers.end()) {
    printError(args.scene + ": the scene asks for tier '" + scene->tier + "', which this build does not include");
    return 1;
  }
  options->scene = permutations::SceneNeeds{{*key}};
  return 0;
}

}  // namespace

int parseTiers(const std::vector<std::string>& names, std::vector<permutations::Tier>* tiers) {
  if (names.empty()) return 0;
  const auto& supported = permutations::supportedTiers();
  tiers->clear();
  for (const std::string& name : names) {
    auto tier = permutations::tierFromString(name);
    if (!tier) {
      printError("unknown tier '" + name + "' (reference, high, mid, low)");
      return 2;
    }
    if (std::find(supported.begin(), supported.end(), *tier) == supported.end()) {
      std::string list;
      for (permutations::Tier t : supported) list += (list.empty() ? "" : ", ") + std::string(permutations::toString(t));
      printError("tier '" + name + "' is not built by this compiler version (supported: " + list + ")");
      return 2;
    }
    tiers->push_back(*tier);
  }
  return 0;
}

int compileCommand(const CompileArgs& args) {
  ir::SourceFile source;
  std::optional<ir::Material> material = loadMaterial(args.input, &source);
  if (!material) return 1;

  compiler::BuildOptions options;
  options.fp16Emulation = args.fp16Emulation;
  if (int status = buildOptions(args, *material, &options); status != 0) return status;
  compiler::BuildError buildError;
  std::optional<compiler::BuildResult> built = compiler::buildMaterial(*material, options, &buildError);
  if (!built) {
    printBuildError(source, buildError.message, buildError.loc);
    return 1;
  }
  std::string error;
  std::string output = args.output;
  if (output.empty()) output = fs::path(args.input).replace_extension(".matpkg").string();
  std::vector<uint8_t> bytes = package::write(built->package);
  if (!package::writeFile(output, bytes, &error)) {
    printError(error);
    return 1;
  }
  if (!args.emitSource.empty() && !writeSources(args.emitSource, built->sources)) return 1;
  size_t variants = built->package.variants.size();
  std::string forScene;
  if (options.scene) {
    permutations::MaterialNeeds needs{material->shading == "lit"};
    forScene = " for scene " + args.scene + " (" +
               std::to_string(permutations::enumerate(needs, options.tiers, nullptr, args.pointLights).size()) +
               " without it)";
  }
  std::printf("%s: %zu variant%s%s, %zu bytes -> %s\n", material->name.c_str(), variants, variants == 1 ? "" : "s",
              forScene.c_str(), bytes.size(), output.c_str());
  return 0;
}

}  // namespace facet::matc
