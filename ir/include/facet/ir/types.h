// Value types of the material language. `color` parameters become Vec3 (linear) in the IR.
#pragma once

#include <optional>
#include <string_view>

namespace facet::ir {

// Texture2D: a texture parameter; its only use is as the first argument of sample().
enum class Type { Float, Vec2, Vec3, Vec4, Int, Bool, Texture2D };

inline int componentCount(Type t) {
  switch (t) {
    case Type::Vec2: return 2;
    case Type::Vec3: return 3;
    case Type::Vec4: return 4;
    default: return 1;
  }
}
inline bool isFloatType(Type t) { return t == Type::Float || t == Type::Vec2 || t == Type::Vec3 || t == Type::Vec4; }
inline Type floatVector(int n) { return n == 1 ? Type::Float : n == 2 ? Type::Vec2 : n == 3 ? Type::Vec3 : Type::Vec4; }

// GLSL spelling of the type.
const char* glslName(Type t);
// Language spelling; also parses parameter types (`color` maps to Vec3 with isColor set).
const char* typeName(Type t);
enum class TextureSpace { None, Srgb, Linear };

struct ParsedType {
  Type type;
  bool isColor = false;
  TextureSpace textureSpace = TextureSpace::None;
};
// `texture` takes its colour space as an argument: texture(srgb) or texture(linear).
std::optional<ParsedType> parseTypeName(std::string_view name, std::string_view argument = {});

}  // namespace facet::ir
