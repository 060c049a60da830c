#include "facet/eval/evaluate.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <future>
#include <limits>
#include <map>
#include <optional>

#include "facet/compiler/build.h"
#include "facet/eval/prepared_frame.h"
#include "facet/gpu_stats/package_pairs.h"
#include "facet/package/package.h"
#include "facet/runtime/png.h"
#include "facet/runtime/render_backend.h"
#include "facet/scene/scene.h"

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
  char psnr[32] = "identical";
  if (!std::isinf(r.error.psnr)) std::snprintf(psnr, sizeof psnr, "%.1f dB", r.error.psnr);
  char line[256];
  std::snprintf(line, sizeof line, "[%zu/%zu] %-34s %-10s %5.2f cycles  %6.1f ms", index + 1, count,
                r.configuration.name.c_str(), psnr, r.fragment.cycles, 1000.0 * r.seconds);
  return r.sameAs.empty() ? line : std::string(line) + "  (same maths as " + r.sameAs + ")";
}

// One evaluation: the views, the Vulkan backend, and what later configurations are measured
// against (the reference's images, and its first view for paired timing).
class Evaluation {
 public:
  Evaluation(const ir::Material& material, const EvalOptions& options, std::vector<View> views,
             std::unique_ptr<runtime::RenderBackend> backend, fs::path workDir)
      : material_(material),
        options_(options),
        views_(std::move(views)),
        backend_(std::move(backend)),
        workDir_(std::move(workDir)) {}

  // Builds, costs, renders and compares one configuration; the first must be the reference.
  // The cost model's figures only (costFragment, costVertex), built without rendering: what
  // `matc tune` orders and prunes its candidates by. Safe to call from several threads at once.
  bool costOnly(const Configuration& c, ConfigurationResult* r, EvalError* error) const {
    r->configuration = c;
    std::optional<compiler::BuildResult> built = build(c, false, Variants::Cost, &r->variantKey, error);
    return built && cost(built->package, r, error);
  }

  bool measure(const Configuration& c, bool isReference, ConfigurationResult* r, EvalError* error,
               const MeasureOptions& how = {}) {
    r->configuration = c;
    // With the cost given, only the views' variants: the furnace's is built when it is rendered.
    const Variants variants = how.costed ? Variants::Views : Variants::All;
    std::optional<compiler::BuildResult> built =
        how.costed ? aheadOrBuild(c, &r->variantKey, error)
                   : build(c, options_.fp16Emulation, variants, &r->variantKey, error);
    const fs::path packageDir = workDir_ / fileStem(c.name);
    if (!built || !writePackage(built->package, packageDir, error)) return false;

    // The cost of the variant the (first) view renders, as shipped: an fp16-emulation build's
    // SPIR-V is quantized before spirv-opt and costs what no device runs, so the cost comes from
    // the same configuration built without it.
    if (how.costed) {
      r->fragment = how.costed->fragment;
      r->vertex = how.costed->vertex;
      r->costFragment = how.costed->costFragment;
      r->costVertex = how.costed->costVertex;
      r->sunIblFragmentCycles = how.costed->sunIblFragmentCycles;
    } else {
      std::optional<compiler::BuildResult> shipped;
      if (options_.fp16Emulation && !(shipped = build(c, false, Variants::All, &r->variantKey, error))) return false;
      if (!cost(shipped ? shipped->package : built->package, r, error)) return false;
    }

    ErrorAccumulator all, truthError;
    // The renders of the same bytes so far, view by view (MeasureOptions::reuseIdenticalViews).
    std::vector<RenderedView>* same = nullptr;
    if (how.reuseIdenticalViews && !isReference && !how.images && options_.timingFrames <= 0 && groundTruth_.empty())
      same = &renderedViews_[renderedBytes(built->package, c.config)];
    for (size_t vi = 0; vi < views_.size(); ++vi) {
      if (same && vi < same->size()) {
        r->views.push_back((*same)[vi].view);
        r->views.back().image = (fs::path("images") / (fileStem(c.name) + "." + views_[vi].name + ".png")).string();
        all = (*same)[vi].allSoFar;
        ++r->viewsReused;
      } else if (!renderView(c, vi, isReference, how, packageDir, r, &all, &truthError, error)) {
        return false;
      } else if (same) {
        same->push_back({r->views.back(), all});
      }
      if (how.worthFinishing && !isReference && vi + 1 < views_.size()) {
        // A view compares at most as many pixels as reference's image of it has.
        size_t rest = 0;
        for (size_t later = vi + 1; later < views_.size(); ++later) rest += referenceImages_[later].ldr.size() / 4;
        const double bound = all.psnrAtMost(rest);
        if (!how.worthFinishing(bound)) {
          r->error = all.metrics();
          r->psnrAtMost = bound;
          r->furnaceGain = std::numeric_limits<double>::quiet_NaN();
          return true;
        }
      }
    }
    r->error = all.metrics();
    if (!groundTruth_.empty()) r->groundTruthError = truthError.metrics();
    if (material_.shading != "lit") return true;
    if (how.furnaceWanted && !how.furnaceWanted(*r)) {
      r->furnaceGain = std::numeric_limits<double>::quiet_NaN();
      return true;
    }
    if (variants == Variants::All) return furnace(c, packageDir, r, error);
    std::string furnaceKey;
    std::optional<compiler::BuildResult> lights =
        build(c, options_.fp16Emulation, Variants::Furnace, &furnaceKey, error);
    return lights && writePackage(lights->package, packageDir / "furnace", error) &&
           furnace(c, packageDir / "furnace", r, error);
  }

