// SPIRV-Cross (Debian's C API): SPIR-V -> Metal Shading Language for iOS.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::compiler {

// MSL 2.0 for the iOS platform. SPIRV-Cross names the entry point "main0".
bool spirvToMsl(const std::vector<uint32_t>& words, std::string* msl, std::string* error);

}  // namespace facet::compiler
