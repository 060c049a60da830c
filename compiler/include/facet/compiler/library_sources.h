// Where the templates/ and chunks/ files embedded in the compiler came from, for build systems
// (matc compile --depfile). The compiler never reads them at run time: they are embedded
// (cmake/EmbedFiles.cmake); these paths only tell Ninja/Make what to watch while developing.
#pragma once

#include <string>

namespace facet::compiler {

// The source file of a glslLibrary() entry in the tree this compiler was built from, or "" when
// that file no longer exists (an installed compiler whose source tree is gone).
std::string librarySourcePath(const std::string& name);

}  // namespace facet::compiler