  // Starts measure()'s build of a configuration given its cost (Variants::Views) on a thread of its
  // own, one core, so that it overlaps the renders before it; measure() takes it from there. Two
  // are kept: the one measure() is about to take and this one. An older one nobody took is
  // waited for and dropped.
  void buildAhead(const Configuration& c) {
    for (const AheadBuild& a : ahead_)
      if (sameConfiguration(a.configuration, c)) return;
    if (ahead_.size() == 2) ahead_.erase(ahead_.begin());  // std::future's destructor waits for its thread
    ahead_.emplace_back(c, std::async(std::launch::async, [this, c] {
                          AheadBuild::Outcome o;
                          o.built = build(c, options_.fp16Emulation, Variants::Views, &o.firstKey, &o.error, 1);
                          return o;
                        }));
  }

  // One view rendered and scored against reference's (the reference's own image kept), added to
  // *all (and *truthError where the ground truth was rendered).
  bool renderView(const Configuration& c, size_t vi, bool isReference, const MeasureOptions& how,
                  const fs::path& packageDir, ConfigurationResult* r, ErrorAccumulator* all,
                  ErrorAccumulator* truthError, EvalError* error) {
    runtime::Scene scene = views_[vi].scene;
    scene.tier = permutations::toString(c.tier);
    if (isReference) scene.shadows.atlasSize = kReferenceShadowAtlas;
    std::string message;
    std::unique_ptr<PreparedFrame> prepared = PreparedFrame::prepare(scene, packageDir.string(), c.config, &message);
    if (!prepared) return fail(c, message, error);
    const runtime::FrameDesc& frame = prepared->frame();
    runtime::FrameResult image;
    for (int w = 0; w < std::max(options_.warmupFrames, 1); ++w)
      if (!backend_->render(frame, &image, &message)) return fail(c, "render failed: " + message, error);
    if (vi == 0 && !time(c, frame, r, error)) return false;
    if (!backend_->validationErrors().empty())
      return fail(c, "Vulkan validation reported: " + backend_->validationErrors().front(), error);

    ViewResult view;
    view.name = views_[vi].name;
    view.image = (fs::path("images") / (fileStem(c.name) + "." + view.name + ".png")).string();
    if (how.images && !runtime::encodePng(image.width, image.height, image.ldr, &view.png, &message))
      return fail(c, message, error);
    const runtime::FrameResult* measured = &image;
    if (isReference) {
      if (backgrounds_.size() == vi)
        backgrounds_.push_back({frame.clearColor[0], frame.clearColor[1], frame.clearColor[2]});
      referenceImages_.push_back(std::move(image));
      measured = &referenceImages_.back();
      if (vi == 0) referenceFrame_ = std::move(prepared);  // for the paired timing of the others
    }
    const runtime::FrameResult& ref = referenceImages_[vi];
    const runtime::FrameResult& mine = *measured;
    std::vector<bool> mask = coverageMask(mine.hdr, ref.hdr, backgrounds_[vi]);
    ErrorAccumulator one;
    one.add(mine.ldr, ref.ldr, mine.hdr, ref.hdr, mask);
    all->add(mine.ldr, ref.ldr, mine.hdr, ref.hdr, mask);
    view.error = one.metrics();
    r->views.push_back(std::move(view));
    if (!groundTruth_.empty()) {
      const runtime::FrameResult& truth = groundTruth_[vi];
      truthError->add(mine.ldr, truth.ldr, mine.hdr, truth.hdr, coverageMask(mine.hdr, truth.hdr, backgrounds_[vi]));
    }
    return true;
  }

