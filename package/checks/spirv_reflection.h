// A package's SPIR-V as the runtime's interface check sees it (program_interface.h), read with
// SPIRV-Cross's reflection through Debian's C API (libspirv-cross-c-shared): these checks link none
// of the compiler, which reads the same library to write the shaders.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/package/program_interface.h"

namespace facet::package {

// Reflects a module spirv-val has accepted (validateUntrustedSpirv) for the `stage` slot of a
// package. Its entry points come first: exactly one, of the slot's execution model, named "main"
// (what the Vulkan backend calls) — a stage-swapped module is valid SPIR-V on its own, and a driver
// handed it fails without saying why (lavapipe: VK_ERROR_UNKNOWN; under the validation layer, a
// crash). Then what the entry point statically uses: uniform blocks with their members, samplers,
// other resources; and every user-defined stage input and output. False with *error ("is a
// fragment shader ...", "SPIRV-Cross ...") otherwise.
bool reflectSpirv(const std::vector<uint32_t>& words, package::Stage stage, ReflectedStage* out, std::string* error);

}  // namespace facet::package
