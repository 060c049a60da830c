// Shipping size of GLSL ES: the assembled text carries every chunk's header comment, the
// functions of other tiers and the preprocessor branches of other variants (33 KB per fragment
// variant before this pass). A driver compiles what remains exactly as it would the original:
// the pass only deletes (comments, whitespace, unreachable declarations) and never rewrites an
// expression, so constants keep their spelling and images stay identical.
#pragma once

#include <string>

namespace facet::compiler {

// Minifies preprocessed GLSL (no #if/#define left; directives such as #version stay): keeps one
// statement per line without indentation, spaces only where two tokens would otherwise merge,
// and drops every function, struct, `const` and plain global that no kept declaration
// references, starting from main() and the interface (in/out/uniform/precision/layout).
// Overloads of one name are kept or dropped together. Comments are removed too, so the input
// may still carry them.
std::string minifyPreprocessedGlsl(const std::string& preprocessed);

}  // namespace facet::compiler