  // The ground truth (EvalOptions::groundTruthSamples): `reference` as shipped with its ambient
  // integrated by importance sampling, kept per view; the same at a quarter of the samples against
  // it bounds the truth's own error (quasi-Monte Carlo error falls about as 1/N, so the truth's is
  // about a quarter of that figure). Before any configuration is measured, so that every one is
  // compared with it.
  bool renderGroundTruth(const Configuration& reference, ImageMetrics* convergence, std::vector<ViewResult>* views,
                         EvalError* error) {
    std::vector<runtime::FrameResult> coarse;
    const int samples = options_.groundTruthSamples;
    if (!renderSampled(reference, std::max(samples / 4, 1), &coarse, error) ||
        !renderSampled(reference, samples, &groundTruth_, error))
      return false;
    ErrorAccumulator change;
    for (size_t vi = 0; vi < views_.size(); ++vi) {
      const runtime::FrameResult& truth = groundTruth_[vi];
      const std::vector<bool> mask = coverageMask(coarse[vi].hdr, truth.hdr, backgrounds_[vi]);
      change.add(coarse[vi].ldr, truth.ldr, coarse[vi].hdr, truth.hdr, mask);
      ViewResult view;
      view.name = views_[vi].name;
      view.image = (fs::path("images") / ("ground_truth." + view.name + ".png")).string();
      std::string message;
      if (!runtime::encodePng(truth.width, truth.height, truth.ldr, &view.png, &message))
        return fail(reference, message, error);
      ErrorAccumulator one;
      one.add(coarse[vi].ldr, truth.ldr, coarse[vi].hdr, truth.hdr, mask);
      view.error = one.metrics();
      views->push_back(std::move(view));
    }
    *convergence = change.metrics();
    return true;
  }

  // Which clock the timings used (EvalReport::timingClock); empty when nothing was timed.
  std::string timingClock() const {
    if (!gpuClock_) return "";
    return *gpuClock_ ? "gpu_forward_pass" : "wall_render";
  }

 private:
  // The white furnace: the first view's spheres, no sun and no point light, in a constant sky of
  // kFurnaceLuminance; the brightest value the spheres cover (the pixels that differ from the
  // background, which is the sky) ÷ the sky's pre-exposed radiance.
  static constexpr double kFurnaceLuminance = 5000;  // cd/m², about a bright overcast sky
  bool furnace(const Configuration& c, const fs::path& packageDir, ConfigurationResult* r, EvalError* error) {
    runtime::Scene scene = views_[0].scene;
    scene.tier = permutations::toString(c.tier);
    scene.sun.reset();
    scene.lights.clear();
    scene.environment.reset();
    scene.skyLuminance = kFurnaceLuminance;
    std::string message;
    std::unique_ptr<PreparedFrame> prepared = PreparedFrame::prepare(scene, packageDir.string(), c.config, &message);
    if (!prepared) return fail(c, "white furnace: " + message, error);
    runtime::FrameResult image;
    if (!backend_->render(prepared->frame(), &image, &message))
      return fail(c, "white furnace: render failed: " + message, error);
    const float* clear = prepared->frame().clearColor;
    const std::vector<bool> covered = coverageMask(image.hdr, image.hdr, {clear[0], clear[1], clear[2]});
    r->furnaceGain = furnaceGain(image.hdr, kFurnaceLuminance * prepared->exposure(), covered);
    return true;
  }

