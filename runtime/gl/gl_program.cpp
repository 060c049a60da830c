#include "gl_program.h"

#include <string>
#include <vector>

#include "facet/abi/shader_abi.h"

namespace facet::runtime::gl {
namespace {

std::string shaderInfoLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  if (length <= 0) return "(no info log)";
  std::vector<GLchar> log(static_cast<size_t>(length));
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return std::string(log.data());
}

std::string programInfoLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  if (length <= 0) return "(no info log)";
  std::vector<GLchar> log(static_cast<size_t>(length));
  glGetProgramInfoLog(program, length, nullptr, log.data());
  return std::string(log.data());
}

std::optional<Shader> compileStage(GLenum stage, const std::string& source, std::string* error) {
  const char* stageName = stage == GL_VERTEX_SHADER ? "vertex" : "fragment";
  if (source.empty()) {
    if (error) *error = std::string(stageName) + " shader source is empty";
    return std::nullopt;
  }
  Shader shader(glCreateShader(stage));
  const GLchar* text = source.c_str();
  const auto length = static_cast<GLint>(source.size());
  glShaderSource(shader.id(), 1, &text, &length);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    if (error) *error = std::string(stageName) + " shader failed to compile:\n" + shaderInfoLog(shader.id());
    return std::nullopt;
  }
  return shader;
}

// GLES 3.00 shaders carry no binding: the block is found by the table's name, bound to its binding.
UniformBlock bindBlock(GLuint program, const abi::BlockDesc& desc) {
  UniformBlock block;
  block.index = glGetUniformBlockIndex(program, std::string(desc.name).c_str());
  if (!block.present()) return block;  // the shader does not use this block
  glUniformBlockBinding(program, block.index, desc.binding);
  glGetActiveUniformBlockiv(program, block.index, GL_UNIFORM_BLOCK_DATA_SIZE, &block.dataSize);
  return block;
}

}  // namespace

std::optional<LinkedProgram> buildProgram(const std::string& vertexSource, const std::string& fragmentSource,
                                          std::string* error) {
  std::optional<Shader> vertex = compileStage(GL_VERTEX_SHADER, vertexSource, error);
  if (!vertex) return std::nullopt;
  std::optional<Shader> fragment = compileStage(GL_FRAGMENT_SHADER, fragmentSource, error);
  if (!fragment) return std::nullopt;

  LinkedProgram linked;
  linked.program = Program(glCreateProgram());
  const GLuint program = linked.program.id();
  glAttachShader(program, vertex->id());
  glAttachShader(program, fragment->id());
  glLinkProgram(program);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    if (error) *error = "program failed to link:\n" + programInfoLog(program);
    return std::nullopt;
  }
  // The linked program keeps the code; detaching lets the shader objects be freed now.
  glDetachShader(program, vertex->id());
  glDetachShader(program, fragment->id());

  linked.frame = bindBlock(program, abi::kFrameBlock);
  linked.object = bindBlock(program, abi::kObjectBlock);
  linked.material = bindBlock(program, abi::kMaterialBlock);
  linked.shadow = bindBlock(program, abi::kShadowBlock);
  if (!checkGlError("program link", error)) return std::nullopt;
  return linked;
}

}  // namespace facet::runtime::gl
