// The interface the hand-written GLSL ES 3.00 test shaders share (test_gl_backend, test_textures):
// shader_abi.h's first three vertex inputs and the leading members of its frame and object
// blocks. A block may end early: the GL backend checks only that it is no larger than the ABI's.
// Macros of string literals, so a shader is written as adjacent literals around them.
#pragma once

#define FACET_GL_TEST_FRAME_BLOCK            \
  "layout(std140) uniform FrameUniforms {\n" \
  "  mat4 viewProjection;\n"                 \
  "  vec4 cameraPosition;\n"                 \
  "  vec4 lightDirection;\n"                 \
  "  vec4 lightColor;\n"                     \
  "  vec4 ambient;\n"                        \
  "};\n"

#define FACET_GL_TEST_VERTEX_INTERFACE                            \
  "layout(location = 0) in vec3 position;\n"                      \
  "layout(location = 1) in vec3 normal;\n"                        \
  "layout(location = 2) in vec2 uv0;\n" FACET_GL_TEST_FRAME_BLOCK \
  "layout(std140) uniform ObjectUniforms {\n"                     \
  "  mat4 model;\n"                                               \
  "  mat4 normalMatrix;\n"                                        \
  "};\n"