  // Every view of `reference` with AmbientModel::Sampled at `samples` points per integral; also
  // records each view's background (the clear colour), which the reference's images share.
  bool renderSampled(Configuration c, int samples, std::vector<runtime::FrameResult>* images, EvalError* error) {
    c.config.ambient = permutations::AmbientModel::Sampled;
    c.config.ambientSamples = samples;
    c.name = "ground_truth." + std::to_string(samples);
    std::string key;
    std::optional<compiler::BuildResult> built = build(c, false, Variants::All, &key, error);
    if (!built) return false;
    const fs::path packageDir = workDir_ / c.name;
    std::error_code ec;
    fs::create_directories(packageDir, ec);
    if (!package::writeFile((packageDir / (material_.name + ".matpkg")).string(), package::write(built->package),
                            &error->message))
      return false;
    backgrounds_.clear();
    images->clear();
    for (const View& v : views_) {
      runtime::Scene scene = v.scene;
      scene.tier = permutations::toString(c.tier);
      scene.shadows.atlasSize = kReferenceShadowAtlas;  // the ground truth is reference's
      std::string message;
      std::unique_ptr<PreparedFrame> prepared = PreparedFrame::prepare(scene, packageDir.string(), c.config, &message);
      if (!prepared) return fail(c, message, error);
      runtime::FrameResult image;
      if (!backend_->render(prepared->frame(), &image, &message)) return fail(c, "render failed: " + message, error);
      if (!backend_->validationErrors().empty())
        return fail(c, "Vulkan validation reported: " + backend_->validationErrors().front(), error);
      const float* clear = prepared->frame().clearColor;
      backgrounds_.push_back({clear[0], clear[1], clear[2]});
      images->push_back(std::move(image));
    }
    return true;
  }

  static bool fail(const Configuration& c, const std::string& message, EvalError* error) {
    error->message = c.name + ": " + message;
    return false;
  }

  bool writePackage(const package::Package& pkg, const fs::path& dir, EvalError* error) const {
    std::error_code ec;
    fs::create_directories(dir, ec);
    return package::writeFile((dir / (material_.name + ".matpkg")).string(), package::write(pkg), &error->message);
  }

  // A build started by buildAhead(): the same bytes build() would give, computed earlier.
  struct AheadBuild {
    struct Outcome {
      std::optional<compiler::BuildResult> built;
      std::string firstKey;
      EvalError error;
    };
    AheadBuild(Configuration c, std::future<Outcome> f) : configuration(std::move(c)), outcome(std::move(f)) {}
    Configuration configuration;
    std::future<Outcome> outcome;
  };

  static bool sameConfiguration(const Configuration& a, const Configuration& b) {
    return a.name == b.name && a.tier == b.tier && a.config == b.config;
  }

  // measure()'s build of a configuration given its cost: buildAhead()'s when it started this one.
  std::optional<compiler::BuildResult> aheadOrBuild(const Configuration& c, std::string* firstKey, EvalError* error) {
    auto a = std::find_if(ahead_.begin(), ahead_.end(),
                          [&](const AheadBuild& b) { return sameConfiguration(b.configuration, c); });
    if (a == ahead_.end()) return build(c, options_.fp16Emulation, Variants::Views, firstKey, error);
    AheadBuild::Outcome o = a->outcome.get();
    ahead_.erase(a);
    *firstKey = std::move(o.firstKey);
    if (!o.built) *error = std::move(o.error);
    return std::move(o.built);
  }

  // Which of a configuration's variants a build makes. All: the views', the sun + IBL variant
  // <tier>.dir1 the cost goals refer to, and (lit materials) the white furnace's. Cost: <tier>.dir1
  // alone. Views and Furnace: the views' alone, the furnace's alone.
  enum class Variants { All, Cost, Views, Furnace };

