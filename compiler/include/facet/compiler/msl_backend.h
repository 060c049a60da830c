// SPIRV-Cross (Debian's C API): SPIR-V -> Metal Shading Language for iOS.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "facet/package/package.h"

namespace facet::compiler {

// MSL 2.0 for the iOS platform. SPIRV-Cross names the entry point "main0". Each resource in
// `slots` (by its Vulkan set and binding) is pinned to its Metal index; others are numbered by
// SPIRV-Cross in order of use (the post pass passes none).
bool spirvToMsl(const std::vector<uint32_t>& words, std::span<const package::MslBinding> slots, std::string* msl,
                std::string* error);

}  // namespace facet::compiler
