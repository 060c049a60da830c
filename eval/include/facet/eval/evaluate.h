// `matc eval`: every tier and single-option swap of a material, rendered on lavapipe and measured
// against `reference` (error) and by the mobile cost model and lavapipe's frame time (speed).
// docs/eval.md describes what is measured and how; report.h writes the result.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "facet/compiler/mobile_cost.h"
#include "facet/eval/brdf_sweep.h"
#include "facet/eval/configurations.h"
#include "facet/eval/grid_scene.h"
#include "facet/eval/lobe_sweep.h"
#include "facet/eval/metrics.h"
#include "facet/gpu_stats/mesa_compile.h"
#include "facet/ir/module.h"
#include "facet/permutations/variant_key.h"

namespace facet::eval {

struct EvalOptions {
  std::vector<permutations::Tier> tiers = permutations::supportedTiers();
  bool swaps = true;      // also every single-option swap of each tier
  std::string sceneFile;  // a scene file instead of the built-in grid ("" = the grid)
  GridOptions grid;
  // The grid: also the "shadowed" view (shadowedGridView), the sun casting onto a wall, so that each
  // tier's shadow receiver is measured with the rest. A scene file whose sun casts is measured so
  // without it.
  bool shadows = false;
  int timingFrames = 5;        // timed renders of the first view (median), each paired with one of reference's
  int warmupFrames = 1;        // untimed renders first (the first also makes the image)
  bool validation = false;     // Vulkan validation layers (FACET_VK_VALIDATION=1 also turns them on)
  bool fp16Emulation = false;  // render mediump SPIR-V with binary16 rounding (docs/fp16-emulation.md);
                               // the cost is still that of the shaders as shipped
  compiler::MobileCostWeights weights;
  bool brdfSweep = true;  // also each lobe over the BRDF domain (brdf_sweep.h; lit materials)
  // Lit materials: also measure every configuration against the ground truth, `reference` with its
  // environment integrated per pixel by importance sampling with this many points per integral
  // (AmbientModel::Sampled), and the same at a quarter of the points against it. 0: off.
  int groundTruthSamples = 0;
  std::function<void(const std::string&)> progress;  // one line per configuration, if set
  // A variant cache (compiler::BuildOptions::cacheDir) for a Session's builds, Session::cost()'s
  // and the rendered ones: `matc tune` builds every candidate, and a second run finds them there.
  // "": none.
  std::string cacheDir;
  // The tiers as shipped when a tuning file chose them (compiler::BuildOptions::tunedTiers, as
  // `matc compile` builds them), and that file's path for the report ("": the presets).
  std::map<permutations::Tier, permutations::TierConfig> tunedTiers;
  std::string tuningFile;
};

// `reference` renders views whose sun casts with this atlas size, whatever the scene's: the other
// configurations' shadows, with the scene's atlas (2048² by default) and their tier's filter, are
// measured against reference's widest filter (the 3×3 tent) on the largest atlas a phone is given.
inline constexpr uint32_t kReferenceShadowAtlas = 4096;

struct ViewResult {
  std::string name;          // "frontal", "grazing", or the scene file's stem
  std::string image;         // PNG path relative to the report's folder (images/<configuration>.<view>.png)
  std::vector<uint8_t> png;  // its bytes, written with the report (report.h)
  ImageMetrics error;
};

struct ConfigurationResult {
  Configuration configuration;
  std::string variantKey;  // e.g. "high.dir1.pt1"
  std::string sameAs;      // the earlier configuration with identical maths whose results these are
  compiler::MobileStageCost fragment, vertex;
  ImageMetrics error;  // all views together
  // Against the ground truth (EvalOptions::groundTruthSamples), all views together; unset when off.
  std::optional<ImageMetrics> groundTruthError;
  std::vector<ViewResult> views;
  double seconds = 0;       // lavapipe: median render() time of the first view
  double cyclesVsHigh = 0;  // fragment cycles ÷ high's as shipped (0 when high was not evaluated)
  double cyclesVsReference = 0;
  // Lit materials: fragment cycles of the sun + IBL variant <tier>.dir1 (no point light), the
  // variant the tiers' cost goals (and the Mali-G57 measurements) refer to, and its ratio to high's.
  double sunIblFragmentCycles = 0;
  // The cost model's figures of that variant (for unlit materials, of <tier>, their one light
  // variant): the op counts `matc tune`'s one-number cost weighs (docs/tune.md).
  compiler::MobileStageCost costFragment, costVertex;
  double sunIblVsHigh = 0;
  double timeVsReference = 0;  // median over the paired renders of this time ÷ reference's (0: not timed)
  // Lit materials: the white furnace — the grid's first view with no sun and no point light in a
  // constant sky, the brightest value the spheres cover ÷ the sky's radiance (furnaceGain). Above
  // 1 the surface reflects more than it receives; `reference` itself does on bright dielectrics
  // (Filament's standard model adds the diffuse and the Fresnel-weighted specular without
  // coupling them), so a configuration gains energy when it exceeds both kFurnaceGainLimit and
  // reference's gain by that factor (furnaceGainsEnergy). 0 for unlit materials.
  double furnaceGain = 0;
  bool pareto = false;  // no other configuration has both fewer cycles and a higher PSNR
  // The GLSL ES 3.00 pair of variantKey as shipped, for per-GPU figures (addGpuFigures); empty
  // for a configuration with the same maths as an earlier one, and from Session::cost() and a
  // measure() given its cost (both build SPIR-V alone).
  std::vector<gpu_stats::ShaderPair> glslEs;
  // Set when Session::measure() stopped after the first views (MeasureOptions::worthFinishing):
  // `error` is theirs, and this bounds the PSNR all the views together could have reached.
  std::optional<double> psnrAtMost;
  // Views whose figures came from an earlier render of the same bytes (MeasureOptions::reuseIdenticalViews).
  size_t viewsReused = 0;
};

// A furnace gain above this factor is flagged as energy gain: the RGBA16F target and the
// environment's fp16 texels round L by up to 2^-11 each, and mediump shading adds a few such
// roundings.
inline constexpr double kFurnaceGainLimit = 1.01;
// Energy gain: above the limit and above reference's own gain by the same factor.
inline bool furnaceGainsEnergy(double gain, double referenceGain) {
  return gain > kFurnaceGainLimit && gain > referenceGain * kFurnaceGainLimit;
}

struct EvalReport {
  std::string material;
  std::string scene;                    // "built-in grid" or the scene file
  std::vector<std::string> sceneNotes;  // the sweep, dropped objects, ...
  std::vector<std::string> viewNames;
  uint32_t width = 0, height = 0;  // of the first view
  int timingFrames = 0, warmupFrames = 0;
  // "gpu_forward_pass": the forward pass's GPU time from Vulkan timestamps (lavapipe reports
  // them); "wall_render": the wall time of RenderBackend::render(), where the device cannot time;
  // empty when nothing was timed (timingFrames 0).
  std::string timingClock;
  bool fp16Emulation = false;
  std::string tuningFile;  // the tuning file the tiers as shipped come from ("": the presets)
  compiler::MobileCostWeights weights;
  // The ground truth's samples (EvalOptions::groundTruthSamples; 0: not measured) and a bound on
  // its own error: the image at a quarter of the samples against it, all views together.
  int groundTruthSamples = 0;
  ImageMetrics groundTruthConvergence;
  std::vector<ViewResult> groundTruthViews;  // images/ground_truth.<view>.png; error: the quarter-samples image's
  std::vector<ConfigurationResult> results;  // results[0] is reference as shipped
  // Per-GPU figures from Mesa's compilers (addGpuFigures), one per GPU asked for; the pairs are
  // named by configuration. Empty: the cost model's figures only.
  std::vector<gpu_stats::GpuStats> gpuStats;
  // Each (specular lobe, precision) of the configurations over the BRDF domain; empty for unlit
  // materials or with EvalOptions::brdfSweep off.
  std::vector<BrdfSweepRow> brdfSweep;
  BrdfSweepDomain brdfDomain;  // what the sweep sampled
  // The lobes of the material models it writes (clear coat, anisotropy, sheen: lobe_sweep.h) over
  // the same domain, and their white furnace; empty for a material that writes none.
  std::vector<BrdfSweepRow> modelLobeSweep;
  std::vector<LobeFurnaceRow> lobeFurnace;
  LobeFurnaceDomain furnaceDomain;
};

struct EvalError {
  std::string message;
  std::optional<ir::SourceLoc> loc;  // a build error that traces back to a line of the material
};

// How Session::measure() may save work.
struct MeasureOptions {
  // The configuration's Session::cost() result: the cost model's figures are taken from it
  // instead of a second build (under fp16 emulation the rendered build is not the costed one).
  const ConfigurationResult* costed = nullptr;
  // Called after the views are scored; false: the white furnace is not rendered (furnaceGain NaN),
  // e.g. for an error no budget would take.
  std::function<bool(const ConfigurationResult&)> furnaceWanted;
  // Called after each view but the last with the highest PSNR all the views together could reach
  // (ErrorAccumulator::psnrAtMost, every pixel of the views still to render counted as covered and
  // exact); false: the rest and the furnace are not rendered (ConfigurationResult::psnrAtMost).
  std::function<bool(double psnrAtMost)> worthFinishing;
  // Encode each view's image as PNG (ViewResult::png); `matc tune` writes none.
  bool images = true;
  // A view whose shaders and inputs an earlier measure() of this session rendered already (the
  // package's SPIR-V and everything else the renderer reads, byte for byte, and the colour
  // encoding) takes that render's figures instead of rendering again: lavapipe renders the same
  // bytes to the same pixels, so every figure is the one a render would give
  // (ConfigurationResult::viewsReused). Untimed sessions, without images or ground truth only.
  bool reuseIdenticalViews = false;
};

// One evaluation's renderer, views and `reference`'s images, for measuring configurations one at a
// time (`matc tune`, docs/tune.md); evaluate() is a session over configurations(). start() renders
// `reference` as shipped (and the ground truth when asked): report().results[0].
class Session {
 public:
  static std::unique_ptr<Session> start(const ir::Material& material, const EvalOptions& options, EvalError* error);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  // Builds the configuration's cost variant (<tier>.dir1) and fills the cost model's figures
  // (fragment, vertex, costFragment, costVertex, sunIblFragmentCycles) without rendering. Safe to
  // call from several threads at once (not with measure()).
  bool cost(const Configuration& configuration, ConfigurationResult* result, EvalError* error) const;
  // Builds, costs, renders and scores one configuration against `reference`.
  bool measure(const Configuration& configuration, ConfigurationResult* result, EvalError* error,
               const MeasureOptions& how = {});
  // Starts building what measure() with MeasureOptions::costed builds for this configuration, on
  // one core of its own, so that the build overlaps the renders of the measure() calls before it
  // (`matc tune` names its next candidate). The result is the same; a build that measure() is not
  // asked for before the next buildAhead() is dropped.
  void buildAhead(const Configuration& configuration);
  // The report's fields known at the start, and reference's result.
  const EvalReport& report() const { return report_; }
  std::string timingClock() const;

 private:
  Session();
  struct State;
  std::unique_ptr<State> state_;
  EvalReport report_;
};

// Runs the evaluation. Fails on a build error (with the material's line where known), a scene
// that cannot be read or rendered, or no Vulkan device.
std::optional<EvalReport> evaluate(const ir::Material& material, const EvalOptions& options, EvalError* error);

// Compiles every measured configuration's shaders (ConfigurationResult::glslEs) with Mesa's
// compilers for `gpus` (docs/mesa-statistics.md) into report->gpuStats. A GPU that cannot be
// measured says why there; never fails.
void addGpuFigures(EvalReport* report, const std::vector<std::string>& gpus, const gpu_stats::MesaTool& tool);

}  // namespace facet::eval
