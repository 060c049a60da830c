// matc post: the runtime's post pass, compiled by the compiler's post domain and written as C++
// source the runtime builds in (runtime/CMakeLists.txt runs `matc post` at build time).
#include <cstdio>
#include <filesystem>

#include "commands.h"
#include "facet/cli/inputs.h"
#include "facet/cli/outputs.h"
#include "facet/compiler/mobile_cost.h"
#include "facet/compiler/post.h"
#include "facet/package/package.h"

namespace facet::matc {
namespace {

// The static mobile cost model's estimate of a fragment stage (docs/eval.md, "The mobile cost
// model"), as `matc info` prints it for a material's: "12.3 cycles (arithmetic-bound), 1 sample".
std::string fragmentCost(const std::vector<uint32_t>& spirv) {
  compiler::MobileStageCost cost;
  std::string error;
  if (!compiler::estimateMobileCost(spirv, &cost, &error)) return "cost unknown (" + error + ")";
  char text[96];
  std::snprintf(text, sizeof text, "%.1f cycles (%s-bound), %.0f samples", cost.cycles, cost.bound(),
                cost.textureSamples);
  return text;
}

}  // namespace

int postCommand(const PostArgs& args) {
  compiler::PostEffects chosen;
  chosen.toneCurve = *compiler::toneCurveFromString(args.toneCurve);  // CLI11 checked the name
  chosen.dither = args.dither;
  chosen.colorGrading = args.grading;
  chosen.vignette = args.vignette;
  chosen.bloom = args.bloom;
  const std::vector<compiler::PostEffects> effects =
      args.everyVariant ? compiler::everyPostEffects() : std::vector<compiler::PostEffects>{chosen};
  std::vector<compiler::PostShaders> variants(effects.size());
  std::string error;
  for (size_t i = 0; i < effects.size(); ++i) {
    if (!compiler::buildPostShaders(effects[i], &variants[i], &error)) {
      cli::printError(error);
      return 1;
    }
  }
  compiler::PostStage fxaa;
  compiler::BloomStages bloom;
  compiler::BackgroundStages background;
  if (!compiler::buildFxaaShader(&fxaa, &error) || !compiler::buildBloomShaders(&bloom, &error) ||
      !compiler::buildBackgroundShaders(&background, &error)) {
    cli::printError(error);
    return 1;
  }
  // Every output, checked against the others and written together.
  namespace fs = std::filesystem;
  std::vector<cli::NamedFile> outputs;
  std::vector<package::OutputFile> files;
  auto add = [&](const char* role, const std::string& path, const std::string& text) {
    outputs.push_back({role, path});
    files.push_back({path, std::vector<uint8_t>(text.begin(), text.end())});
  };
  for (size_t i = 0; i < variants.size() && !args.emitSource.empty(); ++i) {
    const compiler::PostShaders& shaders = variants[i];
    const std::string stem =
        (fs::path(args.emitSource) / ("post." + compiler::postVariantKey(shaders.effects))).string();
    add("--emit-source", stem + ".vert.es300.glsl", shaders.vertex.glslEs);
    add("--emit-source", stem + ".vert.metal", shaders.vertex.msl);
    add("--emit-source", stem + ".frag.es300.glsl", shaders.sampledFragment.glslEs);
    add("--emit-source", stem + ".frag.metal", shaders.sampledFragment.msl);
    add("--emit-source", stem + ".fetch.frag.es300.glsl", shaders.fetchFragment.glslEs);
    add("--emit-source", stem + ".fetch.frag.metal", shaders.fetchFragment.msl);
    add("--emit-source", stem + ".upscaled.frag.es300.glsl", shaders.upscaledFragment.glslEs);
    add("--emit-source", stem + ".upscaled.frag.metal", shaders.upscaledFragment.msl);
    if (!shaders.samplesFragment.glslEs.empty()) {
      // GLSL ES 3.10 (sampler2DMS): its vertex stage is the variant's, at the same version.
      std::string vertex = shaders.vertex.glslEs;
      vertex.replace(0, vertex.find('\n'), "#version 310 es");
      add("--emit-source", stem + ".samples.vert.es310.glsl", vertex);
      add("--emit-source", stem + ".samples.frag.es310.glsl", shaders.samplesFragment.glslEs);
    }
  }
  if (!args.emitSource.empty()) {
    const std::string stem = (fs::path(args.emitSource) / "post.fxaa").string();
    add("--emit-source", stem + ".frag.es300.glsl", fxaa.glslEs);
    add("--emit-source", stem + ".frag.metal", fxaa.msl);
    const std::string bloomStem = (fs::path(args.emitSource) / "post.bloom").string();
    add("--emit-source", bloomStem + ".vert.es300.glsl", bloom.vertex.glslEs);
    add("--emit-source", bloomStem + ".vert.metal", bloom.vertex.msl);
    add("--emit-source", bloomStem + ".down.frag.es300.glsl", bloom.downsample.glslEs);
    add("--emit-source", bloomStem + ".down.frag.metal", bloom.downsample.msl);
    add("--emit-source", bloomStem + ".threshold.frag.es300.glsl", bloom.downsampleThreshold.glslEs);
    add("--emit-source", bloomStem + ".threshold.frag.metal", bloom.downsampleThreshold.msl);
    add("--emit-source", bloomStem + ".up.frag.es300.glsl", bloom.upsample.glslEs);
    add("--emit-source", bloomStem + ".up.frag.metal", bloom.upsample.msl);
    const std::string backgroundStem = (fs::path(args.emitSource) / "post.background").string();
    add("--emit-source", backgroundStem + ".vert.es300.glsl", background.vertex.glslEs);
    add("--emit-source", backgroundStem + ".vert.metal", background.vertex.msl);
    add("--emit-source", backgroundStem + ".frag.es300.glsl", background.fragment.glslEs);
    add("--emit-source", backgroundStem + ".frag.metal", background.fragment.msl);
  }
  add("--cpp", args.cpp, compiler::postShadersCpp(variants, fxaa, bloom) + compiler::backgroundShadersCpp(background));
  if (!cli::outputsSpareInputs({}, outputs) || !cli::writeOutputs({args.emitSource}, files)) return 1;
  for (const compiler::PostShaders& shaders : variants)
    std::printf(
        "post %s: %zu + %zu + %zu + %zu + %zu SPIR-V words; fragment: sampled %s, fetch %s, upscaled %s, per-sample "
        "%s\n",
        compiler::postVariantKey(shaders.effects).c_str(), shaders.vertex.spirv.size(),
        shaders.sampledFragment.spirv.size(), shaders.fetchFragment.spirv.size(), shaders.upscaledFragment.spirv.size(),
        shaders.samplesFragment.spirv.size(), fragmentCost(shaders.sampledFragment.spirv).c_str(),
        fragmentCost(shaders.fetchFragment.spirv).c_str(), fragmentCost(shaders.upscaledFragment.spirv).c_str(),
        shaders.samplesFragment.spirv.empty() ? "none" : fragmentCost(shaders.samplesFragment.spirv).c_str());
  std::printf("post fxaa: %zu SPIR-V words; fragment %s\n", fxaa.spirv.size(), fragmentCost(fxaa.spirv).c_str());
  std::printf("post bloom: downsample %s, threshold %s, upsample %s\n", fragmentCost(bloom.downsample.spirv).c_str(),
              fragmentCost(bloom.downsampleThreshold.spirv).c_str(), fragmentCost(bloom.upsample.spirv).c_str());
  std::printf("post background: %zu + %zu SPIR-V words; fragment %s\n", background.vertex.spirv.size(),
              background.fragment.spirv.size(), fragmentCost(background.fragment.spirv).c_str());
  std::printf("-> %s\n", args.cpp.c_str());
  return 0;
}

}  // namespace facet::matc
