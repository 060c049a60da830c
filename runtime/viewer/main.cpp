// facet-view: renders a scene JSON headless to PNG with the Vulkan and/or GL backend.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "cascade_overlay.h"
#include "facet/package/atomic_file.h"
#include "facet/runtime/frame_graph.h"
#include "facet/runtime/png.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/render_path.h"
#include "facet/runtime/scene_frame.h"
#include "frame_stats.h"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "facet-view: error: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  facet::removeTemporaryFilesOnSignals();  // an interrupted PNG write leaves nothing behind
  CLI::App app{"facet-view: renders a Facet scene headless to PNG"};
  std::string scenePath, assetRoot, packageDir = ".", outDir = ".", backendName = "both", tier;
  bool validation = false, stats = false, keepHdr = false, json = false, decodeTextures = false, fxaa = false;
  size_t frames = 1, warmup = 2;
  bool oneDrawPerObject = false, shadowCascades = false;
  std::string postPathName = "auto", glContext = "auto", hdrFormatName = "rgba16f", msaaForm = "auto";
  uint32_t width = 0, height = 0, msaa = 0;
  double renderScale = 1.0;
  facet::runtime::BloomSettings bloom;
  app.add_option("scene", scenePath, "scene JSON")->required();
  app.add_option("--packages", packageDir, "folder holding <material>.matpkg files");
  app.add_option("--asset-root", assetRoot,
                 "folder the scene's images may come from (default: the scene's folder; images elsewhere are refused)");
  app.add_option("--out", outDir, "folder for the PNG files");
  app.add_option("--backend", backendName, "vulkan | gl | both")->check(CLI::IsMember({"vulkan", "gl", "both"}));
  app.add_option("--tier", tier, "render at this tier instead of the scene's (reference, high, mid, low)");
  app.add_flag("--validation", validation, "enable Vulkan validation layers; any validation error fails the run");
  app.add_option("--post-path", postPathName,
                 "auto | merged (post pass reads its own pixel in the same render pass) | separate (post samples the "
                 "stored HDR)")
      ->check(CLI::IsMember({"auto", "merged", "separate"}));
  app.add_option("--hdr-format", hdrFormatName, "rgba16f (default) | r11g11b10f (half the bytes, 6/6/5 mantissa bits)")
      ->check(CLI::IsMember({"rgba16f", "r11g11b10f"}));
  app.add_option("--msaa", msaa, "MSAA samples per pixel: 1 | 2 | 4 (default: the scene's \"antialiasing\", else 1)")
      ->check(CLI::IsMember({1, 2, 4}));
  app.add_option("--msaa-form", msaaForm,
                 "Vulkan: auto (VK_EXT_multisampled_render_to_single_sampled where offered) | attachments "
                 "(multisampled attachments; the merged path tone maps each sample) | resolve-first (the same, "
                 "reading the resolve)")
      ->check(CLI::IsMember({"auto", "attachments", "resolve-first"}));
  app.add_flag("--fxaa", fxaa, "an FXAA pass after the post pass (default: the scene's \"antialiasing\")");
  CLI::Option* bloomOption =
      app.add_option("--bloom", bloom.intensity,
                     "bloom of this intensity, 0..1 (default: the scene's \"post\": {\"bloom\"}, else none)");
  CLI::Option* bloomLevelsOption =
      app.add_option("--bloom-levels", bloom.levels, "with bloom: the chain's levels, 1..12 (each doubles the radius)");
  CLI::Option* bloomThresholdOption =
      app.add_option("--bloom-threshold", bloom.threshold, "with bloom: the brightness it starts from, 0 (none) up");
  CLI::Option* renderScaleOption = app.add_option(
      "--render-scale", renderScale,
      "render the forward pass at this fraction of the output size, 0.5..1, upscaled by the post pass (default: the "
      "scene's \"renderScale\", else 1)");
  app.add_flag("--keep-hdr", keepHdr, "also store HDR and read it back (debugging; HDR is then not transient)");
  app.add_option("--gl-context", glContext, "auto (EGL GLES, else OSMesa) | egl | osmesa")
      ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  app.add_option("--width", width, "render at this width instead of the scene's")->check(CLI::Range(1, 16384));
  app.add_option("--height", height, "render at this height instead of the scene's")->check(CLI::Range(1, 16384));
  app.add_flag("--stats", stats,
               "print per-pass GPU time (median over --frames after --warmup) and the frame graph: render passes, "
               "load/store ops, bytes loaded/stored per frame");
  app.add_flag("--json", json, "with --stats: print the statistics as JSON on stdout (other output goes to stderr)");
  app.add_option("--frames", frames, "frames to render and measure (the PNG is the last one)")
      ->check(CLI::Range(1, 100000));
  app.add_flag("--one-draw-per-object", oneDrawPerObject,
               "draw every object with its own call instead of instancing those that share all but the transform");
  app.add_flag("--decode-textures", decodeTextures,
               "GL: decode ASTC textures on the CPU even where the context samples ASTC (the fallback path)");
  app.add_flag("--shadow-cascades", shadowCascades,
               "tint the sun's shadow receivers by the cascade they read (red, green, blue, yellow: 0..3), an overlay "
               "from a CPU ray-cast of the scene (docs/shadows.md)");
  app.add_option("--warmup", warmup, "with --stats: frames rendered first and not measured (default 2)")
      ->check(CLI::Range(0, 1000));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  // Checked here, not by CLI::Range, which lets NaN through.
  if (renderScaleOption->count() && !facet::runtime::isRenderScale(renderScale)) {
    std::fprintf(stderr, "facet-view: error: %s\n",
                 facet::runtime::renderScaleError("--render-scale", renderScale).c_str());
    return 2;
  }

  if ((bloomLevelsOption->count() || bloomThresholdOption->count()) && !bloomOption->count()) {
    std::fprintf(stderr, "facet-view: error: --bloom-levels and --bloom-threshold need --bloom INTENSITY\n");
    return 2;
  }
  if (const std::string why = facet::runtime::bloomSettingsError("bloom", bloom);
      bloomOption->count() && !why.empty()) {
    std::fprintf(stderr, "facet-view: error: %s\n", why.c_str());
    return 2;
  }

  std::string error;
  auto scene = facet::runtime::loadScene(scenePath, &error, {.assetRoot = assetRoot});
  if (!scene) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  if (!tier.empty()) scene->tier = tier;
  if (width) scene->width = width;
  if (height) scene->height = height;
  if (msaa) scene->msaaSamples = msaa;
  if (fxaa) scene->fxaa = true;
  if (renderScaleOption->count()) scene->renderScale = renderScale;
  if (bloomOption->count()) {
    scene->post.bloom = true;
    scene->bloom = bloom;
  }
  auto prepared = facet::runtime::SceneFrame::prepare(*scene, packageDir, &error);
  if (!prepared) return fail(scenePath + ": " + error);
  if (shadowCascades && !prepared->frame().shadow)
    return fail(scenePath + ": --shadow-cascades: the scene's sun does not cast shadows (/sun/castShadows)");

  std::error_code ec;
  std::filesystem::create_directories(outDir, ec);
  if (ec) return fail("cannot create '" + outDir + "': " + ec.message());
  std::string stem = std::filesystem::path(scenePath).stem().string();
  if (!tier.empty()) stem += "." + tier;

  std::vector<std::string> backends;
  if (backendName == "both" || backendName == "vulkan") backends.push_back("vulkan");
  if (backendName == "both" || backendName == "gl") backends.push_back("gl");
  const facet::runtime::PostPath postPath = postPathName == "merged"     ? facet::runtime::PostPath::Merged
                                            : postPathName == "separate" ? facet::runtime::PostPath::Separate
                                                                         : facet::runtime::PostPath::Auto;
  const facet::runtime::HdrFormat hdrFormat = hdrFormatName == "r11g11b10f" ? facet::runtime::HdrFormat::R11G11B10Float
                                                                            : facet::runtime::HdrFormat::Rgba16Float;
  nlohmann::json report = nlohmann::json::array();
  for (const std::string& name : backends) {
    std::unique_ptr<facet::runtime::RenderBackend> backend;
    if (name == "vulkan") {
      facet::runtime::VulkanOptions options;
      options.validation = validation;
      options.postPath = postPath;
      options.readBackHdr = keepHdr;
      options.post = scene->post;
      options.hdrFormat = hdrFormat;
      options.msaaSamples = scene->msaaSamples;
      options.renderToSingleSampled = msaaForm == "auto";
      options.toneMapSamples = msaaForm != "resolve-first";
      options.fxaa = scene->fxaa;
      options.renderScale = scene->renderScale;
      options.bloom = scene->bloom;
      backend = facet::runtime::createVulkanBackend(options, &error);
    } else {
      facet::runtime::GlOptions options;
      options.context = glContext == "egl"      ? facet::runtime::GlContextKind::EglGles
                        : glContext == "osmesa" ? facet::runtime::GlContextKind::OsMesa
                                                : facet::runtime::GlContextKind::Auto;
      options.postPath = postPath;
      options.readBackHdr = keepHdr;
      options.post = scene->post;
      options.hdrFormat = hdrFormat;
      options.decodeCompressedTextures = decodeTextures;
      options.msaaSamples = scene->msaaSamples;
      options.fxaa = scene->fxaa;
      options.renderScale = scene->renderScale;
      options.bloom = scene->bloom;
      backend = facet::runtime::createGlBackend(options, &error);
    }
    if (!backend) return fail(name + ": " + error);
    facet::runtime::FrameResult result;
    std::vector<std::vector<facet::runtime::PassTime>> times;
    std::vector<double> cpuTimes;
    facet::runtime::FrameDesc frame = prepared->frame();
    if (oneDrawPerObject) frame.draws = facet::runtime::oneDrawPerInstance(frame.draws);
    // The shadow pass's draws: one per (cascade, caster that can shadow it), as the backends issue them.
    size_t casterDraws = 0;
    if (frame.shadow)
      for (const facet::runtime::ShadowCascadeDesc& c : frame.shadow->cascades) casterDraws += c.casters.size();
    const size_t total = frames + (stats ? warmup : 0);
    for (size_t i = 0; i < total; ++i) {
      if (!backend->render(frame, &result, &error)) return fail(name + ": " + error);
      if (i >= total - frames) {
        times.push_back(result.gpuTimes);
        cpuTimes.push_back(result.cpuSubmitMilliseconds);
      }
    }
    for (const std::string& message : backend->validationErrors())
      std::fprintf(stderr, "%s validation: %s\n", name.c_str(), message.c_str());
    if (!backend->validationErrors().empty()) return fail(name + ": validation reported errors");
    if (shadowCascades) {
      std::array<size_t, facet::abi::kMaxShadowCascades> pixels{};
      if (!facet::viewer::tintShadowCascades(*scene, prepared->frame().shadow->uniforms, &result.ldr, &pixels, &error))
        return fail(scenePath + ": " + error);
      std::fprintf(json ? stderr : stdout, "%s: receiver pixels per cascade: %zu, %zu, %zu, %zu\n", name.c_str(),
                   pixels[0], pixels[1], pixels[2], pixels[3]);
    }
    std::string path = (std::filesystem::path(outDir) / (stem + "." + name + ".png")).string();
    if (!facet::runtime::writePng(path, result.width, result.height, result.ldr, &error)) return fail(error);
    std::fprintf(json ? stderr : stdout, "%s: %s (%ux%u, variant %s, exposure %.3g)\n", name.c_str(), path.c_str(),
                 result.width, result.height, prepared->variantKey().c_str(), prepared->exposure());
    if (stats) {
      const facet::runtime::ForwardPostGraph graph = facet::runtime::buildForwardPostGraph(
          result.width, result.height, backend->postPath(), backend->readsBackHdr(), backend->hdrFormat(),
          backend->msaaSamples(), backend->fxaa(), backend->renderScale(), int(result.bloomLevels),
          prepared->frame().shadow ? prepared->frame().shadow->atlasSize : 0u, backend->toneMapsSamples());
      facet::runtime::fg::CompiledGraph compiled;
      if (!graph.graph.compile(&compiled, &error)) return fail(name + ": frame graph: " + error);
      const std::vector<facet::viewer::MedianTime> medians = facet::viewer::medianTimes(times);
      if (json) {
        nlohmann::json entry = facet::viewer::statsJson(graph.graph, compiled, medians, times.size());
        entry["backend"] = name;
        entry["path"] = facet::runtime::toString(backend->postPath());
        entry["hdrFormat"] = facet::runtime::toString(backend->hdrFormat());
        entry["msaa"] = backend->msaaSamples();
        entry["msaaMethod"] = backend->msaaMethod();
        entry["fxaa"] = backend->fxaa();
        entry["renderScale"] = backend->renderScale();
        entry["bloomLevels"] = result.bloomLevels;
        entry["width"] = result.width;
        entry["height"] = result.height;
        entry["scene"] = scenePath;
        entry["draws"] = frame.draws.size();
        entry["shadowCasterDraws"] = casterDraws;
        entry["shadowCascades"] = frame.shadow ? frame.shadow->cascades.size() : 0;
        entry["cpuSubmitMs"] = facet::viewer::median(cpuTimes);
        report.push_back(std::move(entry));
      } else {
        const std::string scaled = backend->renderScale() < 1.0
                                       ? ", forward pass at " + std::to_string(result.hdrWidth) + "x" +
                                             std::to_string(result.hdrHeight) + " (render scale " +
                                             nlohmann::json(backend->renderScale()).dump() + ")"
                                       : std::string();
        std::printf("%s: %s path, %s HDR, frame graph at %ux%u%s, MSAA %ux (%s)%s:\n%s", name.c_str(),
                    facet::runtime::toString(backend->postPath()), facet::runtime::toString(backend->hdrFormat()),
                    result.width, result.height, scaled.c_str(), backend->msaaSamples(), backend->msaaMethod().c_str(),
                    (std::string(backend->fxaa() ? ", FXAA" : "") +
                     (result.bloomLevels ? ", bloom of " + std::to_string(result.bloomLevels) + " levels" : ""))
                        .c_str(),
                    facet::viewer::statsText(graph.graph, compiled, medians, times.size()).c_str());
        std::printf("  %zu draw calls; CPU issuing the frame (FrameResult::cpuSubmitMilliseconds): median %.3f ms\n",
                    frame.draws.size(), facet::viewer::median(cpuTimes));
        if (frame.shadow)
          std::printf("  shadow pass: %zu caster draws over %zu cascades (%u² atlas)\n", casterDraws,
                      frame.shadow->cascades.size(), frame.shadow->atlasSize);
      }
    }
  }
  if (stats && json) std::printf("%s\n", report.dump(2).c_str());
  return 0;
}
