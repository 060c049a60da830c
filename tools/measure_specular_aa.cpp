// tools/measure_specular_aa.cpp — the specular anti-aliasing figures of docs/material-models.md
// ("Specular anti-aliasing"): per tier (high, mid, low), the scene with 1 sample per pixel, without
// specular anti-aliasing (REFERENCE_PACKAGES) and with each LABEL's packages, against 16 samples
// per pixel without it (tools/specular_aa_figures.h says what each figure is). A reference row's
// summed specular is over high's reference: what each tier's lobe reflects of the same light.
//
// Usage: measure_specular_aa SCENE REFERENCE_PACKAGES LABEL=PACKAGES... [--asset-root DIR]
//        [--images DIR] [--backend vulkan|gl]   (prints Markdown; deterministic). --asset-root: the folder the scene
//        may read files from (default its own; facet-view's option of the same name); --images: writes
//        each tier's first frames there as PNG (<tier>.<label>.png, <tier>.reference.png).
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "facet/runtime/png.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "specular_aa_figures.h"

namespace {

using namespace facet::runtime;
using namespace facet::supersample;

int fail(const std::string& message) {
  std::fprintf(stderr, "measure_specular_aa: error: %s\n", message.c_str());
  return 1;
}

int usage() {
  std::fprintf(stderr,
               "usage: measure_specular_aa SCENE REFERENCE_PACKAGES LABEL=PACKAGES... [--asset-root DIR] "
               "[--images DIR] [--backend vulkan|gl]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string api = "vulkan";
  SceneReadOptions read;
  std::string images;
  while (args.size() >= 2) {
    const std::string& option = args[args.size() - 2];
    if (option != "--backend" && option != "--asset-root" && option != "--images") break;
    (option == "--backend" ? api : option == "--asset-root" ? read.assetRoot : images) = args.back();
    args.resize(args.size() - 2);
  }
  if (api != "vulkan" && api != "gl") return usage();
  if (args.size() < 3) return usage();
  std::vector<std::pair<std::string, std::string>> measured = {{"without", args[1]}};
  for (size_t i = 2; i < args.size(); ++i) {
    const size_t eq = args[i].find('=');
    if (eq == std::string::npos || eq == 0) return usage();
    measured.emplace_back(args[i].substr(0, eq), args[i].substr(eq + 1));
  }
  std::string error;
  auto scene = loadScene(args[0], &error, read);
  if (!scene) return fail(error);
  std::unique_ptr<RenderBackend> backend =
      api == "gl" ? createGlBackend(GlOptions{}, &error) : createVulkanBackend(VulkanOptions{}, &error);
  if (!backend) return fail(error);

  std::printf(
      "%s, %ux%u, 1 sample per pixel against 16 (4x4, box filter in linear light) without specular "
      "anti-aliasing; flicker over %d camera positions 1/%d pixel apart (8-bit steps):\n\n",
      api.c_str(), scene->width, scene->height, kSweepSteps, kSweepSteps);
  std::printf(
      "| tier | packages | summed specular / reference | PSNR dB | PSNR of HDR dB | frame-to-frame | beyond the "
      "reference's |\n");
  std::printf("|---|---|--:|--:|--:|--:|--:|\n");
  double highReference = 0;  // the reference rows' summed specular is over high's reference
  for (const char* tier : {"high", "mid", "low"}) {
    Scene s = *scene;
    s.tier = tier;
    Reference reference;
    if (!measureReference(*backend, s, args[1], &reference, &error)) return fail(error);
    if (highReference == 0) highReference = reference.hdrSum;
    const auto save = [&](const std::string& name, const std::vector<uint8_t>& rgba) {
      return images.empty() ||
             writePng(images + "/" + tier + "." + name + ".png", scene->width, scene->height, rgba, &error);
    };
    if (!save("reference", reference.image)) return fail(error);
    for (const auto& [label, packages] : measured) {
      SpecularAaFigures f;
      if (!measureOneSample(*backend, s, packages, reference, &f, &error)) return fail(error);
      if (!save(label, f.firstFrame)) return fail(error);
      std::printf("| %s | %s | %.4f | %.2f | %.2f | %.4f | %.4f |\n", tier, label.c_str(), f.specularRatio, f.psnr,
                  f.psnrHdr, f.flicker, f.flickerBeyondReference);
    }
    double change = 0, excess = 0;
    flicker(reference.sweep, reference.sweep, &change, &excess);
    std::printf("| %s | reference (16 samples) | %.4f | ∞ | %.2f | %.4f | 0 |\n", tier,
                reference.hdrSum / highReference, facet::eval::psnr8(reference.image, reference.resolved), change);
  }
  for (const std::string& e : backend->validationErrors()) return fail("validation: " + e);
  return 0;
}
