// Per-GPU statistics of GLSL ES shader pairs from Mesa's compilers on drm-shim fake devices
// (docs/mesa-statistics.md): `matc lint --gpu` and `matc eval --gpu`. The compile runs in a child
// process, tools/mesa_stats/mesa_compile.py, because the fake device is LD_PRELOADed into the
// process that loads Mesa; matc itself never loads it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace facet::gpu_stats {

// The GPUs mesa_compile.py fakes, in its spelling: mali-g52 (Bifrost), mali-g57 (Valhall),
// adreno-630 (ir3).
const std::vector<std::string>& knownGpus();

// "mali-g52,adreno-630" -> the list, in order, without repeats. False with *error naming an
// unknown GPU (and the known ones) or an empty list.
bool parseGpuList(const std::string& text, std::vector<std::string>* gpus, std::string* error);

// Where the tool and the compilers are. Empty fields take the defaults: python3 from PATH; the
// script from $FACET_MESA_COMPILE, else this source tree's tools/mesa_stats/mesa_compile.py; the
// Mesa build as mesa_compile.py finds it ($MESA_PREFIX, $MESA_CACHE_DIR/install, else
// ~/.cache/facet/mesa/install: scripts/build-mesa-shader-compilers.sh's cache folder).
struct MesaTool {
  std::string python;
  std::string script;
  std::string prefix;
};

struct ShaderPair {
  std::string name;        // e.g. a variant key
  std::string vertexGlsl;  // GLSL ES 3.00 source text
  std::string fragmentGlsl;
};

// One shader as a driver compiled it. Mali splits a vertex shader into vertex_position and
// vertex_varying (IDVS); Adreno adds vertex_binning.
struct StageStats {
  std::string stage;  // fragment, vertex, vertex_position, vertex_varying, vertex_binning
  double instructions = 0;
  std::optional<double> cycles;  // Mali: Mesa's cycle bound; ir3 prints none
  std::string bound;             // Mali: the pipe that bounds it (fma, cvt, sfu, v, t, ls / arith, ...)
  std::optional<int> threads;    // Mali: threads per core (occupancy)
  std::optional<int> waves;      // Adreno: waves (occupancy)
  std::optional<int> spills;     // Mali; ir3 22.3 prints none
};

struct GpuStats {
  std::string gpu;       // as asked, e.g. "mali-g57"
  std::string renderer;  // as the driver names itself, e.g. "Mali-G57 (Panfrost)"
  // Non-empty when this GPU gave no figures: the compilers are not built, the tool cannot run,
  // or a shader did not compile. The tool's own message, on one line.
  std::string unavailable;
  std::map<std::string, std::vector<StageStats>> shaders;  // by ShaderPair::name, stages sorted
  const StageStats* find(const std::string& pair, const std::string& stage) const;
};

// Compiles every pair on every GPU (one child process per GPU). Never throws; a GPU whose
// figures cannot be had says why in `unavailable`.
std::vector<GpuStats> measure(const std::vector<ShaderPair>& pairs, const std::vector<std::string>& gpus,
                              const MesaTool& tool = {});

}  // namespace facet::gpu_stats