  // The configuration's package: its tier only, the variants asked for. *firstKey: the first
  // view's variant (Cost: <tier>.dir1; Furnace: the furnace's).
  // jobs: BuildOptions::jobs (0: as many as the machine has; Cost always builds on one).
  std::optional<compiler::BuildResult> build(const Configuration& c, bool fp16Emulation, Variants variants,
                                             std::string* firstKey, EvalError* error, unsigned jobs = 0) const {
    compiler::BuildOptions options;
    options.tiers = {c.tier};
    options.cacheDir = options_.cacheDir;
    options.jobs = variants == Variants::Cost ? 1 : jobs;
    options.fp16Emulation = fp16Emulation;
    // The renderer and the cost model read SPIR-V; the GLSL ES is read only by the Mesa figures
    // (addGpuFigures), from the package measure() costs: the one built with everything, unemulated.
    options.spirvOnly = fp16Emulation || variants != Variants::All;
    options.adjustTier = [config = c.config](permutations::Tier, TierConfig* t) { *t = config; };
    const permutations::MaterialNeeds needs{material_.shading == "lit",
                                            permutations::blendingCastsShadows(material_.blending)};
    permutations::SceneNeeds scene;
    auto add = [&](const permutations::VariantKey& key) {
      if (std::find(scene.keys.begin(), scene.keys.end(), key) == scene.keys.end()) scene.keys.push_back(key);
    };
    if (variants == Variants::All || variants == Variants::Views)
      for (const View& v : views_) {
        // The receivers and the casters' depth-only programs of a view whose sun or spot casts, as
        // `matc compile --scene` builds them (every object of the view is this material's).
        const int cascades = int(runtime::sunShadowCascades(v.scene));
        const bool spotCasts = !runtime::shadowSpotLights(v.scene).empty();
        for (const runtime::SceneObject& o : v.scene.objects) {
          add(permutations::requestKey(needs, c.tier, v.scene.sun.has_value(), int(v.scene.lights.size()),
                                       o.receiveShadows ? cascades : 0, o.receiveShadows && spotCasts));
          if ((cascades > 0 || spotCasts) && o.castShadows && needs.castsShadows) add(permutations::depthKey(c.tier));
        }
      }
    if (variants == Variants::All || variants == Variants::Cost) add(permutations::requestKey(needs, c.tier, true, 0));
    if (needs.lit && (variants == Variants::All || variants == Variants::Furnace))
      add(permutations::requestKey(needs, c.tier, false, 0));  // the white furnace
    *firstKey = scene.keys[0].toString();
    options.scene = scene;
    compiler::BuildError buildError;
    auto built = compiler::buildMaterial(material_, options, &buildError);
    if (!built) {
      error->message = c.name + ": " + buildError.message;
      error->loc = buildError.loc;
    }
    return built;
  }

  bool cost(const package::Package& pkg, ConfigurationResult* r, EvalError* error) const {
    const std::string sunIbl =
        permutations::requestKey({material_.shading == "lit"}, r->configuration.tier, true, 0).toString();
    for (const package::Variant& v : pkg.variants) {
      if (v.key != r->variantKey && v.key != sunIbl) continue;
      for (const package::Shader& s : v.shaders) {
        if (s.target != package::Target::Spirv) continue;
        compiler::MobileStageCost cost;
        if (!compiler::estimateMobileCost(wordsOf(s), &cost, &error->message, options_.weights))
          return fail(r->configuration, error->message, error);
        if (v.key == r->variantKey) (s.stage == package::Stage::Fragment ? r->fragment : r->vertex) = cost;
        if (v.key == sunIbl) (s.stage == package::Stage::Fragment ? r->costFragment : r->costVertex) = cost;
        if (v.key == sunIbl && s.stage == package::Stage::Fragment) r->sunIblFragmentCycles = cost.cycles;
      }
    }
    r->glslEs = gpu_stats::glslEsPairs(pkg, {r->variantKey});
    return true;
  }

