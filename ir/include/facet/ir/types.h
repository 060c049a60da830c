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
// Srgb: colour, decoded to linear by the sampler. Linear: data (masks, roughness) read as stored.
// Normal: a tangent-space normal map, 8-bit RGB with 128 = 0; sample() returns the decoded vec3
// xyz = rgb · 255/127 − 128/127 (so a flat texel (128, 128, 255) decodes to exactly (0, 0, 1)).
enum class TextureSpace { None, Srgb, Linear, Normal };

struct ParsedType {
  Type type;
  bool isColor = false;
  TextureSpace textureSpace = TextureSpace::None;
};
// `texture` takes its colour space as an argument: texture(srgb), texture(linear), texture(normal).
std::optional<ParsedType> parseTypeName(std::string_view name, std::string_view argument = {});

}  // namespace facet::ir
