// fp16 emulation for testing (docs/fp16-emulation.md): lowers RelaxedPrecision
// semantics to explicit OpQuantizeToF16, so a GPU that computes mediump in fp32 (lavapipe)
// rounds every relaxed float result to binary16 as a mobile GPU would: round to nearest even per
// operation, overflow to +-inf, subnormals flushed to zero. Mesa-style name: the pass lowers
// RelaxedPrecision to quantization. Works on raw SPIR-V words (the Debian SPIRV-Tools package
// installs no opt IR headers), so it is a small word-level walker.
//
// What it does, for each function body:
//   - results: every instruction decorated RelaxedPrecision whose result type is a 32-bit float
//     scalar or vector is renamed in place: `%x = OpFAdd %t %a %b` becomes
//         %fresh = OpFAdd %t %a %b
//         %x     = OpQuantizeToF16 %t %fresh
//     so every use of %x, loop back-edge OpPhi operands included, sees the quantized value
//     without any use being rewritten. Decorations and names stay on %x.
//   - operands: a float scalar/vector operand of a relaxed arithmetic instruction that is not
//     itself a quantized relaxed result (a highp value, a constant, a texture sample, a phi) is
//     quantized just before that instruction and substituted in it only: a mobile GPU converts
//     the value to fp16 where it enters mediump maths.
//   - relaxed float OpFunctionParameters (glslang passes pointers, so rare) are quantized at the
//     start of the function's first block, after its OpVariables.
// What it skips (counted in QuantizeCounts): matrix results (their columns are quantized where
//   they are extracted and used), OpPhi results (nothing may sit between phis; their incoming
//   values are already quantized when relaxed), image instructions (OpSampledImage, OpImage*:
//   sample results are quantized at their first relaxed use; coordinates are left alone),
//   booleans, integers and pointers (never float results; integer conversions of relaxed floats
//   are not touched), and module-level instructions (spec constants).
//
// Run it on glslang's unoptimized output, before any SSA rewrite: there a highp value entering
// mediump is a relaxed OpLoad from a mediump variable, which gets quantized; after spirv-opt's
// memory-to-register passes those loads are gone and the value would stay fp32. Optimizing
// afterwards is fine: spirv-opt keeps OpQuantizeToF16 (tests/compiler/test_fp16.cpp checks it).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::compiler {

struct QuantizeCounts {
  uint32_t results = 0;          // relaxed float results renamed and quantized
  uint32_t operands = 0;         // float operands quantized in front of a relaxed instruction
  uint32_t skippedMatrices = 0;  // relaxed matrix results, left in fp32
  uint32_t skippedPhis = 0;      // relaxed float OpPhi results, left as they are
  uint32_t skippedImageOps = 0;  // relaxed OpImage*/OpSampledImage results, quantized at their uses
};

// Rewrites the module in place and updates the header's id bound. Returns false with *error on
// malformed SPIR-V (the module is then unchanged).
bool lowerRelaxedToQuantized(std::vector<uint32_t>* words, QuantizeCounts* counts, std::string* error);

}  // namespace facet::compiler
