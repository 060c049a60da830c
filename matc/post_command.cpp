// matc post: the runtime's post pass, compiled by the compiler's post domain and written as C++
// source the runtime builds in (runtime/CMakeLists.txt runs this at build time).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "facet/compiler/post.h"
#include "facet/package.h"

namespace facet::matc {

void addPostOptions(CLI::App* command, PostArgs* args) {
  command->add_option("--cpp", args->cpp, "C++ file to write (defines facet::runtime::postShaders())")->required();
  command->add_option("--emit-source", args->emitSource, "also write every generated shader source to this folder");
  command
      ->add_option("--tone-curve", args->toneCurve,
                   "aces (filmic, default) | neutral (Khronos PBR Neutral: keeps hue below its knee) | none (HDR "
                   "clamped to [0, 1])")
      ->check(CLI::IsMember({"aces", "neutral", "none"}));
  command->add_flag("--dither", args->dither, "add triangular noise of one 8-bit step before quantisation (no banding)");
}

int postCommand(const PostArgs& args) {
  compiler::PostEffects effects;
  effects.toneCurve = *compiler::toneCurveFromString(args.toneCurve);  // CLI11 checked the name
  effects.dither = args.dither;
  compiler::PostShaders shaders;
  std::string error;
  if (!compiler::buildPostShaders(effects, &shaders, &error)) {
    printError(error);
    return 1;
  }
  auto write = [&](const std::string& path, const std::string& text) {
    const std::vector<uint8_t> bytes(text.begin(), text.end());
    if (package::writeFile(path, bytes, &error)) return true;
    printError(error);
    return false;
  };
  if (!args.emitSource.empty()) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(args.emitSource, ec);
    if (ec) {
      printError("cannot create '" + args.emitSource + "': " + ec.message());
      return 1;
    }
    const std::string stem = (fs::path(args.emitSource) / ("post." + shaders.key)).string();
    if (!write(stem + ".vert.es300.glsl", shaders.vertex.glslEs) || !write(stem + ".vert.metal", shaders.vertex.msl) ||
        !write(stem + ".frag.es300.glsl", shaders.sampledFragment.glslEs) ||
        !write(stem + ".frag.metal", shaders.sampledFragment.msl) ||
        !write(stem + ".fetch.frag.es300.glsl", shaders.fetchFragment.glslEs) ||
        !write(stem + ".fetch.frag.metal", shaders.fetchFragment.msl)) {
      return 1;
    }
  }
  if (!write(args.cpp, compiler::postShadersCpp(shaders))) return 1;
  std::printf("post %s: %zu + %zu + %zu SPIR-V words -> %s\n", shaders.key.c_str(), shaders.vertex.spirv.size(),
              shaders.sampledFragment.spirv.size(), shaders.fetchFragment.spirv.size(), args.cpp.c_str());
  return 0;
}

}  // namespace facet::matc
