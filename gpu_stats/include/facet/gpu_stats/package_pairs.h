// A package's own GLSL ES 3.00 vertex + fragment pairs, as gpu_stats::measure takes them: what
// the runtime's GL path hands the driver is what is measured (docs/mesa-statistics.md).
#pragma once

#include <string>
#include <vector>

#include "facet/gpu_stats/mesa_compile.h"
#include "facet/package/package.h"

namespace facet::gpu_stats {

// One pair per variant that has both GLSL ES stages, named by its key; `keys` limits the
// variants (empty: all), in the package's order.
std::vector<ShaderPair> glslEsPairs(const package::Package& pkg, const std::vector<std::string>& keys = {});

}  // namespace facet::gpu_stats
