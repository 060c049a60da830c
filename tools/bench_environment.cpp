// Per-scene environment set-up benchmarks (Google Benchmark; built with the tests, never run by
// ctest): the irradiance cube SceneFrame builds for every lit scene, whether or not a variant reads
// it (the package does not record which tiers do). Run from the source root:
//   build/test/tests/bench_environment
// Results: docs/ibl.md, "In the shaders".
#include <benchmark/benchmark.h>

#include "facet/runtime/environment.h"

namespace {

// A sky-like SH3 (the frame block's pre-folded coefficients): every band non-zero, so no term of
// the sum is skipped.
facet::runtime::EnvironmentLighting skyLighting() {
  facet::runtime::EnvironmentLighting lighting;
  for (size_t k = 0; k < lighting.sh.size(); ++k)
    lighting.sh[k] = {0.3f + 0.1f * float(k), 0.2f + 0.05f * float(k), 0.1f + 0.02f * float(k)};
  return lighting;
}

void irradianceCube(benchmark::State& state) {
  const facet::runtime::EnvironmentLighting lighting = skyLighting();
  for (auto _ : state) benchmark::DoNotOptimize(facet::runtime::irradianceTexture(lighting));
}
BENCHMARK(irradianceCube)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
