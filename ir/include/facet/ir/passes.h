// IR passes. Each takes the material and leaves it with the same meaning, smaller.
//
// Every pass rebuilds the value graph through Module::add, which interns values: operations that
// became identical (after folding, say) merge into one, so common subexpressions are eliminated
// as a side effect of every pass rather than by a pass of their own.
#pragma once

#include "facet/ir/module.h"

namespace facet::ir {

// op(constant, ...) -> constant, for every operation and built-in; select(constant, a, b) -> a|b.
// Results that are not finite stay unfolded (see evaluate.h).
void opt_fold_constants(Material& material);

// Drops values no written output depends on, and marks parameters nothing reads as unused
// (Param::used = false): they get no uniform, so an unused feature costs zero instructions.
void opt_eliminate_dead_code(Material& material);

// The pipeline matc runs: fold, then dead-code elimination.
void optimize(Material& material);

}  // namespace facet::ir
