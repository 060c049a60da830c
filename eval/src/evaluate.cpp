#include "facet/eval/evaluate.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include "facet/compiler/build.h"
#include "facet/package.h"
#include "facet/render_backend.h"
#include "facet/runtime/png.h"
#include "facet/eval/prepared_frame.h"
#include "facet/runtime/scene_frame.h"

namespace facet::eval {
namespace {

namespace fs = std::filesystem;
using permutations::TierConfig;

struct View {
  std::string name;
  runtime::Scene scene;
};

std::vector<uint32_t> wordsOf(const package::Shader& s) {
  std::vector<uint32_t> w(s.code.size() / 4);
  std::memcpy(w.data(), s.code.data(), w.size() * 4);
  return w;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Removes the folder it names when it goes out of scope.
struct TempDir {
  fs::path path;
  ~TempDir() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

void markPareto(std::vector<ConfigurationResult>* results) {
  for (ConfigurationResult& a : *results) {
    a.pareto = true;
    for (const ConfigurationResult& b : *results) {
      const bool noWorse = b.fragment.cycles <= a.fragment.cycles && b.error.psnr >= a.error.psnr;
      const bool better = b.fragment.cycles < a.fragment.cycles || b.error.psnr > a.error.psnr;
      if (noWorse && better) {
        a.pareto = false;
        break;
      }
    }
  }
}

std::string formatProgress(size_t index, size_t count, const ConfigurationResult& r) {
  char buf[256];
  std::string psnr = std::isinf(r.error.psnr) ? "identical" : [&] {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f dB", r.error.psnr);
    return std::string(b);
  }();
  std::snprintf(buf, sizeof buf, "[%zu/%zu] %-34s %-10s %5.2f cycles  %6.1f ms%s", index + 1, count,
                r.configuration.name.c_str(), psnr.c_str(), r.fragment.cycles, 1000.0 * r.seconds,
                r.sameAs.empty() ? "" : ("  (same maths as " + r.sameAs + ")").c_str());
  return buf;
}

}  // namespace

std::optional<EvalReport> evaluate(const ir::Material& material, const EvalOptions& options, EvalError* error) {
  EvalReport report;
  report.material = material.name;
  report.timingFrames = std::max(options.timingFrames, 0);
  report.warmupFrames = std::max(options.warmupFrames, 1);
  report.fp16Emulation = options.fp16Emulation;
  report.weights = options.weights;

  // The views: the built-in grid, or the scene file's objects of this material.
  std::vector<View> views;
  if (options.sceneFile.empty()) {
    report.scene = "built-in evaluation grid";
    for (GridView& v : evaluationGrid(material, options.grid)) views.push_back({v.name, std::move(v.scene)});
    report.sceneNotes = describeSweep(material, options.grid);
  } else {
    report.scene = options.sceneFile;
    auto scene = runtime::loadScene(options.sceneFile, &error->message);
    if (!scene) return std::nullopt;
    const size_t before = scene->objects.size();
    std::erase_if(scene->objects, [&](const runtime::SceneObject& o) { return o.material != material.name; });
    if (scene->objects.empty()) {
      error->message = options.sceneFile + ": no object of the scene uses material '" + material.name + "'";
      return std::nullopt;
    }
    if (scene->objects.size() < before)
      report.sceneNotes.push_back(std::to_string(before - scene->objects.size()) +
                                  " object(s) of other materials left out: matc eval renders one material");
    views.push_back({fs::path(options.sceneFile).stem().string(), std::move(*scene)});
  }
  for (const View& v : views) report.viewNames.push_back(v.name);
  report.width = views[0].scene.width;
  report.height = views[0].scene.height;

  std::string message;
  std::unique_ptr<runtime::RenderBackend> backend = runtime::createVulkanBackend({options.validation}, &message);
  if (!backend) {
    error->message = "no Vulkan device to render on (matc eval renders with lavapipe): " + message;
    return std::nullopt;
  }

  std::error_code ec;
  const fs::path imageDir = fs::path(options.outDir) / "images";
  fs::create_directories(imageDir, ec);
  if (ec) {
    error->message = "cannot create '" + imageDir.string() + "': " + ec.message();
    return std::nullopt;
  }
  TempDir work;
  work.path = fs::temp_directory_path(ec) / ("facet-eval-" + std::to_string(getpid()));
  fs::remove_all(work.path, ec);
  fs::create_directories(work.path, ec);
  if (ec) {
    error->message = "cannot create a temporary folder '" + work.path.string() + "': " + ec.message();
    return std::nullopt;
  }


  // Timing: render() of the first view, timingFrames times, each paired with a render() of the
  // reference's first view, so that the ratio of the two (the median of the per-pair ratios) sees
  // the same machine load; the reference alone for the reference.
  std::unique_ptr<PreparedFrame> referenceFrame;
  auto timeFrame = [&](const Configuration& c, const runtime::FrameDesc& frame, ConfigurationResult* r, EvalError* failure) {
    std::vector<double> mine, ratios;
    runtime::FrameResult scratch;
    auto timed = [&](const runtime::FrameDesc& f, double* seconds) {
      auto t0 = std::chrono::steady_clock::now();
      bool ok = backend->render(f, &scratch, &message);
      *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!ok) failure->message = c.name + ": render failed: " + message;
      return ok;
    };
    for (int t = 0; t < report.timingFrames; ++t) {
      double own = 0, ref = 0;
      if (!timed(frame, &own)) return false;
      if (referenceFrame && !timed(referenceFrame->frame(), &ref)) return false;
      mine.push_back(own);
      ratios.push_back(referenceFrame && ref > 0 ? own / ref : 1.0);
    }
    r->seconds = median(mine);
    r->timeVsReference = report.timingFrames > 0 ? median(ratios) : 0.0;
    return true;
  };

  const std::vector<Configuration> configs = configurations(material, options.tiers, options.swaps);
  const permutations::MaterialNeeds needs{material.shading == "lit"};
  std::vector<runtime::FrameResult> referenceFrames;  // per view
  std::vector<std::array<float, 3>> backgrounds;      // per view: the clear colour

  for (size_t i = 0; i < configs.size(); ++i) {
    const Configuration& c = configs[i];
    ConfigurationResult r;
    r.configuration = c;
    // Identical maths (e.g. high with energy compensation = reference in mediump): the same shaders
    // and images, measured once.
    auto same = std::find_if(report.results.begin(), report.results.end(),
                             [&](const ConfigurationResult& e) { return e.configuration.config == c.config && e.sameAs.empty(); });
    if (same != report.results.end()) {
      r = *same;
      r.configuration = c;
      r.sameAs = same->configuration.name;
      report.results.push_back(r);
      if (options.progress) options.progress(formatProgress(i, configs.size(), r));
      continue;
    }

    compiler::BuildOptions build;
    build.tiers = {c.tier};
    build.fp16Emulation = options.fp16Emulation;
    build.adjustTier = [config = c.config](permutations::Tier, TierConfig* t) { *t = config; };
    permutations::SceneNeeds sceneNeeds;
    for (const View& v : views) {
      auto key = permutations::requestKey(needs, c.tier, v.scene.sun.has_value(), int(v.scene.lights.size()));
      if (std::find(sceneNeeds.keys.begin(), sceneNeeds.keys.end(), key) == sceneNeeds.keys.end()) sceneNeeds.keys.push_back(key);
    }
    build.scene = sceneNeeds;
    r.variantKey = sceneNeeds.keys[0].toString();
    compiler::BuildError buildError;
    auto built = compiler::buildMaterial(material, build, &buildError);
    if (!built) {
      error->message = c.name + ": " + buildError.message;
      error->loc = buildError.loc;
      return std::nullopt;
    }
    const fs::path packageDir = work.path / fileStem(c.name);
    fs::create_directories(packageDir, ec);
    const std::string packagePath = (packageDir / (material.name + ".matpkg")).string();
    if (!package::writeFile(packagePath, package::write(built->package), &error->message)) return std::nullopt;

    // Cost of the variant the (first) view renders.
    for (const package::Variant& v : built->package.variants) {
      if (v.key != r.variantKey) continue;
      for (const package::Shader& s : v.shaders) {
        if (s.target != package::Target::Spirv) continue;
        compiler::MobileStageCost* cost = s.stage == package::Stage::Fragment ? &r.fragment : &r.vertex;
        if (!compiler::estimateMobileCost(wordsOf(s), cost, &error->message, options.weights)) {
          error->message = c.name + ": " + error->message;
          return std::nullopt;
        }
      }
    }

    ErrorAccumulator all;
    for (size_t vi = 0; vi < views.size(); ++vi) {
      runtime::Scene scene = views[vi].scene;
      scene.tier = permutations::toString(c.tier);
      std::unique_ptr<PreparedFrame> prepared = PreparedFrame::prepare(scene, packageDir.string(), c.config, &message);
      if (!prepared) {
        error->message = c.name + ": " + message;
        return std::nullopt;
      }
      const runtime::FrameDesc& frame = prepared->frame();
      runtime::FrameResult image;
      for (int w = 0; w < report.warmupFrames; ++w) {
        if (!backend->render(frame, &image, &message)) {
          error->message = c.name + ": render failed: " + message;
          return std::nullopt;
        }
      }
      if (vi == 0 && !timeFrame(c, frame, &r, error)) return std::nullopt;
      if (!backend->validationErrors().empty()) {
        error->message = c.name + ": Vulkan validation reported: " + backend->validationErrors().front();
        return std::nullopt;
      }
      const std::array<float, 3> background = {frame.clearColor[0], frame.clearColor[1], frame.clearColor[2]};
      // The reference's first view is kept for the timing of every later configuration.
      if (i == 0 && vi == 0) referenceFrame = std::move(prepared);
      ViewResult view;
      view.name = views[vi].name;
      view.image = (fs::path("images") / (fileStem(c.name) + "." + view.name + ".png")).string();
      if (!runtime::writePng((fs::path(options.outDir) / view.image).string(), image.width, image.height, image.ldr,
                             &message)) {
        error->message = message;
        return std::nullopt;
      }
      if (i == 0) {
        backgrounds.push_back(background);
        referenceFrames.push_back(std::move(image));
      }
      const runtime::FrameResult& ref = referenceFrames[vi];
      const runtime::FrameResult& mine = i == 0 ? referenceFrames[vi] : image;
      std::vector<bool> mask = coverageMask(mine.hdr, ref.hdr, backgrounds[vi]);
      ErrorAccumulator one;
      one.add(mine.ldr, ref.ldr, mine.hdr, ref.hdr, mask);
      all.add(mine.ldr, ref.ldr, mine.hdr, ref.hdr, mask);
      view.error = one.metrics();
      r.views.push_back(std::move(view));
    }
    r.error = all.metrics();
    report.results.push_back(std::move(r));
    if (options.progress) options.progress(formatProgress(i, configs.size(), report.results.back()));
  }

  // Ratios to the tiers as shipped.
  auto shipped = [&](permutations::Tier t) -> const ConfigurationResult* {
    for (const ConfigurationResult& r : report.results)
      if (!r.configuration.swap() && r.configuration.tier == t) return &r;
    return nullptr;
  };
  const ConfigurationResult* reference = shipped(permutations::Tier::Reference);
  const ConfigurationResult* high = shipped(permutations::Tier::High);
  auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
  const double referenceCycles = reference->fragment.cycles;
  const double highCycles = high ? high->fragment.cycles : 0;
  for (ConfigurationResult& r : report.results) {
    r.cyclesVsReference = ratio(r.fragment.cycles, referenceCycles);
    r.cyclesVsHigh = ratio(r.fragment.cycles, highCycles);
  }
  markPareto(&report.results);
  return report;
}

}  // namespace facet::eval
