// glslang: GLSL -> SPIR-V (Vulkan flavour), and the GLSL ES 3.00 validity check (GLES flavour).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/compiler/assemble.h"

namespace facet::compiler {

struct SpirvStages {
  std::vector<uint32_t> vertex;
  std::vector<uint32_t> fragment;
};

// Compiles and links both stages (ES 3.10, Vulkan 1.0 rules) to SPIR-V 1.0. On failure returns
// false with glslang's log, prefixed by the stage.
bool compileToSpirv(const StageSources& sources, SpirvStages* out, std::string* log);

// Parses and links both stages as GLSL ES 3.00 for OpenGL ES, as a driver would. Returns false
// with glslang's log on failure.
bool checkGlslEs300(const StageSources& sources, std::string* log);

// Runs glslang's preprocessor on both stages as GLSL ES 3.00: #if branches resolved, macros
// expanded, comments gone; #version and #extension lines stay. Line numbers of the result do not
// map back to the input (fragmentSurfaceLine is cleared).
bool preprocessGlslEs300(const StageSources& sources, StageSources* out, std::string* log);

}  // namespace facet::compiler
