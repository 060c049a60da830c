// A linked "#version 300 es" program's interface as GL reflects it, in the form the runtime's
// interface check reads (facet/package/program_interface.h): what the GL backend holds against the package
// before a program's first draw, since the GLSL ES text of a package is never seen by the core.
#pragma once

#include <vector>

#include "facet/package/program_interface.h"
#include "gl_context.h"

namespace facet::runtime::gl {

// Blocks (GL_UNIFORM_BLOCK_DATA_SIZE, members with GL_UNIFORM_OFFSET and types) per stage that
// references them; default-block uniforms, which must be samplers (GL_SAMPLER_2D or
// GL_SAMPLER_CUBE), per stage when the context has program interface queries, else in one entry
// with no stage; the vertex stage's active attributes at their locations. Blocks and samplers are
// identified by name, as the backend binds them. Stage linkage is the GL linker's.
std::vector<package::ReflectedStage> reflectProgram(GLuint program, const Context::ResourceQueries& queries);

}  // namespace facet::runtime::gl
