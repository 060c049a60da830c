// Names a material may not give its parameters: they reach the generated GLSL as uniform-block
// members (`params.<name>`) and sampler uniforms, where the shader compiler would reject them.
#pragma once

#include <string>
#include <string_view>

namespace facet::ir {

// Why `name` cannot be used as an identifier in GLSL ES 3.00 / 3.10, or "" if it can:
//   - a keyword or a word reserved for future use (GLSL ES 3.00 §3.7 and 3.10 §3.8; the Vulkan
//     flavour is 3.10, so its extra keywords count too), e.g. `discard`, `sample`, `input`;
//   - a name starting with `gl_` (reserved for the language, §3.8);
//   - a name containing `__` (reserved for the implementation, §3.8; not an error in every
//     compiler, so a material using one would build here and fail on some driver).
std::string reservedNameReason(std::string_view name);

}  // namespace facet::ir
