// facet-measure-shadows: the ray-cast shadow reference of a scene, and the score of a renderer's
// shadows against it (docs/shadows.md, "Accuracy: the ray-cast reference").
//
// Renders the scene's reference visibility (library shadow_reference: the scene's own meshes in
// double, a BVH, the sun's visibility at each pixel's hit point and over a footprint disc) and,
// given the renderer's visibility (a visibility image, or a frame with shadows and one without,
// both lit by the sun alone), counts its wrong pixels among those whose footprint visibility is
// exactly 0 or 1. Writes the reference as PNG (--reference) and the figures as JSON (--json);
// prints them as a Markdown table. Same inputs, same bytes.
//
// Exit 0, 1 on an input error (scene, images), 2 on a usage error.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "facet/cli/command_line.h"
#include "facet/cli/inputs.h"
#include "facet/cli/outputs.h"
#include "facet/package/atomic_file.h"
#include "facet/runtime/png.h"
#include "facet/shadow_reference/reference_image.h"
#include "facet/shadow_reference/rendered_visibility.h"
#include "facet/shadow_reference/shadow_score.h"

namespace {

using namespace facet::shadow_reference;

// The libraries' messages already read "<file>: error: ...".
int inputError(const std::string& message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  return 1;
}

nlohmann::ordered_json countsJson(const ReferenceCounts& c) {
  return {{"lit", c.lit}, {"occluded", c.occluded}, {"partial", c.partial}, {"facesAway", c.facesAway}, {"sky", c.sky}};
}

nlohmann::ordered_json scoreJson(const ShadowScore& s) {
  return {{"scored", s.scored}, {"wrong", s.wrong}, {"wrongFraction", s.wrongFraction()},
          {"leaks", s.leaks},   {"acne", s.acne},   {"unmeasured", s.unmeasured}};
}

}  // namespace

