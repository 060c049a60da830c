// Built-in functions of the material language: the GLSL ES 3.00 built-ins a surface program may
// call, plus `saturate`. Each entry checks argument types and gives the result type.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/ir/types.h"

namespace facet::ir {

struct BuiltinCall {
  Type result;
  std::string glsl;  // function to emit (saturate is emitted via clamp by the emitter)
};

// nullopt + *error set when the name is known but the arguments do not fit;
// nullopt + empty *error when the name is not a built-in.
std::optional<BuiltinCall> resolveBuiltin(const std::string& name, const std::vector<Type>& args, std::string* error);

std::vector<std::string> builtinNames();

}  // namespace facet::ir
