// SPIRV-Tools: validation (spirv-val), optimization (spirv-opt) and disassembly, for Vulkan 1.0.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::compiler {

bool validateSpirv(const std::vector<uint32_t>& words, std::string* log);

// spirv-opt's performance recipe (the same as `spirv-opt -O`). RelaxedPrecision decorations,
// which carry mediump into SPIR-V, survive it.
bool optimizeSpirv(std::vector<uint32_t>* words, std::string* log);

// For the Metal path only: rewrites RelaxedPrecision float arithmetic as true 16-bit floats
// (spirv-opt --convert-relaxed-to-half), since SPIRV-Cross's MSL output ignores RelaxedPrecision
// and would otherwise give Apple GPUs full-precision `float` where the GLES path gets mediump.
bool convertRelaxedToHalf(std::vector<uint32_t>* words, std::string* log);

std::string disassembleSpirv(const std::vector<uint32_t>& words);

}  // namespace facet::compiler
