#include "facet/compiler/spirv_cost.h"

#include <spirv/unified1/GLSL.std.450.h>
#include <spirv/unified1/spirv.h>

#include <map>
#include <set>

#include "spirv_walk.h"

namespace facet::compiler {
namespace {

bool isAlu(uint32_t op) {
  return (op >= SpvOpConvertFToU && op <= SpvOpQuantizeToF16) ||  // conversions
         (op >= SpvOpSNegate && op <= SpvOpDot) ||                // arithmetic
         (op >= SpvOpAny && op <= SpvOpFUnordGreaterThanEqual) || // logic, select, comparisons
         (op >= SpvOpShiftRightLogical && op <= SpvOpNot);        // bit operations
}

bool isDivision(uint32_t op) {
  return op == SpvOpFDiv || op == SpvOpSDiv || op == SpvOpUDiv || op == SpvOpFRem || op == SpvOpFMod ||
         op == SpvOpSRem || op == SpvOpSMod || op == SpvOpUMod;
}

bool isTextureSample(uint32_t op) {
  return (op >= SpvOpImageSampleImplicitLod && op <= SpvOpImageDrefGather);
}

// GLSL.std.450 instructions that run on the special-function unit (or contain such an op:
// normalize and length take an inverse square root or a square root).
bool isTranscendental(uint32_t ext) {
  switch (ext) {
    case GLSLstd450Sin: case GLSLstd450Cos: case GLSLstd450Tan: case GLSLstd450Asin: case GLSLstd450Acos:
    case GLSLstd450Atan: case GLSLstd450Sinh: case GLSLstd450Cosh: case GLSLstd450Tanh: case GLSLstd450Asinh:
    case GLSLstd450Acosh: case GLSLstd450Atanh: case GLSLstd450Atan2: case GLSLstd450Pow: case GLSLstd450Exp:
    case GLSLstd450Log: case GLSLstd450Exp2: case GLSLstd450Log2: case GLSLstd450Sqrt: case GLSLstd450InverseSqrt:
    case GLSLstd450Length: case GLSLstd450Distance: case GLSLstd450Normalize: case GLSLstd450Refract:
      return true;
    default:
      return false;
  }
}

}  // namespace

bool analyseSpirvCost(const std::vector<uint32_t>& words, StageCost* cost, std::string* error) {
  std::map<uint32_t, uint32_t> components;  // type id -> scalar components
  std::map<uint32_t, uint32_t> pointee;     // pointer type id -> pointee type id
  std::set<uint32_t> relaxed, builtins;
  std::vector<std::pair<uint32_t, uint32_t>> inputs;  // (variable id, pointer type id)
  uint32_t glslStd = 0;
  bool inFunction = false;
  *cost = {};

  bool walked = forEachSpirvInstruction(words, [&](const SpirvInstruction& ins) {
    const uint32_t op = ins.opcode;
    auto w = [&](uint32_t i) { return ins.operand(i); };
    switch (op) {
      case SpvOpExtInstImport:
        if (ins.literalString(2) == "GLSL.std.450") glslStd = w(1);
        break;
      case SpvOpTypeBool: case SpvOpTypeInt: case SpvOpTypeFloat: components[w(1)] = 1; break;
      case SpvOpTypeVector: components[w(1)] = components[w(2)] * w(3); break;
      case SpvOpTypeMatrix: components[w(1)] = components[w(2)] * w(3); break;
      case SpvOpTypePointer: pointee[w(1)] = w(3); break;
      case SpvOpDecorate:
        if (w(2) == SpvDecorationRelaxedPrecision) relaxed.insert(w(1));
        if (w(2) == SpvDecorationBuiltIn) builtins.insert(w(1));
        break;
      case SpvOpMemberDecorate:
        if (w(3) == SpvDecorationBuiltIn) builtins.insert(w(1));  // gl_PerVertex-style blocks
        break;
      case SpvOpVariable:
        if (!inFunction && w(3) == SpvStorageClassInput) inputs.emplace_back(w(2), w(1));
        break;
      case SpvOpFunction: inFunction = true; break;
      case SpvOpFunctionEnd: inFunction = false; break;
      default: break;
    }
    if (inFunction && ins.count >= 3) {
      uint32_t resultType = w(1), result = w(2);
      uint32_t n = components.count(resultType) ? components[resultType] : 1;
      bool counted = false;
      if (op == SpvOpExtInst && ins.count >= 5 && w(3) == glslStd) {
        if (isTranscendental(w(4))) {
          ++cost->transcendentalOps;
        } else {
          ++cost->aluOps;
          cost->scalarAluOps += n;
        }
        counted = true;
      } else if (isAlu(op)) {
        ++cost->aluOps;
        cost->scalarAluOps += n;
        counted = true;
      }
      if (isDivision(op)) ++cost->divisions;
      if (isTextureSample(op)) ++cost->textureSamples;
      if (counted && relaxed.count(result)) ++cost->relaxedOps;
    }
  }, error);
  if (!walked) return false;
  for (const auto& [variable, pointerType] : inputs) {
    if (builtins.count(variable)) continue;
    uint32_t type = pointee.count(pointerType) ? pointee[pointerType] : 0;
    if (builtins.count(type)) continue;
    cost->varyingComponents += components.count(type) ? components[type] : 0;
  }
  return true;
}

}  // namespace facet::compiler
