// The compile pipeline for one material, stage by stage (docs/architecture.md):
//   IR -> surface GLSL -> per variant: assemble (two flavours)
//     GLES flavour  -> glslang check as ES 3.00                      -> package (text)
//     Vulkan flavour -> glslang -> spirv-val -> spirv-opt -> spirv-val -> package (SPIR-V)
//                                                      \-> SPIRV-Cross -> package (MSL)
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "facet/ir/module.h"
#include "facet/package/package.h"
#include "facet/permutations/tiers.h"
#include "facet/permutations/variant_key.h"

namespace facet::compiler {

// "facet-matc <version>"; recorded in every package.
const std::string& compilerVersion();

struct GeneratedFile {
  std::string name;  // e.g. "brass.high.dir1.frag.es300.glsl"
  std::string text;
};

struct BuildResult {
  package::Package package;
  // With BuildOptions::emitSources: every generated source (`matc compile --emit-source`), in
  // variant order; empty otherwise.
  std::vector<GeneratedFile> sources;
  // The templates/ and chunks/ files (glslLibrary() names) any built variant was assembled from.
  std::set<std::string> libraryFiles;
  size_t cacheHits = 0;  // variants taken from BuildOptions::cacheDir instead of compiled
  // Cache entries that failed the checks fresh output passes (spirv-val, glslang): compiled
  // again and replaced.
  size_t cacheRejected = 0;
};

// matc compile's bound on the variant cache: about 27,000 variants of the example materials
// (19.4 KB each on average, docs/build-integration.md).
inline constexpr uint64_t kDefaultCacheMaxBytes = uint64_t(512) << 20;

// Makes `dir` a variant cache (BuildOptions::cacheDir), or checks that it is one. The cache deletes
// what it holds, so it only takes a folder it can tell is its own: one that does not exist yet
// or is empty (created, then marked with a file `facet-variant-cache` whose first line is the
// format's version), one with that marker, or one that holds nothing but cache entries (written
// before the marker existed; marked now). A regular file, a non-empty folder of other files and a
// cache of another format are refused with *error saying why. buildMaterial runs it and fails
// with the same message.
bool prepareVariantCache(const std::string& dir, std::string* error);

// One compile job's wall-clock span and the pool thread (0 .. jobs-1) that ran it: what
// bench_compile's "busy" figure (how much of the pool's time its threads had work) is made of.
struct JobSpan {
  double start = 0;  // seconds on std::chrono::steady_clock
  double end = 0;
  unsigned thread = 0;
};

struct BuildOptions {
  std::vector<permutations::Tier> tiers = permutations::supportedTiers();
  std::optional<permutations::SceneNeeds> scene;  // set: build only what the scene asks for
  std::vector<int> pointLightCounts{0};           // without a scene: the point-light permutations to build
  std::vector<int> shadowCascadeCounts{0};        // without a scene: the sun-shadow receiver permutations
  bool spotShadows = false;  // without a scene: each variant with point lights also as a spot-shadow receiver (.sp1)
  // Without a scene: the depth-only programs also with the vertex-stage slope bias (.depth.slope).
  bool vertexSlopeBias = false;
  // Testing only, never for shipping: the SPIR-V (Vulkan) target of mediump tiers rounds every
  // RelaxedPrecision float result to binary16 (OpQuantizeToF16), so lavapipe, which computes
  // mediump in fp32, shows what a mobile GPU's fp16 ALUs would. GLSL ES, MSL and highp tiers
  // (`reference`) are unchanged. docs/fp16-emulation.md.
  bool fp16Emulation = false;
  // Testing only, never for shipping: the SPIR-V target of mediump tiers computes in 16-bit
  // floats (spirv-opt --convert-relaxed-to-half, image operands back to 32-bit:
  // lower_half_image_operands.h), for a Vulkan device with shaderFloat16
  // (VulkanOptions::float16Arithmetic): the fp16 arithmetic the emulation models, done by the
  // device. Not with fp16Emulation. docs/fp16-emulation.md, "True half".
  bool fp16TrueHalf = false;
  // Evaluation only (`matc eval`, `matc tune`): each variant carries its SPIR-V stages alone, the
  // code the Vulkan renderer runs and the cost model reads. The GLSL ES 3.00 is neither made nor
  // checked, no MSL is made, and an fp16-emulated stage is optimized once (its un-emulated copy
  // only fed the MSL). Not for shipping: a package's readers expect all three targets.
  bool spirvOnly = false;
  // Fill BuildResult::sources: the readable assembled GLSL of both flavours and the SPIR-V
  // disassembly cost time and are only wanted for debugging.
  bool emitSources = false;
  // Variants compiled at once; 0: one per hardware thread. The result is byte-identical for any
  // value.
  unsigned jobs = 0;
  // Content-addressed cache of compiled variants (compiler/src/variant_cache.h); "" for none.
  // The package is the same bytes with or without it. A folder prepareVariantCache refuses
  // fails the build.
  std::string cacheDir;
  // After the build, the least recently used entries are removed until the cache holds at most
  // this many bytes (0: no bound). matc's default is kDefaultCacheMaxBytes.
  uint64_t cacheMaxBytes = 0;
  // Called after each variant finishes (done of total), one call at a time, from any thread;
  // matc draws its terminal progress line with it.
  std::function<void(size_t done, size_t total)> progress;
  // Compute the inputs that depend only on parameters once on the CPU (compiler/preshader.h).
  // false: every variant computes them per pixel, as packages before format 1.3 did (tests and
  // `matc eval`'s before/after).
  bool preshader = true;
  // Benchmarks: when set, the span of every job of the pool is appended here.
  std::vector<JobSpan>* jobSpans = nullptr;
  // The tiers a tuning file chose (`<stem>.tuning.json`, docs/tune.md, "The tuning file"): each
  // replaces its tier's preset and the material's overrides for that tier, which the tuning was
  // searched from. A tier it leaves out ships its preset with the overrides.
  std::map<permutations::Tier, permutations::TierConfig> tunedTiers;
  // Evaluation only (`matc eval`, docs/eval.md): called with each tier's configuration after the
  // preset and the material's overrides (or the tuned tier) are applied, to change any choice of
  // it (a single-option swap). Unset: the tier as shipped.
  std::function<void(permutations::Tier, permutations::TierConfig*)> adjustTier;
};

// The maths a tier's variants use: options.tunedTiers' configuration of the tier, else the tier's
// preset with the material's overrides for that tier; then options.adjustTier.
permutations::TierConfig tierConfig(const ir::Material& material, permutations::Tier tier, const BuildOptions& options);

struct BuildError {
  std::string message;
  // Set when the failure traces back to a line of the material (a backend rejected code the
  // surface program produced); unset for the compiler's own defects.
  std::optional<ir::SourceLoc> loc;
};

// What the material asks of the permutation space: lit or not, casts the sun's shadow or not.
permutations::MaterialNeeds materialNeeds(const ir::Material& material);

// Builds every variant. Returns nullopt with *error set when a backend rejects generated code.
std::optional<BuildResult> buildMaterial(const ir::Material& material, const BuildOptions& options, BuildError* error);

}  // namespace facet::compiler
