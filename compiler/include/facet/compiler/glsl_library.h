// The GLSL files shipped inside the compiler: chunks/ and templates/, embedded at build time.
#pragma once

#include <map>
#include <string>

namespace facet::compiler {

// File name (e.g. "brdf_ggx.glsl") -> text.
const std::map<std::string, std::string>& glslLibrary();

}  // namespace facet::compiler
