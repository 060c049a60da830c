// Parses material text into an AST (grammar: docs/material-language.md).
#pragma once

#include <optional>

#include "facet/ir/ast.h"
#include "facet/ir/diagnostics.h"

namespace facet::ir {

// Expression trees taller than this are reported, not built, so no later recursive pass (checker,
// destructor) can overflow the stack on hostile input. Split long expressions with `let`.
inline constexpr int kMaxExpressionDepth = 256;

// Returns the material, or nullopt when the text has syntax errors (all reported to diags;
// the parser recovers at statement and declaration boundaries to report several at once).
std::optional<ast::Material> parse(const SourceFile& file, Diagnostics& diags);

}  // namespace facet::ir
