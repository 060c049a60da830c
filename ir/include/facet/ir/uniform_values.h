// Which values of a surface program are the same at every pixel of a draw: those computed from
// parameters (textures excepted) and constants alone. The compiler moves such shading inputs out
// of the fragment stage into the preshader (compiler/preshader.h), computed once on the CPU.
#pragma once

#include <optional>

#include "facet/ir/module.h"

namespace facet::ir {

// True when `id` and everything it depends on reads no vertex attribute and no texture.
bool isUniformOnly(const Material& material, ValueId id);

// True when `id` depends on at least one parameter: a uniform-only value that does not is a
// constant, which the shader compiler folds better than any preshader.
bool readsParameter(const Material& material, ValueId id);

// The value a surface output takes: what the program writes, or nullopt when it keeps its
// default (a constant: uniform too).
std::optional<ValueId> outputValue(const Material& material, std::string_view output);

}  // namespace facet::ir
