#include "facet/compiler/build.h"

#include <algorithm>
#include <cstring>
#include <mutex>

#include "facet/compiler/assemble.h"
#include "facet/compiler/backend_errors.h"
#include "facet/compiler/glslang_backend.h"
#include "facet/compiler/msl_backend.h"
#include "facet/compiler/param_layout.h"
#include "facet/compiler/preshader.h"
#include "facet/compiler/specular_lut.h"
#include "facet/compiler/spirv_tools_backend.h"
#include "facet/ir/emit_glsl.h"
#include "facet/ir/passes.h"
#include "facet/compiler/minify_glsl.h"
#include "facet/compiler/lower_relaxed_to_quantized.h"
#include "parallel_for.h"
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

// BuildOptions::fp16Emulation: glslang's unoptimized stages with every relaxed float result
// rounded to binary16, then validated and optimized as usual.
bool emulateFp16(SpirvStages* stages, std::string* error) {
  for (auto [words, stage] : {std::pair{&stages->vertex, "fp16-emulated vertex"}, {&stages->fragment, "fp16-emulated fragment"}}) {
    QuantizeCounts counts;
    if (!lowerRelaxedToQuantized(words, &counts, error) || !finishSpirv(words, stage, error)) return false;
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

// What every variant of one material shares; read-only while variants build in parallel.
struct MaterialContext {
  const ir::Material& material;
  const ir::SurfaceGlsl& surface;
  const ParamLayout& layout;
  const PreshadeLayout& preshade;
  const BuildOptions& options;
  const VariantCache& cache;
  const std::vector<package::MslBinding>& mslBindings;  // Metal slots, the same for every variant
};

// One variant's share of the result, written by exactly one job.
struct VariantBuild {
  package::Variant variant;
  std::vector<GeneratedFile> sources;
  bool samplesSpecularLut = false;
  std::vector<package::PreshaderOp> preshader;  // empty: the variant preshades nothing
  bool cacheHit = false;
  std::set<std::string> libraryFiles;
  BuildError failure;
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

// The glslang, SPIRV-Tools and SPIRV-Cross work of one variant: what the cache saves.
bool compileVariant(const MaterialContext& ctx, const permutations::TierConfig& tier, const StageSources& es,
                    const StageSources& vk, const std::string& keyText, CompiledShaders* out, BuildError* failure) {
  std::string* error = &failure->message;
  std::string log;
  StageSources shipped;
  if (!shippedGlslEs(es, &shipped, &log)) {
    // Only on failure is the readable text checked (one glslang parse saved per variant): its
    // line numbers map an error back to the material; if it compiles, the minifier is at fault.
    std::string readableLog;
    if (!checkGlslEs300(es, &readableLog)) {
      reportGlslangFailure(readableLog, es, ctx.surface, "GLSL ES 3.00 for variant " + keyText, failure);
      return false;
    }
    *error = "internal error: the minified GLSL ES 3.00 of variant " + keyText + " does not compile:\n" + log;
    return false;
  }
  log.clear();
  SpirvStages spirv;
  if (!compileToSpirv(vk, &spirv, &log)) {
    reportGlslangFailure(log, vk, ctx.surface, "SPIR-V for variant " + keyText, failure);
    return false;
  }
  // fp16 emulation replaces only the Vulkan target; it must see the stages before spirv-opt.
  std::optional<SpirvStages> emulated;
  if (ctx.options.fp16Emulation && tier.precision == permutations::PrecisionPolicy::Mediump) {
    emulated = spirv;
    if (!emulateFp16(&*emulated, error)) return false;
  }
  if (!finishSpirv(&spirv.vertex, "vertex", error) || !finishSpirv(&spirv.fragment, "fragment", error)) return false;
  const SpirvStages& vulkan = emulated ? *emulated : spirv;
  // Metal: mediump becomes `half` (16-bit) through spirv-opt, as on GLES drivers.
  std::vector<uint32_t> metalVertex = spirv.vertex, metalFragment = spirv.fragment;
  if (!convertRelaxedToHalf(&metalVertex, &log) || !convertRelaxedToHalf(&metalFragment, &log)) {
    *error = "internal error: spirv-opt --convert-relaxed-to-half failed for variant " + keyText + ":\n" + log;
    return false;
  }
  std::string mslVertex, mslFragment;
  if (!spirvToMsl(metalVertex, ctx.mslBindings, &mslVertex, error) ||
      !spirvToMsl(metalFragment, ctx.mslBindings, &mslFragment, error))
    return false;
  *out = {bytesOf(shipped.vertex), bytesOf(shipped.fragment), bytesOf(vulkan.vertex),
          bytesOf(vulkan.fragment), bytesOf(mslVertex),       bytesOf(mslFragment)};
  return true;
}

// Everything one variant needs, from assembly to its package entry. Runs on any thread.
bool buildVariant(const MaterialContext& ctx, const permutations::VariantKey& key, VariantBuild* out) {
  const ir::Material& material = ctx.material;
  std::string* error = &out->failure.message;
  const std::string keyText = key.toString();
  const permutations::TierConfig tier = tierConfig(material, key.tier, ctx.options);
  AssemblyInput input{material, ctx.surface, ctx.layout, key, tier, compilerVersion()};
  out->preshader = preshaderProgram(material, ctx.layout, ctx.preshade, tier);
  if (!out->preshader.empty()) input.preshade = &ctx.preshade;
  StageSources es, vk;
  if (!assemble(input, Flavour::GlslEs300, &es, error) || !assemble(input, Flavour::Vulkan, &vk, error)) return false;

  // The same text compiles to the same code, so a cached variant skips every backend.
  const std::string cacheKey = variantCacheKey(compilerVersion(), es, vk, ctx.options.fp16Emulation);
  CompiledShaders shaders;
  if (std::optional<CompiledShaders> cached = ctx.cache.load(cacheKey)) {
    shaders = std::move(*cached);
    out->cacheHit = true;
  } else {
    if (!compileVariant(ctx, tier, es, vk, keyText, &shaders, &out->failure)) return false;
    ctx.cache.store(cacheKey, shaders);
  }

  if (ctx.options.emitSources) {
    // Debug sources: the readable assembled text of both flavours beside what ships.
    const std::string stem = material.name + "." + keyText;
    auto text = [&](size_t i) { return std::string(shaders[i].begin(), shaders[i].end()); };
    out->sources = {
        {stem + ".vert.es300.glsl", text(0)},
        {stem + ".frag.es300.glsl", text(1)},
        {stem + ".vert.es300.readable.glsl", es.vertex},
        {stem + ".frag.es300.readable.glsl", es.fragment},
        {stem + ".vert.vulkan.glsl", vk.vertex},
        {stem + ".frag.vulkan.glsl", vk.fragment},
        {stem + ".vert.spvasm", disassembleSpirv(wordsOf(shaders[2]))},
        {stem + ".frag.spvasm", disassembleSpirv(wordsOf(shaders[3]))},
        {stem + ".vert.metal", text(4)},
        {stem + ".frag.metal", text(5)},
    };
  }
  using package::Stage;
  using package::Target;
  out->variant.key = keyText;
  out->variant.shaders = {
      {Stage::Vertex, Target::GlslEs300, std::move(shaders[0])}, {Stage::Fragment, Target::GlslEs300, std::move(shaders[1])},
      {Stage::Vertex, Target::Spirv, std::move(shaders[2])},     {Stage::Fragment, Target::Spirv, std::move(shaders[3])},
      {Stage::Vertex, Target::Msl, std::move(shaders[4])},       {Stage::Fragment, Target::Msl, std::move(shaders[5])},
  };
  out->samplesSpecularLut = samplesSpecularLut(input);
  out->libraryFiles = es.libraryFiles;
  out->libraryFiles.insert(vk.libraryFiles.begin(), vk.libraryFiles.end());
  return true;
}

}  // namespace

const std::string& compilerVersion() {
  static const std::string version = std::string("facet-matc ") + FACET_VERSION;
  return version;
}

permutations::TierConfig tierConfig(const ir::Material& material, permutations::Tier tierName, const BuildOptions& options) {
  // The tier's preset, with the material's overrides for that tier (checked by ir::check).
  permutations::TierConfig tier = permutations::preset(tierName);
  for (const ir::TierOverride& o : material.tierOverrides)
    if (o.tier == permutations::toString(tierName)) permutations::applyOverride(&tier, o.axis, o.option);
  if (options.adjustTier) options.adjustTier(tierName, &tier);
  return tier;
}

std::optional<BuildResult> buildMaterial(const ir::Material& checked, const BuildOptions& options, BuildError* failure) {
  BuildResult result;
  ir::Material material = checked;
  ir::optimize(material);
  ParamLayout layout = layoutParams(material.params);
  const PreshadeLayout preshade = options.preshader ? planPreshade(material, layout) : PreshadeLayout{};
  ir::SurfaceGlsl surface = ir::emitSurface(material);
  result.package.compilerVersion = compilerVersion();
  result.package.material = materialInfo(material, layout);

  permutations::MaterialNeeds needs;
  needs.lit = material.shading == "lit";
  const permutations::SceneNeeds* scene = options.scene ? &*options.scene : nullptr;
  const std::vector<permutations::VariantKey> keys = permutations::enumerate(needs, options.tiers, scene, options.pointLightCounts);

  // Jobs finish in any order; each writes only its own slot, and the slots are read in key order.
  VariantCache cache(options.cacheDir);
  result.package.mslBindings = materialMslBindings(result.package.material);
  MaterialContext ctx{material, surface, layout, preshade, options, cache, result.package.mslBindings};
  std::vector<VariantBuild> builds(keys.size());
  std::vector<char> done(keys.size(), 0);
  std::mutex progressMutex;
  size_t finished = 0;
  parallelFor(keys.size(), options.jobs, [&](size_t i) {
    done[i] = buildVariant(ctx, keys[i], &builds[i]);
    if (options.progress) {
      std::lock_guard<std::mutex> lock(progressMutex);
      options.progress(++finished, keys.size());
    }
    return done[i] != 0;
  });

  std::vector<uint32_t> lutVariants;  // indices of the variants that sample the specular table
  for (size_t i = 0; i < keys.size(); ++i) {
    if (!done[i]) {  // the first failure in key order, whatever the job count
      *failure = std::move(builds[i].failure);
      return std::nullopt;
    }
    const uint32_t index = uint32_t(result.package.variants.size());
    if (builds[i].samplesSpecularLut) lutVariants.push_back(index);
    if (!builds[i].preshader.empty()) {
      // Variants with the same program (every tier but the gamma hack's, say) share one entry.
      std::vector<package::PreshaderProgram>& programs = result.package.preshader.programs;
      auto same = std::find_if(programs.begin(), programs.end(),
                               [&](const package::PreshaderProgram& p) { return p.ops == builds[i].preshader; });
      if (same == programs.end()) {
        programs.push_back({{}, std::move(builds[i].preshader)});
        same = programs.end() - 1;
      }
      same->variants.push_back(index);
      result.package.preshader.blockSize = preshade.blockSize;
    }
    result.package.variants.push_back(std::move(builds[i].variant));
    for (GeneratedFile& f : builds[i].sources) result.sources.push_back(std::move(f));
    result.libraryFiles.insert(builds[i].libraryFiles.begin(), builds[i].libraryFiles.end());
    result.cacheHits += builds[i].cacheHit ? 1 : 0;
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
