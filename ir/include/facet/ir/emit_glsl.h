// GLSL emission of a checked surface program: the body of `evaluate_surface`, one statement per
// IR value, named after the `let` that bound it where there is one.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "facet/ir/module.h"

namespace facet::ir {

struct SurfaceGlsl {
  std::string body;                  // statements, each on its own line, indented 4 spaces
  std::set<std::string> attributes;  // vertex.* attributes the outputs depend on
  std::set<std::string> params;      // parameters the outputs depend on
  std::vector<SourceLoc> lineLocs;   // per line of `body`: the material source that produced it
};

// Emits only what the written outputs depend on; unused lets and reads vanish.
SurfaceGlsl emitSurface(const Material& material);

// A GLSL literal for a constant value, e.g. "0.5", "vec3(1.0, 0.25, 0.0)", "(-2.0)".
std::string glslConstant(Type type, const std::array<double, 4>& c);

}  // namespace facet::ir
