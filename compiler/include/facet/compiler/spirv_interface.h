// The resources a shader stage asks a GLES 3.0 device for, read from its SPIR-V by SPIRV-Cross's
// reflection: what `matc lint` holds against the API's guaranteed minimums (a variant that needs
// more fails to link on some real device, however fast it is).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::compiler {

struct StageInterface {
  uint32_t samplers = 0;                   // combined image samplers (array elements counted)
  uint32_t inputVectors = 0;               // vec4 slots of the stage inputs: vertex attributes, or varyings
  uint32_t outputVectors = 0;              // vec4 slots of the stage outputs: varyings, or colour outputs
  uint32_t uniformVectors = 0;             // vec4 slots of the uniform blocks the stage's code reaches
  std::vector<std::string> relaxedInputs;  // names of stage inputs decorated RelaxedPrecision (mediump)
};

// Returns false with *error on SPIR-V SPIRV-Cross cannot parse.
bool analyseStageInterface(const std::vector<uint32_t>& words, StageInterface* out, std::string* error);

// OpenGL ES 3.0 minimum maximums (ES 3.0.6 spec, table 6.33 "Implementation Dependent Values").
struct Gles30Limits {
  static constexpr uint32_t kVertexAttribs = 16;            // MAX_VERTEX_ATTRIBS
  static constexpr uint32_t kVaryingVectors = 15;           // MAX_VARYING_VECTORS
  static constexpr uint32_t kVertexUniformVectors = 256;    // MAX_VERTEX_UNIFORM_VECTORS
  static constexpr uint32_t kFragmentUniformVectors = 224;  // MAX_FRAGMENT_UNIFORM_VECTORS
  static constexpr uint32_t kFragmentSamplers = 16;         // MAX_TEXTURE_IMAGE_UNITS
  static constexpr uint32_t kVertexSamplers = 16;           // MAX_VERTEX_TEXTURE_IMAGE_UNITS
};

}  // namespace facet::compiler
