// Evaluation of IR values on constant operands, in double precision: the arithmetic behind
// constant folding and constant contexts (parameter defaults, range bounds).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "facet/ir/module.h"

namespace facet::ir {

using Components = std::array<double, 4>;

// The value of `v` given its operands' values (in v.args order), or nullopt when `v` reads a
// parameter or attribute, or when the result is not finite (that division stays on the GPU,
// where the author wrote it). Follows GLSL: scalars broadcast against vectors; int division
// truncates.
std::optional<Components> evaluate(const Value& v, const std::vector<Components>& args,
                                   const std::vector<Type>& argTypes);

// Evaluates `id` and everything it depends on; nullopt if any of it is not constant.
std::optional<Components> evaluateConstant(const Module& m, ValueId id);

}  // namespace facet::ir