  // render() of the first view, timingFrames times, each paired with a render() of the reference's
  // first view, so that their ratio (the median of the per-pair ratios) sees the same machine
  // load; the reference alone for the reference.
  bool time(const Configuration& c, const runtime::FrameDesc& frame, ConfigurationResult* r, EvalError* error) {
    std::vector<double> own, ratios;
    runtime::FrameResult scratch;
    std::string message;
    // The forward pass's GPU time where the backend reports it (Vulkan timestamps, on lavapipe
    // too): the material's draws and nothing else. Else the wall time of render(), which also
    // holds the post pass, the submission and the read-back. The clock is chosen at the first
    // timed frame and kept for the run, so that every ratio compares like with like.
    auto timed = [&](const runtime::FrameDesc& f, double* seconds) {
      auto t0 = std::chrono::steady_clock::now();
      bool ok = backend_->render(f, &scratch, &message);
      *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!ok) return false;
      auto forward = std::find_if(scratch.gpuTimes.begin(), scratch.gpuTimes.end(),
                                  [](const runtime::PassTime& t) { return t.pass == "forward"; });
      if (!gpuClock_) gpuClock_ = forward != scratch.gpuTimes.end();
      if (*gpuClock_) {
        if (forward == scratch.gpuTimes.end()) {
          message = "the forward pass's GPU time was reported for earlier frames and not for this one";
          return false;
        }
        *seconds = forward->milliseconds * 1e-3;
      }
      return true;
    };
    for (int t = 0; t < options_.timingFrames; ++t) {
      double mine = 0, reference = 0;
      if (!timed(frame, &mine) || (referenceFrame_ && !timed(referenceFrame_->frame(), &reference)))
        return fail(c, "render failed: " + message, error);
      own.push_back(mine);
      ratios.push_back(referenceFrame_ && reference > 0 ? mine / reference : 1.0);
    }
    r->seconds = median(own);
    r->timeVsReference = options_.timingFrames > 0 ? median(ratios) : 0.0;
    return true;
  }

  // A view as rendered and scored, and the error of the views up to it together.
  struct RenderedView {
    ViewResult view;
    ErrorAccumulator allSoFar;
  };
  // What a render reads besides the scene: the package as written with its other targets' code
  // left out (the Vulkan renderer reads the SPIR-V) and the colour encoding PreparedFrame gives the
  // parameters. Bytes, not a hash: equal keys are equal inputs.
  static std::string renderedBytes(package::Package pkg, const TierConfig& config) {
    for (package::Variant& v : pkg.variants)
      std::erase_if(v.shaders, [](const package::Shader& s) { return s.target != package::Target::Spirv; });
    const std::vector<uint8_t> bytes = package::write(pkg);
    return std::to_string(int(config.colorSpace)) + ":" + std::string(bytes.begin(), bytes.end());
  }

  const ir::Material& material_;
  const EvalOptions& options_;
  std::vector<View> views_;
  std::unique_ptr<runtime::RenderBackend> backend_;
  fs::path workDir_;
  std::vector<runtime::FrameResult> referenceImages_;               // per view
  std::vector<runtime::FrameResult> groundTruth_;                   // per view; empty unless measured
  std::vector<std::array<float, 3>> backgrounds_;                   // per view: the clear colour
  std::unique_ptr<PreparedFrame> referenceFrame_;                   // the reference's first view
  std::optional<bool> gpuClock_;                                    // timed by the forward pass's GPU time
  std::map<std::string, std::vector<RenderedView>> renderedViews_;  // by renderedBytes()
  std::vector<AheadBuild> ahead_;  // last: their threads read the members above until joined
};

}  // namespace

struct Session::State {
  EvalOptions options;  // the Evaluation keeps a reference: the session owns them
  TempDir work;         // one package per configuration, removed at the end
  std::optional<Evaluation> evaluation;
};

Session::Session() = default;
Session::~Session() = default;

