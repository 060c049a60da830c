// SPIR-V from a package is code the app did not compile: a driver handed malformed SPIR-V may
// crash (lavapipe segfaults on a truncated module whose package checksum is valid) or hang. The
// runtime validates every module with SPIRV-Tools before any backend sees it (docs/security.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::package {

// spirv-val for Vulkan 1.0, as the compiler validated it. False with *error (the validator's
// first message) otherwise.
bool validateUntrustedSpirv(const std::vector<uint32_t>& words, std::string* error);

}  // namespace facet::package
