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
  }
  return "float";
}

const char* typeName(Type t) { return glslName(t); }

std::optional<ParsedType> parseTypeName(std::string_view name) {
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
