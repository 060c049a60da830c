// Maps errors a backend reports in generated GLSL back to the material source that produced the
// offending line, so a user sees `brick.mat:7:16: error: ...`, not a line of generated code.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/ir/diagnostics.h"

namespace facet::compiler {

struct MappedError {
  std::string message;  // the backend's message for the first error in the surface program
  ir::SourceLoc loc;
};

// Reads glslang's log ("ERROR: 0:<line>: <message>") and returns the first error whose line
// falls inside the surface body (body line k is text line surfaceFirstLine + k), mapped through
// lineLocs. nullopt when no error lies in the surface program (then it is the compiler's own).
std::optional<MappedError> mapGlslangErrors(const std::string& log, uint32_t surfaceFirstLine,
                                            const std::vector<ir::SourceLoc>& lineLocs);

}  // namespace facet::compiler
