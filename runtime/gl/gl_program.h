// Compiling and linking "#version 300 es" programs, and binding their uniform blocks to the ABI.
#pragma once

#include <optional>
#include <string>

#include "gl_objects.h"

namespace facet::runtime::gl {

// One of the ABI's uniform blocks as a linked program sees it.
struct UniformBlock {
  GLuint index = GL_INVALID_INDEX;  // GL_INVALID_INDEX: the program does not use the block
  GLint dataSize = 0;               // bytes the program reads (GL_UNIFORM_BLOCK_DATA_SIZE)
  bool present() const { return index != GL_INVALID_INDEX; }
};

struct LinkedProgram {
  Program program;
  UniformBlock frame;     // "FrameUniforms", bound to abi::kFrameBinding
  UniformBlock object;    // "ObjectUniforms", bound to abi::kObjectBinding
  UniformBlock material;  // "MaterialParams", bound to abi::kMaterialBinding
  UniformBlock shadow;    // "ShadowUniforms", bound to abi::kShadowBinding (shadow receivers)
};

// Compiles both stages, links them and binds the ABI blocks present in the program
// (GLSL ES 3.00 has no layout(binding), so the binding is set here by block name).
// On failure returns nullopt and sets *error to the failing stage and its info log.
std::optional<LinkedProgram> buildProgram(const std::string& vertexSource, const std::string& fragmentSource,
                                          std::string* error);

}  // namespace facet::runtime::gl
