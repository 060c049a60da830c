// tools/measure_msaa.cpp — the MSAA figures of docs/runtime.md ("MSAA").
//
// Renders a scene (tests/data/scenes/thin_edges.json: high-contrast silhouettes and a row of
// sub-pixel highlights) and compares, against a 16-sample reference:
// 1. edge quality: PSNR of 1 sample, of MSAA 2x/4x per pixel (on Vulkan also the portable form's
//    4x, resolved first and tone-mapped per sample) and of FXAA (alone and after MSAA 4x).
//    The reference is the scene rendered
//    at 4x the width and height with one sample, box-filtered over each 4x4 block in linear light
//    (each 8-bit output decoded from sRGB, averaged, encoded and rounded): 16 tone-mapped samples
//    per pixel, what the display should show;
// 2. the order of resolve and tone curve, on the same samples: the scene rendered at 2x (4
//    ordered-grid samples per pixel) and at 4x (16), each pixel's HDR samples averaged and then
//    tone-mapped on the CPU (what the merged path's resolve-first does), against each sample
//    tone-mapped and then averaged (what tone mapping per sample would do);
// 3. flicker: the mean absolute difference of consecutive frames (8-bit RGB values) over a sweep of
//    16 camera positions 1/16 pixel apart (the camera and its target moved sideways together by
//    1/16 of a pixel at the target's distance), for 1 sample, MSAA, FXAA and the reference; and the mean
//    absolute difference between an image's frame-to-frame change and the reference's, value by
//    value: the reference's change is the motion itself, what differs from it is temporal aliasing
//    (an aliased edge pops by whole steps where the reference moves smoothly);
// 4. render scale: PSNR of the frame rendered at 0.75 and 0.5 of the width and height and upscaled
//    by the post pass, against the same frame at full size (one sample each) and against the
//    16-sample reference.
//
// Usage: measure_msaa SCENE PACKAGES [--backend vulkan|gl]   (prints Markdown; deterministic)
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "facet/eval/metrics.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "supersample.h"