std::unique_ptr<Session> Session::start(const ir::Material& material, const EvalOptions& options, EvalError* error) {
  std::unique_ptr<Session> session(new Session());
  EvalReport& report = session->report_;
  report.material = material.name;
  report.timingFrames = std::max(options.timingFrames, 0);
  report.warmupFrames = std::max(options.warmupFrames, 1);
  report.fp16Emulation = options.fp16Emulation;
  report.tuningFile = options.tuningFile;
  report.weights = options.weights;

  // The views: the built-in grid, or the scene file's objects of this material.
  std::vector<View> views;
  if (options.sceneFile.empty()) {
    report.scene = "built-in evaluation grid";
    for (GridView& v : evaluationGrid(material, options.grid)) views.push_back({v.name, std::move(v.scene)});
    if (options.shadows) {
      GridView shadowed = shadowedGridView(material, options.grid);
      views.push_back({shadowed.name, std::move(shadowed.scene)});
    }
    report.sceneNotes = describeSweep(material, options.grid);
  } else {
    report.scene = options.sceneFile;
    auto scene = runtime::loadScene(options.sceneFile, &error->message);
    if (!scene) return nullptr;
    const size_t before = scene->objects.size();
    std::erase_if(scene->objects, [&](const runtime::SceneObject& o) { return o.material != material.name; });
    if (scene->objects.empty()) {
      error->message = options.sceneFile + ": no object of the scene uses material '" + material.name + "'";
      return nullptr;
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
    return nullptr;
  }
  std::error_code ec;
  session->state_ = std::make_unique<State>();
  session->state_->options = options;
  fs::path& work = session->state_->work.path;
  work = fs::temp_directory_path(ec) / ("facet-eval-" + std::to_string(getpid()));
  fs::remove_all(work, ec);
  fs::create_directories(work, ec);
  if (ec) {
    error->message = "cannot create a temporary folder '" + work.string() + "': " + ec.message();
    return nullptr;
  }

  Evaluation& evaluation = session->state_->evaluation.emplace(material, session->state_->options, std::move(views),
                                                               std::move(backend), work);
  const Configuration reference = configurations(material, {}, false).at(0);
  // (The sampled ground truth integrates the standard model's lobes: not the cloth model's.)
  if (options.groundTruthSamples > 0 && material.shading == "lit" && !material.cloth) {
    report.groundTruthSamples = options.groundTruthSamples;
    if (!evaluation.renderGroundTruth(reference, &report.groundTruthConvergence, &report.groundTruthViews, error))
      return nullptr;
  }
  ConfigurationResult r;
  if (!evaluation.measure(reference, true, &r, error)) return nullptr;
  report.results.push_back(std::move(r));
  return session;
}

bool Session::cost(const Configuration& c, ConfigurationResult* r, EvalError* error) const {
  return state_->evaluation->costOnly(c, r, error);
}

bool Session::measure(const Configuration& c, ConfigurationResult* r, EvalError* error, const MeasureOptions& how) {
  return state_->evaluation->measure(c, false, r, error, how);
}

void Session::buildAhead(const Configuration& c) { state_->evaluation->buildAhead(c); }

std::string Session::timingClock() const { return state_->evaluation->timingClock(); }

std::optional<EvalReport> evaluate(const ir::Material& material, const EvalOptions& options, EvalError* error) {
  std::unique_ptr<Session> session = Session::start(material, options, error);
  if (!session) return std::nullopt;
  EvalReport report = session->report();
  const std::vector<Configuration> configs = configurations(material, options.tiers, options.swaps, options.tunedTiers);
  if (options.progress) options.progress(formatProgress(0, configs.size(), report.results.back()));
  for (size_t i = 1; i < configs.size(); ++i) {
    const Configuration& c = configs[i];
    // Identical maths (e.g. high with energy compensation = reference in mediump): the same
    // shaders and images, measured once.
    auto same = std::find_if(report.results.begin(), report.results.end(), [&](const ConfigurationResult& e) {
      return e.configuration.config == c.config && e.sameAs.empty();
    });
    ConfigurationResult r;
    if (same != report.results.end()) {
      r = *same;
      r.configuration = c;
      r.sameAs = same->configuration.name;
    } else if (!session->measure(c, &r, error)) {
      return std::nullopt;
    }
    report.results.push_back(std::move(r));
    if (options.progress) options.progress(formatProgress(i, configs.size(), report.results.back()));
  }

  report.timingClock = session->timingClock();

  // Ratios to the tiers as shipped (configurations() puts reference as shipped first).
  auto shipped = [&](permutations::Tier t) -> const ConfigurationResult* {
    for (const ConfigurationResult& r : report.results)
      if (!r.configuration.swap() && r.configuration.tier == t) return &r;
    return nullptr;
  };
  const ConfigurationResult* high = shipped(permutations::Tier::High);
  auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
  const double referenceCycles = report.results[0].fragment.cycles;
  const double highCycles = high ? high->fragment.cycles : 0;
  const double highSunIbl = high ? high->sunIblFragmentCycles : 0;
  for (ConfigurationResult& r : report.results) {
    r.cyclesVsReference = ratio(r.fragment.cycles, referenceCycles);
    r.cyclesVsHigh = ratio(r.fragment.cycles, highCycles);
    r.sunIblVsHigh = ratio(r.sunIblFragmentCycles, highSunIbl);
  }
  markPareto(&report.results);

  // The lobes on their own, over the whole BRDF domain (lit materials: unlit ones have no lobe).
  // The cloth model has no specular lobe, only its sheen's.
  if (options.brdfSweep && material.shading == "lit") {
    GpuEvaluator gpu(options.validation);
    if (!gpu.ready()) {
      error->message = "no Vulkan device for the BRDF-domain sweep: " + gpu.initError();
      return std::nullopt;
    }
    if (!material.cloth && !sweepBrdfDomain(gpu, configs, report.brdfDomain, &report.brdfSweep, &error->message))
      return std::nullopt;
    if (!material.cloth && !furnaceStandardLobes(gpu, configs, report.brdfDomain, report.furnaceDomain,
                                                 &report.lobeFurnace, &error->message))
      return std::nullopt;
    if (!sweepModelLobes(gpu, material, configs, report.brdfDomain, report.furnaceDomain, &report.modelLobeSweep,
                         &report.lobeFurnace, &error->message))
      return std::nullopt;
  }
  return report;
}

}  // namespace facet::eval
