// Name resolution and type checking: AST -> typed IR.
#pragma once

#include <optional>

#include "facet/ir/ast.h"
#include "facet/ir/module.h"

namespace facet::ir {

// Texture parameters per material: the sampler slots shader_abi.h reserves for a material.
inline constexpr size_t kMaxTextureParams = 8;

// Checks a parsed material. Reports every error it can find (several per run); returns the IR
// only when there were none.
std::optional<Material> check(const ast::Material& material, Diagnostics& diags);

// parse + check of one file, the usual entry point.
std::optional<Material> compileSource(const SourceFile& file, Diagnostics& diags);

// sRGB-encoded component -> linear (IEC 61966-2-1), used for `color` parameter values.
double srgbToLinear(double encoded);

}  // namespace facet::ir