int main(int argc, char** argv) {
  facet::removeTemporaryFilesOnSignals();
  facet::cli::setProgramName("facet-measure-shadows");
  CLI::App app{"ray-cast a scene's sun (or spot light) shadows and score a rendering against them (docs/shadows.md)"};
  std::string scenePath, referencePath, jsonPath, visibilityPath, shadowedPath, unshadowedPath, assetRoot;
  ReferenceOptions options;
  app.add_option("scene", scenePath, "scene JSON")->required();
  app.add_option("--reference", referencePath, "PNG to write the reference visibility to");
  app.add_option("--json", jsonPath, "file to write the figures to");
  app.add_option("--footprint", options.footprintRadius,
                 "radius in metres of the filter's footprint disc (0: the hit point alone)")
      ->check(CLI::Range(0.0, 1000.0));
  app.add_option("--samples", options.footprintSamples, "points ray-cast per footprint")->check(CLI::Range(1, 4096));
  auto* visibility =
      app.add_option("--visibility", visibilityPath, "the renderer's visibility image (white lit, black in shadow)");
  auto* shadowed =
      app.add_option("--shadowed", shadowedPath, "the renderer's frame with shadows, lit by the sun alone");
  auto* unshadowed = app.add_option("--unshadowed", unshadowedPath, "the same frame without shadows");
  shadowed->needs(unshadowed);
  unshadowed->needs(shadowed);
  visibility->excludes(shadowed)->excludes(unshadowed);
  std::optional<size_t> spotLight;
  app.add_option("--spot", spotLight, "ray-cast the spot light /lights/N instead of the sun")
      ->check(CLI::Range(size_t{0}, facet::runtime::kMaxSceneLights - 1));
  app.add_option("--asset-root", assetRoot, "folder the scene's files may be read from (default: the scene's)");
  if (std::optional<int> exit = facet::cli::parseCommandLine(app, argc, argv)) return *exit;
  // CLI11's range check lets NaN through (no comparison with it is true).
  if (!(options.footprintRadius >= 0)) {
    facet::cli::printError("--footprint: expected a radius in [0, 1000] metres");
    return 2;
  }

  std::vector<facet::cli::NamedFile> inputs{{"the scene", scenePath}}, outputs;
  for (const auto& [role, path] : {std::pair{"--visibility", visibilityPath}, std::pair{"--shadowed", shadowedPath},
                                   std::pair{"--unshadowed", unshadowedPath}})
    if (!path.empty()) inputs.push_back({role, path});
  if (!referencePath.empty()) outputs.push_back({"--reference", referencePath});
  if (!jsonPath.empty()) outputs.push_back({"--json", jsonPath});
  if (!facet::cli::outputsSpareInputs(inputs, outputs)) return 1;

  std::string error;
  std::optional<ShadowScene> scene = loadShadowScene(scenePath, &error, {assetRoot});
  if (!scene) return inputError(error);
  std::optional<SunVisibility> sun =
      spotLight ? SunVisibility::buildSpot(*scene, *spotLight, &error) : SunVisibility::build(*scene, &error);
  if (!sun) return inputError(scenePath + ": error: " + error);
  // The renderer's images are read before the reference is cast: a bad one fails at once.
  std::optional<RenderedVisibility> rendered;
  if (!visibilityPath.empty()) rendered = visibilityFromImage(visibilityPath, &error);
  if (!shadowedPath.empty()) rendered = visibilityFromFrames(shadowedPath, unshadowedPath, &error);
  if (!rendered && (!visibilityPath.empty() || !shadowedPath.empty())) {
    facet::cli::printError(error);  // the image reader's "<file>: cannot read image: ..."
    return 1;
  }

  const ReferenceImage reference = renderReference(*scene, *sun, options);
  const ReferenceCounts counts = countReference(reference);
  nlohmann::ordered_json figures = {{"width", reference.width},
                                    {"height", reference.height},
                                    {"footprintRadius", options.footprintRadius},
                                    {"footprintSamples", options.footprintSamples},
                                    {"reference", countsJson(counts)}};
  std::optional<ShadowScore> score;
  if (rendered) {
    score = scoreShadows(reference, *rendered, &error);
    if (!score) return inputError((visibilityPath.empty() ? shadowedPath : visibilityPath) + ": error: " + error);
    figures["score"] = scoreJson(*score);
  }

  std::vector<facet::package::OutputFile> files;
  if (!referencePath.empty()) {
    std::vector<uint8_t> png;
    if (!facet::runtime::encodePng(reference.width, reference.height, referencePixelsRgba(reference), &png, &error))
      return inputError(referencePath + ": error: " + error);
    files.push_back({referencePath, std::move(png)});
  }
  if (!jsonPath.empty()) {
    const std::string text = figures.dump(2) + "\n";
    files.push_back({jsonPath, std::vector<uint8_t>(text.begin(), text.end())});
  }
  if (!facet::cli::writeOutputs({""}, files)) return 1;

  std::printf("| pixels lit | occluded | partial | faces away | sky |");
  if (score) std::printf(" scored | wrong | wrong %% | leaks | acne | unmeasured |");
  std::printf("\n|---:|---:|---:|---:|---:|");
  if (score) std::printf("---:|---:|---:|---:|---:|---:|");
  std::printf("\n| %llu | %llu | %llu | %llu | %llu |", static_cast<unsigned long long>(counts.lit),
              static_cast<unsigned long long>(counts.occluded), static_cast<unsigned long long>(counts.partial),
              static_cast<unsigned long long>(counts.facesAway), static_cast<unsigned long long>(counts.sky));
  if (score)
    std::printf(" %llu | %llu | %.3f | %llu | %llu | %llu |", static_cast<unsigned long long>(score->scored),
                static_cast<unsigned long long>(score->wrong), 100 * score->wrongFraction(),
                static_cast<unsigned long long>(score->leaks), static_cast<unsigned long long>(score->acne),
                static_cast<unsigned long long>(score->unmeasured));
  std::printf("\n");
  return 0;
}
