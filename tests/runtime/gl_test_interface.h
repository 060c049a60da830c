// The interface the hand-written GLSL ES 3.00 test shaders share (test_gl_backend, test_textures):
// shader_abi.h's first three vertex inputs and the instance transform, the leading members of its frame block and its
// object block with the decode of the packed streams. A block may end early: the GL backend checks only that it is no
// larger than the ABI's. Macros of string literals, so a shader is written as adjacent literals around them.
#pragma once

#define FACET_GL_TEST_FRAME_BLOCK            \
  "layout(std140) uniform FrameUniforms {\n" \
  "  mat4 viewProjection;\n"                 \
  "  vec4 cameraPosition;\n"                 \
  "  vec4 lightDirection;\n"                 \
  "  vec4 lightColor;\n"                     \
  "  vec4 ambient;\n"                        \
  "};\n"

#define FACET_GL_TEST_VERTEX_INTERFACE                                     \
  "layout(location = 0) in vec3 position;\n"                               \
  "layout(location = 1) in vec3 normal;\n"                                 \
  "layout(location = 2) in vec2 uv0;\n"                                    \
  "layout(location = 6) in vec4 instanceRow0;\n"                           \
  "layout(location = 7) in vec4 instanceRow1;\n"                           \
  "layout(location = 8) in vec4 instanceRow2;\n" FACET_GL_TEST_FRAME_BLOCK \
  "layout(std140) uniform ObjectUniforms {\n"                              \
  "  vec4 positionScale;\n"                                                \
  "  vec4 positionOffset;\n"                                               \
  "  vec4 uv0ScaleOffset;\n"                                               \
  "  vec4 uv1ScaleOffset;\n"                                               \
  "};\n"

// The object-space position and uv0 of the mesh's packed streams (shader_abi.h's decode).
#define FACET_GL_TEST_POSITION "(position * positionScale.xyz + positionOffset.xyz)"
// World position of an object-space vec4 p: the instance's 4×3 transform (shader_abi.h).
#define FACET_GL_TEST_WORLD(p) "vec4(dot(instanceRow0, " p "), dot(instanceRow1, " p "), dot(instanceRow2, " p "), 1.0)"
#define FACET_GL_TEST_UV0 "(uv0 * uv0ScaleOffset.xy + uv0ScaleOffset.zw)"
