// After spirv-opt's --convert-relaxed-to-half: the float operands of image instructions
// (coordinates, lod, bias, gradients, min lod) that the conversion left as 16-bit floats are
// converted back to 32-bit just before the instruction. Mesa-style name: the pass lowers half
// image operands to fp32.
//
// Why: the conversion rewrites a relaxed coordinate's arithmetic to float16 and passes the half
// vector to the sample as it is (legal SPIR-V), and Mesa 22.3's lavapipe aborts compiling it
// (LLVM's x86 backend: "Cannot emit physreg copy instruction"; reproduced with one
// `textureLod(t, mediumpCoordinate, 0.0)`, while every half arithmetic op compiles).
// Texture units take 32-bit coordinates, so the conversion is exact: the values do not change.
// Used by the true-half SPIR-V build (BuildOptions::fp16TrueHalf, docs/fp16-emulation.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::compiler {

// Rewrites the module in place (id bound updated; a 32-bit float vector type is added where the
// module has none of the needed size). False with *error on malformed SPIR-V (the module is then
// unchanged).
bool lowerHalfImageOperands(std::vector<uint32_t>* words, std::string* error);

}  // namespace facet::compiler
