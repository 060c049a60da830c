#include "facet/compiler/build.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstring>
#include <limits>
#include <mutex>

#include "facet/compiler/assemble.h"
#include "facet/compiler/backend_errors.h"
#include "facet/compiler/glslang_backend.h"
#include "facet/compiler/lower_half_image_operands.h"
#include "facet/compiler/lower_relaxed_to_quantized.h"
#include "facet/compiler/minify_glsl.h"
#include "facet/compiler/msl_backend.h"
#include "facet/compiler/param_layout.h"
#include "facet/compiler/preshader.h"
#include "facet/compiler/specular_lut.h"
#include "facet/compiler/spirv_tools_backend.h"
#include "facet/ir/emit_glsl.h"
#include "facet/ir/passes.h"
#include "job_pool.h"
#include "variant_cache.h"

namespace facet::compiler {
namespace {

std::vector<uint8_t> bytesOf(const std::string& text) { return {text.begin(), text.end()}; }

std::vector<uint8_t> bytesOf(const std::vector<uint32_t>& words) {
  std::vector<uint8_t> bytes(words.size() * 4);
  std::memcpy(bytes.data(), words.data(), bytes.size());  // SPIR-V words are stored little-endian
  return bytes;
}

package::ParamType packageType(const ir::Param& p) {
  if (p.isColor) return package::ParamType::Color;
  switch (p.type) {
    case ir::Type::Texture2D:
      if (p.textureSpace == ir::TextureSpace::Srgb) return package::ParamType::TextureSrgb;
      if (p.textureSpace == ir::TextureSpace::Normal) return package::ParamType::TextureNormal;
      return package::ParamType::TextureLinear;
    case ir::Type::Float: return package::ParamType::Float;
    case ir::Type::Vec2: return package::ParamType::Vec2;
    case ir::Type::Vec3: return package::ParamType::Vec3;
    case ir::Type::Vec4: return package::ParamType::Vec4;
    case ir::Type::Int: return package::ParamType::Int;
    case ir::Type::Bool: return package::ParamType::Bool;
  }
  return package::ParamType::Float;
}

package::MaterialInfo materialInfo(const ir::Material& m, const ParamLayout& layout) {
  package::MaterialInfo info;
  info.name = m.name;
  info.shading = m.shading;
  info.blending = m.blending;
  info.doubleSided = m.doubleSided;
  info.paramBlockSize = layout.blockSize;
  for (size_t i = 0; i < m.params.size(); ++i) {
    const ir::Param& p = m.params[i];
    package::Param out;
    out.name = p.name;
    out.type = packageType(p);
    out.defaultValue = p.defaultValue;
    out.rangeMin = p.rangeMin;
    out.rangeMax = p.rangeMax;
    out.offset = layout.slots[i].offset;
    out.size = layout.slots[i].size;
    if (package::isTexture(out.type))
      out.offset = layout.slots[i].textureSlot < 0 ? package::kNoTextureSlot : uint32_t(layout.slots[i].textureSlot);
    info.params.push_back(std::move(out));
  }
  return info;
}

// One stage's SPIR-V: validate what glslang produced, optimize, validate again.
bool finishSpirv(std::vector<uint32_t>* words, const char* stage, std::string* error) {
  std::string log;
  if (!validateSpirv(*words, &log)) {
    *error = std::string("spirv-val rejected the ") + stage + " stage from glslang:\n" + log;
    return false;
  }
  if (!optimizeSpirv(words, &log)) {
    *error = std::string("spirv-opt failed on the ") + stage + " stage:\n" + log;
    return false;
  }
  if (!validateSpirv(*words, &log)) {
    *error = std::string("spirv-val rejected the optimized ") + stage + " stage:\n" + log;
    return false;
  }
  return true;
}

// A glslang failure on generated code: blamed on the material line that produced it when the
// error lies in the surface program, else reported as the compiler's own defect.
void reportGlslangFailure(const std::string& log, const StageSources& sources, const ir::SurfaceGlsl& surface,
                          const std::string& what, BuildError* failure) {
  if (auto mapped = mapGlslangErrors(log, sources.fragmentSurfaceLine, surface.lineLocs)) {
    failure->message = "the shader compiler rejected this expression: " + mapped->message + " (" + what + ")";
    failure->loc = mapped->loc;
    return;
  }
  failure->message = "internal error: generated " + what + " does not compile:\n" + log;
}

// The surface program reduced to what `alpha` depends on: a masked material's depth-only program
// evaluates it (templates/depth.frag.glsl), reading only the attributes and textures its alpha
// test needs. The material's parameters keep the full program's layout: the block is the one the
// runtime binds for every variant.
ir::SurfaceGlsl alphaOnlySurface(const ir::Material& optimized) {
  ir::Material alpha = optimized;
  std::erase_if(alpha.surface.outputs, [](const auto& output) { return output.first != "alpha"; });
  ir::optimize(alpha);
  return ir::emitSurface(alpha);
}

// What every variant of one material shares; read-only while variants build in parallel.
struct MaterialContext {
  const ir::Material& material;
  const ir::SurfaceGlsl& surface;
  const ir::SurfaceGlsl& alphaSurface;  // what the depth-only programs evaluate (alphaOnlySurface)
  const ParamLayout& layout;
  const PreshadeLayout& preshade;
  const BuildOptions& options;
  const VariantCache& cache;
  const std::vector<package::MslBinding>& mslBindings;  // Metal slots, the same for every variant
};

// The steps of one variant, each a job of its own so two threads stay busy to the end (one
// variant's fragment stage alone is about half of its work). The cache saves every step after
// Assemble. A variant's failure is its first failed step in this order, whatever ran first.
enum Step : size_t { Assemble, GlslEs, Spirv, VertexStage, FragmentStage, StepCount };

// One variant's share of the result, written only by its own jobs: each step writes its own
// fields and slots, and the job that brings `pending` to zero assembles the package entry.
struct VariantBuild {
  // Assemble
  std::string keyText;
  permutations::TierConfig tier;
  StageSources es, vk;
  std::string cacheKey;
  bool samplesSpecularLut = false;
  std::vector<package::PreshaderOp> preshader;  // empty: the variant preshades nothing
  bool cacheHit = false;
  bool cacheRejected = false;  // an entry was found and failed passesOutputChecks
  // Spirv: glslang's stages before SPIRV-Tools, each moved out by its stage's job
  SpirvStages spirv;
  // GLSL ES by GlslEs (0, 1); SPIR-V and MSL by VertexStage (2, 4) and FragmentStage (3, 5)
  CompiledShaders shaders;
  std::array<BuildError, StepCount> failures;
  std::array<bool, StepCount> failed{};
  std::atomic<bool> skipped{false};  // a variant earlier in key order failed first: never reported
  std::atomic<int> pending{0};       // compile jobs added and not yet finished
  // The package entry, once every step succeeded
  bool built = false;
  package::Variant variant;
  std::vector<GeneratedFile> sources;
  std::set<std::string> libraryFiles;
};

// The GLSL ES 3.00 the package ships: preprocessed for this variant, then minified
// (compiler/minify_glsl.h), and parsed and linked by glslang as a driver would. False with
// glslang's log when either step fails.
bool shippedGlslEs(const StageSources& es, StageSources* shipped, std::string* log) {
  StageSources preprocessed;
  if (!preprocessGlslEs300(es, &preprocessed, log)) return false;
  shipped->vertex = minifyPreprocessedGlsl(preprocessed.vertex);
  shipped->fragment = minifyPreprocessedGlsl(preprocessed.fragment);
  return checkGlslEs300(*shipped, log);
}

std::vector<uint32_t> wordsOf(const std::vector<uint8_t>& bytes) {
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

// A cache entry comes back from a folder anyone with the user's rights can write, and its
// checksum only catches damage, not an edit resealed with a new checksum. So it ships only after
// the checks fresh output passes on its way: spirv-val on each SPIR-V stage (finishSpirv) and
// glslang on the GLSL ES pair (shippedGlslEs). The MSL has no checker on either path.
bool passesOutputChecks(const CompiledShaders& shaders, bool spirvOnly) {
  std::string log;
  for (size_t spirv : {2, 3})
    if (shaders[spirv].size() % 4 != 0 || !validateSpirv(wordsOf(shaders[spirv]), &log)) return false;
  if (spirvOnly) return true;
  StageSources es;
  es.vertex.assign(shaders[0].begin(), shaders[0].end());
  es.fragment.assign(shaders[1].begin(), shaders[1].end());
  return checkGlslEs300(es, &log);
}

// Job costs, for ordering only: JobPool starts the costliest waiting job first, and what a job
// computes does not depend on when it runs. Assembly and glslang come first (cost kFirst, then in
// key order): they are short and make the jobs that follow. A stage's SPIRV-Tools and SPIRV-Cross
// work grows with the SPIR-V glslang made for it, and a fragment stage is half to three quarters
// of a variant; the shipped GLSL ES costs about as much as the smallest vertex stage. So the
// stages run largest first and the GLSL ES jobs fill the end. Milliseconds of one core per word
// or byte, fitted to red_plastic's 32 variants of `--point-lights 0,1,2,4` with `-j 1`
// (docs/build-integration.md, "Scheduling"); only their ratio matters.
struct CostModel {
  static constexpr double kFirst = std::numeric_limits<double>::infinity();
  static constexpr double kStagePerWord = 0.0045;     // glslang's SPIR-V words of the stage
  static constexpr double kGlslEsPerByte = 0.000057;  // assembled GLSL ES bytes, both stages

  static double glslEs(const VariantBuild& v) {
    return kGlslEsPerByte * double(v.es.vertex.size() + v.es.fragment.size());
  }
  // fp16 emulation optimizes and validates a second copy of the stage, except under
  // BuildOptions::spirvOnly, where the emulated copy is the only one.
  static double stage(size_t words, bool secondCopy) { return kStagePerWord * double(words) * (secondCopy ? 2 : 1); }
};

// A material's variants as jobs on one pool. Each job starts with the variant's assembly and
// adds the next steps as their inputs come to exist.
class VariantJobs {
 public:
  VariantJobs(const MaterialContext& ctx, const std::vector<permutations::VariantKey>& keys)
      : ctx_(ctx), keys_(keys), variants_(keys.size()) {}

  void run(unsigned threads) {
    // A variant has at most three jobs at once (its GLSL ES and two stages): more threads idle.
    threads = std::min<size_t>(threads == 0 ? defaultJobCount() : threads, std::max<size_t>(1, 3 * keys_.size()));
    JobPool pool;
    // Assembly first, in key order: it is cheap and makes every other job.
    for (size_t i = 0; i < keys_.size(); ++i)
      add(pool, CostModel::kFirst, [this, i](JobPool& p) { assembleStep(i, p); });
    pool.run(threads);
  }

  std::vector<VariantBuild>& variants() { return variants_; }

 private:
  // pool.add, timing the job when BuildOptions::jobSpans asks for it.
  void add(JobPool& pool, double cost, JobPool::Job job) {
    if (!ctx_.options.jobSpans) return pool.add(cost, std::move(job));
    pool.add(cost, [this, job = std::move(job)](JobPool& p) {
      using Clock = std::chrono::steady_clock;
      const double start = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
      job(p);
      const double end = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
      std::lock_guard<std::mutex> lock(spansMutex_);
      ctx_.options.jobSpans->push_back({start, end, JobPool::currentThread()});
    });
  }

  bool emulated(const VariantBuild& v) const {
    return ctx_.options.fp16Emulation && v.tier.precision == permutations::PrecisionPolicy::Mediump;
  }
  bool trueHalf(const VariantBuild& v) const {
    return ctx_.options.fp16TrueHalf && v.tier.precision == permutations::PrecisionPolicy::Mediump;
  }

  // Once a variant has failed, the ones after it in key order are not worth compiling (only the
  // first failure is reported); every one before it still runs to the end, so which failure is
  // first does not depend on the thread count or on timing.
  bool skip(size_t i) const { return i > firstFailed_.load(); }

  void fail(size_t i, Step step) {
    variants_[i].failed[step] = true;
    size_t first = firstFailed_.load();
    while (i < first && !firstFailed_.compare_exchange_weak(first, i)) {
    }
  }

  void stepDone(size_t i) {
    if (variants_[i].pending.fetch_sub(1) == 1) finish(i);
  }

  void assembleStep(size_t i, JobPool& pool) {
    VariantBuild& v = variants_[i];
    if (skip(i)) {
      v.skipped = true;
      return finish(i);
    }
    const permutations::VariantKey& key = keys_[i];
    v.keyText = key.toString();
    v.tier = tierConfig(ctx_.material, key.tier, ctx_.options);
    const ir::SurfaceGlsl& surface = key.depthOnly ? ctx_.alphaSurface : ctx_.surface;
    AssemblyInput input{ctx_.material, surface, ctx_.layout, key, v.tier, compilerVersion()};
    // A depth-only program reads alpha alone, which is never preshaded.
    if (!key.depthOnly) v.preshader = preshaderProgram(ctx_.material, ctx_.layout, ctx_.preshade, v.tier);
    if (!v.preshader.empty()) input.preshade = &ctx_.preshade;
    std::string* error = &v.failures[Assemble].message;
    const bool es = !ctx_.options.spirvOnly;
    if ((es && !assemble(input, Flavour::GlslEs300, &v.es, error)) || !assemble(input, Flavour::Vulkan, &v.vk, error)) {
      fail(i, Assemble);
      return finish(i);
    }
    v.samplesSpecularLut = samplesSpecularLut(input);
    // The same text compiles to the same code, so a cached variant skips every backend.
    v.cacheKey = variantCacheKey(compilerVersion(), v.es, v.vk,
                                 {ctx_.options.fp16Emulation, ctx_.options.fp16TrueHalf, ctx_.options.spirvOnly});
    if (std::optional<CompiledShaders> cached = ctx_.cache.load(v.cacheKey)) {
      if (passesOutputChecks(*cached, ctx_.options.spirvOnly)) {
        v.shaders = std::move(*cached);
        v.cacheHit = true;
        return finish(i);
      }
      v.cacheRejected = true;  // compiled below, and the entry replaced
    }
    v.pending = es ? 2 : 1;
    if (es) add(pool, CostModel::glslEs(v), [this, i](JobPool&) { glslEsStep(i); });
    add(pool, CostModel::kFirst, [this, i](JobPool& p) { spirvStep(i, p); });
  }

  void glslEsStep(size_t i) {
    VariantBuild& v = variants_[i];
    if (skip(i)) {
      v.skipped = true;
      return stepDone(i);
    }
    BuildError* failure = &v.failures[GlslEs];
    std::string log;
    StageSources shipped;
    if (shippedGlslEs(v.es, &shipped, &log)) {
      v.shaders[0] = bytesOf(shipped.vertex);
      v.shaders[1] = bytesOf(shipped.fragment);
    } else {
      fail(i, GlslEs);
      // Only on failure is the readable text checked (one glslang parse saved per variant): its
      // line numbers map an error back to the material; if it compiles, the minifier is at fault.
      std::string readableLog;
      if (!checkGlslEs300(v.es, &readableLog))
        reportGlslangFailure(readableLog, v.es, ctx_.surface, "GLSL ES 3.00 for variant " + v.keyText, failure);
      else
        failure->message =
            "internal error: the minified GLSL ES 3.00 of variant " + v.keyText + " does not compile:\n" + log;
    }
    stepDone(i);
  }

  void spirvStep(size_t i, JobPool& pool) {
    VariantBuild& v = variants_[i];
    if (skip(i)) {
      v.skipped = true;
      return stepDone(i);
    }
    std::string log;
    if (!compileToSpirv(v.vk, &v.spirv, &log)) {
      reportGlslangFailure(log, v.vk, ctx_.surface, "SPIR-V for variant " + v.keyText, &v.failures[Spirv]);
      fail(i, Spirv);
      return stepDone(i);
    }
    v.pending += 2;  // before this job counts itself done
    const bool twoCopies = emulated(v) && !ctx_.options.spirvOnly;
    add(pool, CostModel::stage(v.spirv.vertex.size(), twoCopies), [this, i](JobPool&) { stageStep(i, VertexStage); });
    add(pool, CostModel::stage(v.spirv.fragment.size(), twoCopies),
        [this, i](JobPool&) { stageStep(i, FragmentStage); });
    stepDone(i);
  }

  // One stage from glslang's SPIR-V to what ships: the fp16-emulated copy when asked for (it must
  // see the stage before spirv-opt), validated and optimized SPIR-V, and MSL from it. SPIR-V only:
  // the emulated copy is the only one an emulated stage needs.
  void stageStep(size_t i, Step step) {
    VariantBuild& v = variants_[i];
    if (skip(i)) {
      v.skipped = true;
      return stepDone(i);
    }
    const size_t slot = step == VertexStage ? 0 : 1;  // shaders[2 + slot], shaders[4 + slot]
    std::vector<uint32_t> words = std::move(slot == 0 ? v.spirv.vertex : v.spirv.fragment);
    if (!compileStage(v, slot, &words, &v.failures[step].message)) fail(i, step);
    stepDone(i);
  }

  bool compileStage(VariantBuild& v, size_t slot, std::vector<uint32_t>* words, std::string* error) {
    const char* stage = slot == 0 ? "vertex" : "fragment";
    std::optional<std::vector<uint32_t>> emulatedWords;
    if (emulated(v)) {
      emulatedWords = *words;
      QuantizeCounts counts;
      if (!lowerRelaxedToQuantized(&*emulatedWords, &counts, error) ||
          !finishSpirv(&*emulatedWords, (std::string("fp16-emulated ") + stage).c_str(), error))
        return false;
      if (ctx_.options.spirvOnly) {  // the un-emulated copy would only feed the MSL
        v.shaders[2 + slot] = bytesOf(*emulatedWords);
        return true;
      }
    }
    if (!finishSpirv(words, stage, error)) return false;
    if (ctx_.options.spirvOnly && !trueHalf(v)) {  // true half goes on: it ships the converted stage
      v.shaders[2 + slot] = bytesOf(*words);
      return true;
    }
    // Metal: mediump becomes `half` (16-bit) through spirv-opt, as on GLES drivers.
    std::vector<uint32_t> metal = *words;
    std::string log, msl;
    if (!convertRelaxedToHalf(&metal, &log)) {
      *error = "internal error: spirv-opt --convert-relaxed-to-half failed for variant " + v.keyText + ":\n" + log;
      return false;
    }
    if (!ctx_.options.spirvOnly && !spirvToMsl(metal, ctx_.mslBindings, &msl, error)) return false;
    if (trueHalf(v)) {
      // The same conversion as Metal's, then 32-bit image operands (lavapipe cannot compile half
      // ones); validated, since it ships in place of the stage.
      if (!lowerHalfImageOperands(&metal, error)) return false;
      log.clear();
      if (!validateSpirv(metal, &log)) {
        *error = "internal error: the true-half " + std::string(stage) + " stage of variant " + v.keyText +
                 " does not validate:\n" + log;
        return false;
      }
      *words = std::move(metal);
    }
    v.shaders[2 + slot] = bytesOf(emulatedWords ? *emulatedWords : *words);
    v.shaders[4 + slot] = bytesOf(msl);
    return true;
  }

  // The variant's package entry, its debug sources and its cache entry, once every step is done.
  void finish(size_t i) {
    VariantBuild& v = variants_[i];
    const bool failed = std::find(v.failed.begin(), v.failed.end(), true) != v.failed.end();
    if (!failed && !v.skipped) {
      if (!v.cacheHit) ctx_.cache.store(v.cacheKey, v.shaders);
      entry(v);
      v.built = true;
    }
    if (ctx_.options.progress) {
      std::lock_guard<std::mutex> lock(progressMutex_);
      ctx_.options.progress(++finished_, keys_.size());
    }
  }

  void entry(VariantBuild& v) {
    CompiledShaders& shaders = v.shaders;
    if (ctx_.options.emitSources) {
      // Debug sources: the readable assembled text of both flavours beside what ships.
      const std::string stem = ctx_.material.name + "." + v.keyText;
      auto text = [&](size_t i) { return std::string(shaders[i].begin(), shaders[i].end()); };
      v.sources = {
          {stem + ".vert.es300.glsl", text(0)},
          {stem + ".frag.es300.glsl", text(1)},
          {stem + ".vert.es300.readable.glsl", v.es.vertex},
          {stem + ".frag.es300.readable.glsl", v.es.fragment},
          {stem + ".vert.vulkan.glsl", v.vk.vertex},
          {stem + ".frag.vulkan.glsl", v.vk.fragment},
          {stem + ".vert.spvasm", disassembleSpirv(wordsOf(shaders[2]))},
          {stem + ".frag.spvasm", disassembleSpirv(wordsOf(shaders[3]))},
          {stem + ".vert.metal", text(4)},
          {stem + ".frag.metal", text(5)},
      };
    }
    using package::Stage;
    using package::Target;
    v.variant.key = v.keyText;
    v.variant.shaders = {
        {Stage::Vertex, Target::GlslEs300, std::move(shaders[0])},
        {Stage::Fragment, Target::GlslEs300, std::move(shaders[1])},
        {Stage::Vertex, Target::Spirv, std::move(shaders[2])},
        {Stage::Fragment, Target::Spirv, std::move(shaders[3])},
        {Stage::Vertex, Target::Msl, std::move(shaders[4])},
        {Stage::Fragment, Target::Msl, std::move(shaders[5])},
    };
    if (ctx_.options.spirvOnly)
      std::erase_if(v.variant.shaders, [](const package::Shader& s) { return s.target != Target::Spirv; });
    v.libraryFiles = v.es.libraryFiles;
    v.libraryFiles.insert(v.vk.libraryFiles.begin(), v.vk.libraryFiles.end());
  }

  const MaterialContext& ctx_;
  const std::vector<permutations::VariantKey>& keys_;
  std::vector<VariantBuild> variants_;
  std::atomic<size_t> firstFailed_{std::numeric_limits<size_t>::max()};
  std::mutex progressMutex_;
  size_t finished_ = 0;
  std::mutex spansMutex_;
};

}  // namespace

const std::string& compilerVersion() {
  static const std::string version = std::string("facet-matc ") + FACET_VERSION;
  return version;
}

permutations::TierConfig tierConfig(const ir::Material& material, permutations::Tier tierName,
                                    const BuildOptions& options) {
  // The tuned tier was searched from the preset with the overrides: it already holds them.
  permutations::TierConfig tier = permutations::preset(tierName);
  if (auto tuned = options.tunedTiers.find(tierName); tuned != options.tunedTiers.end()) {
    tier = tuned->second;
  } else {
    // The material's overrides for that tier (checked by ir::check).
    for (const ir::TierOverride& o : material.tierOverrides)
      if (o.tier == permutations::toString(tierName)) permutations::applyOverride(&tier, o.axis, o.option);
  }
  if (options.adjustTier) options.adjustTier(tierName, &tier);
  return tier;
}

permutations::MaterialNeeds materialNeeds(const ir::Material& material) {
  return {material.shading == "lit", permutations::blendingCastsShadows(material.blending)};
}

std::optional<BuildResult> buildMaterial(const ir::Material& checked, const BuildOptions& options,
                                         BuildError* failure) {
  if (options.fp16Emulation && options.fp16TrueHalf) {
    failure->message = "fp16 emulation and true half are two builds of the same SPIR-V: ask for one";
    return std::nullopt;
  }
  BuildResult result;
  ir::Material material = checked;
  ir::optimize(material);
  ParamLayout layout = layoutParams(material.params);
  const PreshadeLayout preshade = options.preshader ? planPreshade(material, layout) : PreshadeLayout{};
  ir::SurfaceGlsl surface = ir::emitSurface(material);
  const ir::SurfaceGlsl alphaSurface = alphaOnlySurface(material);
  result.package.compilerVersion = compilerVersion();
  result.package.packedVertices = true;      // templates/forward.vert.glsl decodes the packed streams
  result.package.instanceTransforms = true;  // and reads the instance stream's transforms
  result.package.material = materialInfo(material, layout);

  const permutations::MaterialNeeds needs = materialNeeds(material);
  const permutations::SceneNeeds* scene = options.scene ? &*options.scene : nullptr;
  const std::vector<permutations::VariantKey> keys =
      permutations::enumerate(needs, options.tiers, scene, options.pointLightCounts, options.shadowCascadeCounts,
                              options.spotShadows, options.vertexSlopeBias);

  if (!options.cacheDir.empty() && !prepareVariantCache(options.cacheDir, &failure->message)) return std::nullopt;
  // Jobs finish in any order; each writes only its own variant's fields, read here in key order.
  VariantCache cache(options.cacheDir);
  const bool shadowReceivers =
      std::any_of(keys.begin(), keys.end(), [](const permutations::VariantKey& k) { return k.receivesShadow(); });
  const bool irradianceCube = std::any_of(keys.begin(), keys.end(), [&](const permutations::VariantKey& k) {
    return !k.depthOnly && samplesIrradianceCube(tierConfig(material, k.tier, options), material.shading);
  });
  result.package.mslBindings = package::mslBindingsFor(result.package.material, shadowReceivers, irradianceCube);
  MaterialContext ctx{material, surface, alphaSurface, layout, preshade, options, cache, result.package.mslBindings};
  VariantJobs jobs(ctx, keys);
  jobs.run(options.jobs);

  std::vector<uint32_t> lutVariants;  // indices of the variants that sample the specular table
  for (VariantBuild& v : jobs.variants()) {
    if (!v.built) {  // the first failure in key order, whatever the job count
      const size_t step = size_t(std::find(v.failed.begin(), v.failed.end(), true) - v.failed.begin());
      *failure = step < StepCount ? std::move(v.failures[step])
                                  : BuildError{"internal error: variant " + v.keyText + " was not built", {}};
      return std::nullopt;
    }
    const uint32_t index = uint32_t(result.package.variants.size());
    if (v.samplesSpecularLut) lutVariants.push_back(index);
    if (!v.preshader.empty()) {
      // Variants with the same program (every tier but the gamma hack's, say) share one entry.
      std::vector<package::PreshaderProgram>& programs = result.package.preshader.programs;
      auto same = std::find_if(programs.begin(), programs.end(),
                               [&](const package::PreshaderProgram& p) { return p.ops == v.preshader; });
      if (same == programs.end()) {
        programs.push_back({{}, std::move(v.preshader)});
        same = programs.end() - 1;
      }
      same->variants.push_back(index);
      result.package.preshader.blockSize = preshade.blockSize;
    }
    result.package.variants.push_back(std::move(v.variant));
    for (GeneratedFile& f : v.sources) result.sources.push_back(std::move(f));
    result.libraryFiles.insert(v.libraryFiles.begin(), v.libraryFiles.end());
    result.cacheHits += v.cacheHit ? 1 : 0;
    result.cacheRejected += v.cacheRejected ? 1 : 0;
  }
  if (options.cacheMaxBytes > 0) cache.trim(options.cacheMaxBytes);
  // The `lut` tier's table travels with the package (section TEXS), so the runtime needs no
  // compiler code and the texels always match the chunk that decodes them.
  if (!lutVariants.empty()) {
    SpecularLut lut = generateSpecularLut();
    result.package.textures.push_back({kSpecularLutSamplerName, lut.width, lut.height, package::TexelFormat::R8Unorm,
                                       std::move(lut.texels), std::move(lutVariants)});
  }
  return result;
}

}  // namespace facet::compiler
