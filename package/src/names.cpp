// Names used in `matc info` output and in the compiler's parameter declarations.
#include <cctype>

#include "facet/package/package.h"

namespace facet::package {

const char* toString(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return "vertex";
    case Stage::Fragment: return "fragment";
  }
  return "unknown";
}

const char* toString(Target target) {
  switch (target) {
    case Target::GlslEs300: return "glsl_es_300";
    case Target::Spirv: return "spirv";
    case Target::Msl: return "msl";
  }
  return "unknown";
}

const char* toString(ParamType type) {
  switch (type) {
    case ParamType::Float: return "float";
    case ParamType::Vec2: return "vec2";
    case ParamType::Vec3: return "vec3";
    case ParamType::Vec4: return "vec4";
    case ParamType::Int: return "int";
    case ParamType::Bool: return "bool";
    case ParamType::Color: return "color";
    case ParamType::TextureSrgb: return "texture(srgb)";
    case ParamType::TextureLinear: return "texture(linear)";
    case ParamType::TextureNormal: return "texture(normal)";
  }
  return "unknown";
}

const char* toString(MslResource kind) {
  switch (kind) {
    case MslResource::Buffer: return "buffer";
    case MslResource::Texture: return "texture";
  }
  return "unknown";
}

const char* toString(TexelFormat format) {
  switch (format) {
    case TexelFormat::R8Unorm: return "r8_unorm";
  }
  return "unknown";
}

bool isValidName(std::string_view s) {
  if (s.empty() || s.size() > kMaxNameBytes || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

std::optional<ParamType> paramTypeFromString(std::string_view name) {
  for (ParamType t :
       {ParamType::Float, ParamType::Vec2, ParamType::Vec3, ParamType::Vec4, ParamType::Int, ParamType::Bool,
        ParamType::Color, ParamType::TextureSrgb, ParamType::TextureLinear, ParamType::TextureNormal}) {
    if (name == toString(t)) return t;
  }
  return std::nullopt;
}

}  // namespace facet::package
