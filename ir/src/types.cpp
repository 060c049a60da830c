#include "facet/ir/types.h"

namespace facet::ir {

const char* glslName(Type t) {
  switch (t) {
    case Type::Float: return "float";
    case Type::Vec2: return "vec2";
    case Type::Vec3: return "vec3";
    case Type::Vec4: return "vec4";
    case Type::Int: return "int";
    case Type::Bool: return "bool";
    case Type::Texture2D: return "sampler2D";
  }
  return "float";
}

const char* typeName(Type t) { return t == Type::Texture2D ? "texture" : glslName(t); }

std::optional<ParsedType> parseTypeName(std::string_view name, std::string_view argument) {
  if (name == "texture") {
    if (argument == "srgb") return ParsedType{Type::Texture2D, false, TextureSpace::Srgb};
    if (argument == "linear") return ParsedType{Type::Texture2D, false, TextureSpace::Linear};
    if (argument == "normal") return ParsedType{Type::Texture2D, false, TextureSpace::Normal};
    return std::nullopt;
  }
  if (!argument.empty()) return std::nullopt;
  if (name == "float") return ParsedType{Type::Float};
  if (name == "vec2") return ParsedType{Type::Vec2};
  if (name == "vec3") return ParsedType{Type::Vec3};
  if (name == "vec4") return ParsedType{Type::Vec4};
  if (name == "int") return ParsedType{Type::Int};
  if (name == "bool") return ParsedType{Type::Bool};
  if (name == "color") return ParsedType{Type::Vec3, true};
  return std::nullopt;
}

}  // namespace facet::ir
