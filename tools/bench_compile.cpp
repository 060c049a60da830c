// Compile-path benchmarks (Google Benchmark; built with the tests, never run by ctest — speed is
// measured here, not asserted): variants per second with 1 and 2 jobs, a cold, warm and
// one-tier-edited build against the variant cache, and Filament's matc on the equivalent
// material (tools/filament/red_plastic.mat) in the same run. Run from the source root:
//   build/test/tests/bench_compile --benchmark_counters_tabular=true
// Results and how to read them: docs/build-integration.md, "Benchmarks".
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "facet/compiler/build.h"
#include "facet/ir/check.h"

namespace {

namespace fs = std::filesystem;
using facet::compiler::BuildOptions;

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

facet::ir::Material load(const std::string& text) {
  facet::ir::SourceFile file{"red_plastic.mat", text};
  facet::ir::Diagnostics diags(file);
  auto material = facet::ir::compileSource(file, diags);
  if (!material) {
    std::fprintf(stderr, "%s", diags.format().c_str());
    std::exit(1);
  }
  return *material;
}

const std::string& materialText() {
  static const std::string text = readText(std::string(FACET_SOURCE_DIR) + "/examples/materials/red_plastic.mat");
  return text;
}

size_t build(const facet::ir::Material& material, const BuildOptions& options, benchmark::State& state) {
  facet::compiler::BuildError error;
  auto built = facet::compiler::buildMaterial(material, options, &error);
  if (!built) {
    state.SkipWithError(error.message.c_str());
    return 0;
  }
  return built->package.variants.size();
}

void reportRates(benchmark::State& state, size_t variants) {
  // A variant is 2 stages x 3 targets (GLSL ES, SPIR-V, MSL).
  state.counters["variants/s"] = benchmark::Counter(double(variants), benchmark::Counter::kIsRate);
  state.counters["stages/s"] = benchmark::Counter(double(variants * 6), benchmark::Counter::kIsRate);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peakRSS_MB"] = double(usage.ru_maxrss) / 1024.0;
}

std::string scratch(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("facet_bench_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(dir);
  return dir.string();
}

// Every variant of red_plastic (4 tiers x 2 light sets), no cache, on `jobs` threads. "busy" is
// the share of the pool's time (first job's start to last job's end, times the threads) its
// threads spent in jobs: 1 minus what load imbalance costs. Unlike the wall time it holds on a
// loaded machine, where the threads' slices shrink alike (docs/build-integration.md).
void BM_CompileNoCache(benchmark::State& state) {
  const facet::ir::Material material = load(materialText());
  BuildOptions options;
  options.jobs = unsigned(state.range(0));
  std::vector<facet::compiler::JobSpan> spans;
  options.jobSpans = &spans;
  size_t variants = 0;
  double inJobs = 0, available = 0;
  for (auto _ : state) {
    spans.clear();
    variants += build(material, options, state);
    double first = spans.empty() ? 0 : spans.front().start, last = first;
    for (const facet::compiler::JobSpan& s : spans) {
      inJobs += s.end - s.start;
      first = std::min(first, s.start);
      last = std::max(last, s.end);
    }
    available += (last - first) * options.jobs;
  }
  reportRates(state, variants);
  state.counters["busy"] = available > 0 ? inJobs / available : 0;
}
BENCHMARK(BM_CompileNoCache)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// Cold: an empty cache every iteration (compile everything and fill the cache).
void BM_CacheCold(benchmark::State& state) {
  const facet::ir::Material material = load(materialText());
  BuildOptions options;
  options.jobs = 1;
  options.cacheDir = scratch("cold");
  size_t variants = 0;
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(options.cacheDir);
    state.ResumeTiming();
    variants += build(material, options, state);
  }
  reportRates(state, variants);
  fs::remove_all(options.cacheDir);
}
BENCHMARK(BM_CacheCold)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// Warm: every variant in the cache.
void BM_CacheWarm(benchmark::State& state) {
  const facet::ir::Material material = load(materialText());
  BuildOptions options;
  options.jobs = 1;
  options.cacheDir = scratch("warm");
  build(material, options, state);
  size_t variants = 0;
  for (auto _ : state) variants += build(material, options, state);
  reportRates(state, variants);
  fs::remove_all(options.cacheDir);
}
BENCHMARK(BM_CacheWarm)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// One tier's text edited (a tier override on `high`, standing in for an edit of a chunk only
// that tier includes: both change the text, hence the key, of exactly those variants) against a
// cache warm for the unedited material.
void BM_CacheOneTierEdited(benchmark::State& state) {
  const facet::ir::Material original = load(materialText());
  std::string text = materialText();
  text.insert(text.find("    surface"), "    tier high { specular = ggx_fastv }\n");
  const facet::ir::Material edited = load(text);
  BuildOptions options;
  options.jobs = 1;
  const std::string warm = scratch("edit-warm");
  options.cacheDir = warm;
  build(original, options, state);
  options.cacheDir = scratch("edit");
  size_t variants = 0;
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(options.cacheDir);
    fs::copy(warm, options.cacheDir, fs::copy_options::recursive);
    state.ResumeTiming();
    variants += build(edited, options, state);
  }
  reportRates(state, variants);
  fs::remove_all(warm);
  fs::remove_all(options.cacheDir);
}
BENCHMARK(BM_CacheOneTierEdited)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// Filament's matc (Debian libfilament-tools 1.9.25) on the same material, every backend of its
// mobile profile, as a child process (wall time: it uses its own threads). It writes 120 shader
// stages (matinfo: 40 GLSL, 40 SPIR-V, 40 Metal) where Facet writes 48 for 8 variants.
void BM_FilamentMatc(benchmark::State& state) {
  const std::string out = scratch("filament") + ".filamat";
  const std::string command = "matc -p mobile -a all -o " + out + " " + std::string(FACET_SOURCE_DIR) +
                              "/tools/filament/red_plastic.mat > /dev/null 2>&1";
  for (auto _ : state) {
    if (std::system(command.c_str()) != 0) {
      state.SkipWithError("Filament's matc failed or is not installed (apt-get install libfilament-tools)");
      break;
    }
  }
  state.counters["stages/s"] = benchmark::Counter(120.0 * double(state.iterations()), benchmark::Counter::kIsRate);
  fs::remove(out);
}
BENCHMARK(BM_FilamentMatc)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
