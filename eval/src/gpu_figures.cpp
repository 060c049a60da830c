// addGpuFigures: the measured configurations' shaders on Mesa's compilers (gpu_stats), after the
// evaluation, so that the rendering and its timing never share the machine with the compiles.
#include "facet/eval/evaluate.h"

namespace facet::eval {

void addGpuFigures(EvalReport* report, const std::vector<std::string>& gpus, const gpu_stats::MesaTool& tool) {
  std::vector<gpu_stats::ShaderPair> pairs;
  for (const ConfigurationResult& c : report->results) {
    if (!c.sameAs.empty()) continue;
    for (gpu_stats::ShaderPair p : c.glslEs) {
      p.name = c.configuration.name;
      pairs.push_back(std::move(p));
    }
  }
  report->gpuStats = gpu_stats::measure(pairs, gpus, tool);
}

}  // namespace facet::eval
