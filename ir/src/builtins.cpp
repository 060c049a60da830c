#include "builtins.h"

#include <map>

namespace facet::ir {
namespace {

// How a built-in's arguments relate, in GLSL's genType terms.
enum class Shape {
  Unary,          // genType f(genType)
  Binary,         // genType f(genType, genType)
  BinaryScalarB,  // genType f(genType, genType | float)          min, max
  StepLike,       // genType f(genType | float, genType)          step
  Mix,            // genType f(genType, genType, genType | float)
  Clamp,          // genType f(genType, genType | float, genType | float)
  Smoothstep,     // genType f(genType | float, genType | float, genType)
  Reduce,         // float f(genType)                             length
  Dot,            // float f(genType, genType)
  Cross,          // vec3 f(vec3, vec3)
};

const std::map<std::string, Shape>& table() {
  static const std::map<std::string, Shape> t = {
      {"abs", Shape::Unary},
      {"floor", Shape::Unary},
      {"fract", Shape::Unary},
      {"sqrt", Shape::Unary},
      {"exp2", Shape::Unary},
      {"log2", Shape::Unary},
      {"sin", Shape::Unary},
      {"cos", Shape::Unary},
      {"saturate", Shape::Unary},
      {"normalize", Shape::Unary},
      {"pow", Shape::Binary},
      {"min", Shape::BinaryScalarB},
      {"max", Shape::BinaryScalarB},
      {"step", Shape::StepLike},
      {"mix", Shape::Mix},
      {"clamp", Shape::Clamp},
      {"smoothstep", Shape::Smoothstep},
      {"length", Shape::Reduce},
      {"dot", Shape::Dot},
      {"cross", Shape::Cross},
  };
  return t;
}

int arity(Shape s) {
  switch (s) {
    case Shape::Unary:
    case Shape::Reduce: return 1;
    case Shape::Mix:
    case Shape::Clamp:
    case Shape::Smoothstep: return 3;
    default: return 2;
  }
}

}  // namespace

std::vector<std::string> builtinNames() {
  std::vector<std::string> names;
  for (const auto& [name, shape] : table()) names.push_back(name);
  return names;
}

std::optional<BuiltinCall> resolveBuiltin(const std::string& name, const std::vector<Type>& args, std::string* error) {
  auto it = table().find(name);
  if (it == table().end()) {
    error->clear();
    return std::nullopt;
  }
  Shape shape = it->second;
  if (int(args.size()) != arity(shape)) {
    *error = "'" + name + "' takes " + std::to_string(arity(shape)) + " argument" + (arity(shape) == 1 ? "" : "s") +
             ", not " + std::to_string(args.size());
    return std::nullopt;
  }
  for (Type t : args) {
    if (!isFloatType(t)) {
      *error = "'" + name + "' takes float or vector arguments, not " + typeName(t);
      return std::nullopt;
    }
  }
  // The genType is the first argument that may not be a scalar stand-in.
  auto mismatch = [&](size_t i, Type gen) {
    *error = "argument " + std::to_string(i + 1) + " of '" + name + "' is " + typeName(args[i]) + " but " +
             typeName(gen) + " is required";
    return std::nullopt;
  };
  auto fits = [](Type arg, Type gen, bool scalarOk) { return arg == gen || (scalarOk && arg == Type::Float); };
  Type gen = args[0];
  switch (shape) {
    case Shape::Unary: return BuiltinCall{gen, name};
    case Shape::Reduce: return BuiltinCall{Type::Float, name};
    case Shape::Binary:
    case Shape::Dot:
      if (args[1] != gen) return mismatch(1, gen);
      return BuiltinCall{shape == Shape::Dot ? Type::Float : gen, name};
    case Shape::BinaryScalarB:
      if (!fits(args[1], gen, true)) return mismatch(1, gen);
      return BuiltinCall{gen, name};
    case Shape::StepLike:
      gen = args[1];
      if (!fits(args[0], gen, true)) return mismatch(0, gen);
      return BuiltinCall{gen, name};
    case Shape::Mix:
      if (args[1] != gen) return mismatch(1, gen);
      if (!fits(args[2], gen, true)) return mismatch(2, gen);
      return BuiltinCall{gen, name};
    case Shape::Clamp:
      if (!fits(args[1], gen, true)) return mismatch(1, gen);
      if (!fits(args[2], gen, true)) return mismatch(2, gen);
      return BuiltinCall{gen, name};
    case Shape::Smoothstep:
      gen = args[2];
      if (!fits(args[0], gen, true)) return mismatch(0, gen);
      if (!fits(args[1], gen, true)) return mismatch(1, gen);
      return BuiltinCall{gen, name};
    case Shape::Cross:
      if (args[0] != Type::Vec3) return mismatch(0, Type::Vec3);
      if (args[1] != Type::Vec3) return mismatch(1, Type::Vec3);
      return BuiltinCall{Type::Vec3, name};
  }
  return std::nullopt;
}

}  // namespace facet::ir