namespace {

using namespace facet::runtime;
using facet::supersample::downsampleLdr;
using facet::supersample::render;
using facet::supersample::resolveThenToneMap;

// portable (Vulkan): multisampled attachments instead of VK_EXT_multisampled_render_to_single_sampled,
// with the post subpass tone mapping each sample (toneMapSamples) or reading the resolve.
struct Portable {
  bool on = false;
  bool toneMapSamples = false;
};

std::unique_ptr<RenderBackend> makeBackend(const std::string& api, uint32_t samples, std::string* error,
                                           bool fxaa = false, Portable portable = {}, double renderScale = 1.0) {
  if (api == "gl") {
    GlOptions options;
    options.msaaSamples = samples;
    options.fxaa = fxaa;
    options.renderScale = renderScale;
    return createGlBackend(options, error);
  }
  VulkanOptions options;
  options.msaaSamples = samples;
  options.fxaa = fxaa;
  options.renderScale = renderScale;
  options.renderToSingleSampled = !portable.on;
  options.toneMapSamples = portable.toneMapSamples;
  return createVulkanBackend(options, error);
}

int fail(const std::string& message) {
  std::fprintf(stderr, "measure_msaa: error: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && !(argc == 5 && std::strcmp(argv[3], "--backend") == 0)) {
    std::fprintf(stderr, "usage: measure_msaa SCENE PACKAGES [--backend vulkan|gl]\n");
    return 2;
  }
  const std::string api = argc == 5 ? argv[4] : "vulkan";
  const std::string packages = argv[2];
  std::string error;
  auto scene = loadScene(argv[1], &error);
  if (!scene) return fail(error);
  const PostSettings& post = scene->post;
  if (post.toneCurve != "aces" || post.colorGrading || post.vignette || post.dither)
    return fail("the CPU tone curve here is ACES alone; the scene asks for other post effects");

  auto one = makeBackend(api, 1, &error);
  if (!one) return fail(error);
  std::vector<std::pair<std::string, std::unique_ptr<RenderBackend>>> msaa;
  for (uint32_t samples : {2u, 4u}) {
    std::string why;
    auto backend = makeBackend(api, samples, &why);
    if (backend) {
      msaa.emplace_back("MSAA " + std::to_string(samples) + "x", std::move(backend));
    } else {
      std::printf("MSAA %ux: not offered (%s)\n\n", samples, why.c_str());
    }
  }
  if (api == "vulkan") {
    for (bool perSample : {false, true}) {
      auto backend = makeBackend(api, 4, &error, false, {true, perSample});
      if (!backend) return fail(error);
      msaa.emplace_back(perSample ? "MSAA 4x portable, tone-mapped per sample" : "MSAA 4x portable, resolve first",
                        std::move(backend));
    }
  }
  // FXAA after the post pass, alone and on top of MSAA 4x.
  std::vector<std::pair<std::string, std::unique_ptr<RenderBackend>>> fxaa;
  for (uint32_t samples : {1u, 4u}) {
    std::string why;
    auto backend = makeBackend(api, samples, &why, true);
    const std::string name = samples == 1 ? "FXAA" : "MSAA " + std::to_string(samples) + "x + FXAA";
    if (backend) {
      fxaa.emplace_back(name, std::move(backend));
    } else {
      std::printf("%s: not offered (%s)\n\n", name.c_str(), why.c_str());
    }
  }

  // 1 and 2: one camera position.
  FrameResult reference16, reference4, single;
  if (!render(*one, *scene, 4, 0, packages, &reference16, &error) ||
      !render(*one, *scene, 2, 0, packages, &reference4, &error) ||
      !render(*one, *scene, 1, 0, packages, &single, &error))
    return fail(error);
  const std::vector<uint8_t> reference = downsampleLdr(reference16, 4);
  std::printf("%s, %ux%u, against 16 tone-mapped samples per pixel (4x4 ordered grid, box filter in linear light):\n\n",
              api.c_str(), single.width, single.height);
  std::printf("| image | PSNR |\n|---|---|\n");
  std::printf("| 1 sample | %.2f dB |\n", facet::eval::psnr8(single.ldr, reference));
  for (auto& [name, backend] : msaa) {
    FrameResult r;
    if (!render(*backend, *scene, 1, 0, packages, &r, &error)) return fail(error);
    std::printf("| %s (%s) | %.2f dB |\n", name.c_str(), backend->msaaMethod().c_str(),
                facet::eval::psnr8(r.ldr, reference));
  }
  for (auto& [name, backend] : fxaa) {
    FrameResult r;
    if (!render(*backend, *scene, 1, 0, packages, &r, &error)) return fail(error);
    std::printf("| %s | %.2f dB |\n", name.c_str(), facet::eval::psnr8(r.ldr, reference));
  }
  std::printf("| 4 ordered samples, tone-mapped then averaged | %.2f dB |\n",
              facet::eval::psnr8(downsampleLdr(reference4, 2), reference));
  std::printf("| 4 ordered samples, averaged then tone-mapped (resolve first) | %.2f dB |\n",
              facet::eval::psnr8(resolveThenToneMap(reference4, 2), reference));
  std::printf("| 16 samples, averaged then tone-mapped (resolve first) | %.2f dB |\n\n",
              facet::eval::psnr8(resolveThenToneMap(reference16, 4), reference));

  // 3: the sweep.
  constexpr int kSteps = 16;
  // resolveFirst: each pixel's HDR samples averaged, then tone-mapped (scale > 1 only).
  const auto sweep = [&](RenderBackend& backend, uint32_t scale, std::vector<std::vector<uint8_t>>* frames,
                         bool resolveFirst = false) {
    for (int step = 0; step < kSteps; ++step) {
      FrameResult r;
      if (!render(backend, *scene, scale, double(step) / kSteps, packages, &r, &error)) return false;
      frames->push_back(scale == 1 ? r.ldr : resolveFirst ? resolveThenToneMap(r, scale) : downsampleLdr(r, scale));
    }
    return true;
  };
  // Mean over consecutive pairs of mean |frame k+1 − frame k|; and of mean |that change − the
  // reference's change|, per value: the part of the change the true motion does not explain.
  std::vector<std::vector<uint8_t>> truth;
  if (!sweep(*one, 4, &truth)) return fail(error);
  const auto report = [&](const char* what, const std::vector<std::vector<uint8_t>>& frames) {
    double change = 0, excess = 0;
    facet::supersample::flicker(frames, truth, &change, &excess);
    std::printf("| %s | %.4f | %.4f |\n", what, change, excess);
  };
  std::printf(
      "Flicker over %d camera positions 1/%d pixel apart: mean |frame-to-frame difference| and mean |that "
      "difference - the reference's| (8-bit steps):\n\n",
      kSteps, kSteps);
  std::printf("| image | frame-to-frame | beyond the reference's |\n|---|---|---|\n");
  std::vector<std::vector<uint8_t>> frames;
  if (!sweep(*one, 1, &frames)) return fail(error);
  report("1 sample", frames);
  for (auto& [name, backend] : msaa) {
    frames.clear();
    if (!sweep(*backend, 1, &frames)) return fail(error);
    report(name.c_str(), frames);
  }
  for (auto& [name, backend] : fxaa) {
    frames.clear();
    if (!sweep(*backend, 1, &frames)) return fail(error);
    report(name.c_str(), frames);
  }
  for (bool resolveFirst : {false, true}) {
    frames.clear();
    if (!sweep(*one, 2, &frames, resolveFirst)) return fail(error);
    report(resolveFirst ? "4 ordered samples, averaged then tone-mapped (resolve first)"
                        : "4 ordered samples, tone-mapped then averaged",
           frames);
  }
  report("reference (16 samples)", truth);

  // 4: render scale.
  std::printf("\nRender scale (one sample, the post pass upscaling bilinearly), PSNR:\n\n");
  std::printf("| render scale | against the full-size frame | against 16 samples |\n|---|---|---|\n");
  for (double scale : {0.75, 0.5}) {
    auto backend = makeBackend(api, 1, &error, false, {}, scale);
    if (!backend) return fail(error);
    FrameResult r;
    if (!render(*backend, *scene, 1, 0, packages, &r, &error)) return fail(error);
    std::printf("| %.2f (%ux%u) | %.2f dB | %.2f dB |\n", scale, r.hdrWidth, r.hdrHeight,
                facet::eval::psnr8(r.ldr, single.ldr), facet::eval::psnr8(r.ldr, reference));
    for (const std::string& e : backend->validationErrors()) return fail("validation: " + e);
  }
  for (const std::string& e : one->validationErrors()) return fail("validation: " + e);
  for (auto& [name, backend] : msaa)
    for (const std::string& e : backend->validationErrors()) return fail(name + ": validation: " + e);
  return 0;
}
