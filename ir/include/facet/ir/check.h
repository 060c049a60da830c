// Name resolution and type checking: AST -> typed IR.
#pragma once

#include <optional>

#include "facet/ir/ast.h"
#include "facet/ir/module.h"

namespace facet::ir {

// Texture parameters per material: the sampler slots shader_abi.h reserves for a material.
inline constexpr size_t kMaxTextureParams = 8;
// Parameters per material. 256 vec4s fill 4 KiB of std140, a quarter of the 16 KiB uniform block
// every GLES 3.0 device supports (GL_MAX_UNIFORM_BLOCK_SIZE); the cap also keeps the checker's
// per-parameter work (duplicate and "did you mean" searches) linear on hostile input.
inline constexpr size_t kMaxParams = 256;

// Checks a parsed material. Reports every error it can find (several per run); returns the IR
// only when there were none.
std::optional<Material> check(const ast::Material& material, Diagnostics& diags);

// parse + check of one file, the usual entry point.
std::optional<Material> compileSource(const SourceFile& file, Diagnostics& diags);

// sRGB-encoded component -> linear (IEC 61966-2-1), used for `color` parameter values.
double srgbToLinear(double encoded);

}  // namespace facet::ir
