#include "gl_reflection.h"

#include <algorithm>
#include <string>

namespace facet::runtime::gl {
namespace {

using package::ReflectedBlock;
using package::ReflectedMember;
using package::ReflectedStage;
using package::ReflectedVariable;
using package::SamplerShape;
using package::ScalarKind;
using package::ValueType;

// Numeric GL types; everything else (samplers, images) is ScalarKind::Other.
ValueType valueType(GLenum type, GLint size, const std::string& name) {
  ValueType t;
  const auto set = [&](ScalarKind kind, uint32_t components, uint32_t columns = 1) {
    t.kind = kind;
    t.components = components;
    t.columns = columns;
  };
  switch (type) {
    case GL_FLOAT: set(ScalarKind::Float, 1); break;
    case GL_FLOAT_VEC2: set(ScalarKind::Float, 2); break;
    case GL_FLOAT_VEC3: set(ScalarKind::Float, 3); break;
    case GL_FLOAT_VEC4: set(ScalarKind::Float, 4); break;
    case GL_INT: set(ScalarKind::Int, 1); break;
    case GL_INT_VEC2: set(ScalarKind::Int, 2); break;
    case GL_INT_VEC3: set(ScalarKind::Int, 3); break;
    case GL_INT_VEC4: set(ScalarKind::Int, 4); break;
    case GL_UNSIGNED_INT: set(ScalarKind::Uint, 1); break;
    case GL_UNSIGNED_INT_VEC2: set(ScalarKind::Uint, 2); break;
    case GL_UNSIGNED_INT_VEC3: set(ScalarKind::Uint, 3); break;
    case GL_UNSIGNED_INT_VEC4: set(ScalarKind::Uint, 4); break;
    case GL_BOOL: set(ScalarKind::Bool, 1); break;
    case GL_BOOL_VEC2: set(ScalarKind::Bool, 2); break;
    case GL_BOOL_VEC3: set(ScalarKind::Bool, 3); break;
    case GL_BOOL_VEC4: set(ScalarKind::Bool, 4); break;
    case GL_FLOAT_MAT2: set(ScalarKind::Float, 2, 2); break;
    case GL_FLOAT_MAT3: set(ScalarKind::Float, 3, 3); break;
    case GL_FLOAT_MAT4: set(ScalarKind::Float, 4, 4); break;
    case GL_FLOAT_MAT2x3: set(ScalarKind::Float, 3, 2); break;
    case GL_FLOAT_MAT2x4: set(ScalarKind::Float, 4, 2); break;
    case GL_FLOAT_MAT3x2: set(ScalarKind::Float, 2, 3); break;
    case GL_FLOAT_MAT3x4: set(ScalarKind::Float, 4, 3); break;
    case GL_FLOAT_MAT4x2: set(ScalarKind::Float, 2, 4); break;
    case GL_FLOAT_MAT4x3: set(ScalarKind::Float, 3, 4); break;
    default: break;
  }
  // GL names an array "x[0]" and gives its length as the size.
  const bool array = size > 1 || (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0);
  t.arraySize = array ? uint32_t(std::max(size, 1)) : 0;
  return t;
}

std::string withoutArraySuffix(std::string name) {
  if (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0) name.resize(name.size() - 3);
  return name;
}

SamplerShape samplerShape(GLenum type) {
  return type == GL_SAMPLER_2D          ? SamplerShape::Flat2D
         : type == GL_SAMPLER_CUBE      ? SamplerShape::Cube
         : type == GL_SAMPLER_2D_SHADOW ? SamplerShape::Shadow2D
                                        : SamplerShape::Other;
}

struct Active {
  std::string name;
  GLint size = 0;
  GLenum type = GL_NONE;
};

Active activeUniform(GLuint program, GLuint index, GLint maxLength) {
  std::vector<GLchar> buffer(size_t(std::max(maxLength, 1)) + 1, 0);
  Active a;
  GLsizei length = 0;
  glGetActiveUniform(program, index, GLsizei(buffer.size()), &length, &a.size, &a.type, buffer.data());
  a.name.assign(buffer.data(), size_t(std::clamp<GLsizei>(length, 0, GLsizei(buffer.size()))));
  return a;
}

// Bytes of one member (std140: a vec3 is 12, a matrix a vec4 per column, an array its stride ×
// length, bounded below by the elements' own size).
uint32_t memberBytes(const ValueType& t) {
  const uint32_t columnBytes = t.columns > 1 ? 16 : 4 * t.components;
  return columnBytes * t.columns * std::max<uint32_t>(t.arraySize, 1);
}

}  // namespace

std::vector<ReflectedStage> reflectProgram(GLuint program, const Context::ResourceQueries& queries) {
  std::vector<ReflectedStage> stages(3);
  stages[0].stage = package::Stage::Vertex;
  stages[0].what = "vertex shader (GLSL ES)";
  stages[1].stage = package::Stage::Fragment;
  stages[1].what = "fragment shader (GLSL ES)";
  stages[2].what = "vertex or fragment shader (GLSL ES)";  // no program interface queries
  for (ReflectedStage& s : stages) s.bindsByName = true;

  GLint uniforms = 0, uniformNameMax = 0, blocks = 0, blockNameMax = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &uniforms);
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &uniformNameMax);
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCKS, &blocks);
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCK_MAX_NAME_LENGTH, &blockNameMax);

  for (GLint b = 0; b < blocks; ++b) {
    ReflectedBlock block;
    std::vector<GLchar> name(size_t(std::max(blockNameMax, 1)) + 1, 0);
    GLsizei length = 0;
    glGetActiveUniformBlockName(program, GLuint(b), GLsizei(name.size()), &length, name.data());
    block.name.assign(name.data(), size_t(std::clamp<GLsizei>(length, 0, GLsizei(name.size()))));
    GLint bytes = 0, memberCount = 0, byVertex = 0, byFragment = 0;
    glGetActiveUniformBlockiv(program, GLuint(b), GL_UNIFORM_BLOCK_DATA_SIZE, &bytes);
    glGetActiveUniformBlockiv(program, GLuint(b), GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS, &memberCount);
    glGetActiveUniformBlockiv(program, GLuint(b), GL_UNIFORM_BLOCK_REFERENCED_BY_VERTEX_SHADER, &byVertex);
    glGetActiveUniformBlockiv(program, GLuint(b), GL_UNIFORM_BLOCK_REFERENCED_BY_FRAGMENT_SHADER, &byFragment);
    block.bytes = uint32_t(std::max(bytes, 0));
    std::vector<GLint> indices(size_t(std::clamp(memberCount, 0, uniforms)));
    if (!indices.empty())
      glGetActiveUniformBlockiv(program, GLuint(b), GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES, indices.data());
    for (GLint index : indices) {
      if (index < 0 || index >= uniforms) continue;
      const Active a = activeUniform(program, GLuint(index), uniformNameMax);
      GLint offset = 0;
      const GLuint u = GLuint(index);
      glGetActiveUniformsiv(program, 1, &u, GL_UNIFORM_OFFSET, &offset);
      ReflectedMember m;
      const size_t dot = a.name.rfind('.');
      m.name = withoutArraySuffix(dot == std::string::npos ? a.name : a.name.substr(dot + 1));
      m.offset = uint32_t(std::max(offset, 0));
      m.type = valueType(a.type, a.size, a.name);
      m.size = memberBytes(m.type);
      block.members.push_back(std::move(m));
    }
    if (byVertex) stages[0].blocks.push_back(block);
    if (byFragment) stages[1].blocks.push_back(block);
  }

  for (GLint i = 0; i < uniforms; ++i) {
    const GLuint u = GLuint(i);
    GLint blockIndex = -1;
    glGetActiveUniformsiv(program, 1, &u, GL_UNIFORM_BLOCK_INDEX, &blockIndex);
    if (blockIndex != -1) continue;
    const Active a = activeUniform(program, u, uniformNameMax);
    std::vector<ReflectedStage*> users;
    if (queries.index && queries.values) {
      const GLuint resource = queries.index(program, GL_UNIFORM, a.name.c_str());
      const GLenum properties[2] = {GL_REFERENCED_BY_VERTEX_SHADER, GL_REFERENCED_BY_FRAGMENT_SHADER};
      GLint referenced[2] = {0, 0};
      if (resource != GL_INVALID_INDEX)
        queries.values(program, GL_UNIFORM, resource, 2, properties, 2, nullptr, referenced);
      if (referenced[0]) users.push_back(&stages[0]);
      if (referenced[1]) users.push_back(&stages[1]);
    }
    if (users.empty()) users.push_back(&stages[2]);
    const ValueType type = valueType(a.type, a.size, a.name);
    for (ReflectedStage* stage : users) {
      if (type.kind != ScalarKind::Other) {
        stage->unsupported.push_back("uniform '" + a.name + "' outside the ABI's blocks");
      } else {
        stage->samplers.push_back({withoutArraySuffix(a.name), 0, 0, samplerShape(a.type), type.arraySize});
      }
    }
  }

  GLint attributes = 0, attributeNameMax = 0;
  glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &attributes);
  glGetProgramiv(program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &attributeNameMax);
  for (GLint i = 0; i < attributes; ++i) {
    std::vector<GLchar> buffer(size_t(std::max(attributeNameMax, 1)) + 1, 0);
    GLsizei length = 0;
    GLint size = 0;
    GLenum type = GL_NONE;
    glGetActiveAttrib(program, GLuint(i), GLsizei(buffer.size()), &length, &size, &type, buffer.data());
    const std::string name(buffer.data(), size_t(std::clamp<GLsizei>(length, 0, GLsizei(buffer.size()))));
    if (name.rfind("gl_", 0) == 0) continue;  // built-ins (gl_VertexID) are not the stream's
    ReflectedVariable v;
    v.name = name;
    const GLint location = glGetAttribLocation(program, name.c_str());
    if (location >= 0) v.location = uint32_t(location);
    v.type = valueType(type, size, name);
    stages[0].inputs.push_back(std::move(v));
  }
  if (stages[2].samplers.empty() && stages[2].unsupported.empty()) stages.pop_back();
  return stages;
}

}  // namespace facet::runtime::gl
