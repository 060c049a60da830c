#include "facet/compiler/lower_relaxed_to_quantized.h"

#define SPV_ENABLE_UTILITY_CODE
#include <spirv/unified1/spirv.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <set>

#include "spirv_walk.h"

namespace facet::compiler {
namespace {

enum class FloatShape { None, Scalar, Vector, Matrix };

struct Instruction {
  size_t offset;  // index of the first word in the module
  uint32_t count;
  uint32_t op;
};

bool isImageOp(uint32_t op) {
  return (op >= SpvOpSampledImage && op <= SpvOpImageQuerySamples) ||
         (op >= SpvOpImageSparseSampleImplicitLod && op <= SpvOpImageSparseRead);
}

// Word indices (within the instruction) of the operands that are ids of values the instruction
// computes with, for the relaxed arithmetic whose float operands get quantized. Other opcodes
// (loads, calls, copies, conversions from integers) have their result quantized only.
std::vector<uint32_t> valueOperands(const uint32_t* w, uint32_t count, uint32_t glslStd) {
  std::vector<uint32_t> positions;
  auto range = [&](uint32_t first, uint32_t end) {
    for (uint32_t i = first; i < end && i < count; ++i) positions.push_back(i);
  };
  switch (w[0] & 0xffff) {
    case SpvOpFNegate:
    case SpvOpFAdd:
    case SpvOpFSub:
    case SpvOpFMul:
    case SpvOpFDiv:
    case SpvOpFRem:
    case SpvOpFMod:
    case SpvOpVectorTimesScalar:
    case SpvOpVectorTimesMatrix:
    case SpvOpMatrixTimesVector:
    case SpvOpDot:
    case SpvOpCompositeConstruct:
    case SpvOpSelect:
    case SpvOpFConvert:
    case SpvOpDPdx:
    case SpvOpDPdy:
    case SpvOpFwidth:
    case SpvOpDPdxFine:
    case SpvOpDPdyFine:
    case SpvOpFwidthFine:
    case SpvOpDPdxCoarse:
    case SpvOpDPdyCoarse:
    case SpvOpFwidthCoarse:
    case SpvOpFOrdEqual:
    case SpvOpFUnordEqual:
    case SpvOpFOrdNotEqual:
    case SpvOpFUnordNotEqual:
    case SpvOpFOrdLessThan:
    case SpvOpFUnordLessThan:
    case SpvOpFOrdGreaterThan:
    case SpvOpFUnordGreaterThan:
    case SpvOpFOrdLessThanEqual:
    case SpvOpFUnordLessThanEqual:
    case SpvOpFOrdGreaterThanEqual:
    case SpvOpFUnordGreaterThanEqual: range(3, count); break;
    case SpvOpExtInst:  // set id, instruction number (a literal), then operand ids
      if (count > 4 && w[3] == glslStd) range(5, count);
      break;
    case SpvOpVectorShuffle: range(3, 5); break;     // two vectors, then literal components
    case SpvOpCompositeExtract: range(3, 4); break;  // composite, then literal indices
    case SpvOpCompositeInsert: range(3, 5); break;   // object, composite, then literal indices
    default: break;
  }
  return positions;
}

}  // namespace

bool lowerRelaxedToQuantized(std::vector<uint32_t>* words, QuantizeCounts* counts, std::string* error) {
  const std::vector<uint32_t>& in = *words;
  *counts = {};

  // Pass 1: instruction boundaries, float types, value types, RelaxedPrecision decorations.
  std::vector<Instruction> instructions;
  std::map<uint32_t, FloatShape> shapes;  // type id -> shape, for 32-bit float types only
  std::map<uint32_t, uint32_t> typeOf;    // value id -> its type id
  std::map<uint32_t, uint32_t> opOf;      // value id -> the opcode defining it (in functions)
  std::set<uint32_t> relaxed;
  uint32_t glslStd = 0;
  bool inFunction = false;
  bool walked = forEachSpirvInstruction(
      in,
      [&](const SpirvInstruction& ins) {
        const uint32_t op = ins.opcode;
        auto w = [&](uint32_t i) { return ins.operand(i); };
        instructions.push_back({ins.offset, ins.count, op});
        switch (op) {
          case SpvOpExtInstImport:
            if (ins.literalString(2) == "GLSL.std.450") glslStd = w(1);
            break;
          case SpvOpTypeFloat:
            if (w(2) == 32) shapes[w(1)] = FloatShape::Scalar;
            break;
          case SpvOpTypeVector:
            if (shapes.count(w(2)) && shapes[w(2)] == FloatShape::Scalar) shapes[w(1)] = FloatShape::Vector;
            break;
          case SpvOpTypeMatrix:
            if (shapes.count(w(2)) && shapes[w(2)] == FloatShape::Vector) shapes[w(1)] = FloatShape::Matrix;
            break;
          case SpvOpDecorate:
            if (w(2) == SpvDecorationRelaxedPrecision) relaxed.insert(w(1));
            break;
          case SpvOpFunction: inFunction = true; break;
          case SpvOpFunctionEnd: inFunction = false; break;
          default: break;
        }
        bool hasResult = false, hasType = false;
        SpvHasResultAndType(SpvOp(op), &hasResult, &hasType);
        // OpFunction's "result type" is its return type (glslang decorates mediump functions): the
        // function id is not a value, so it is never quantized.
        if (hasResult && hasType && ins.count >= 3 && op != SpvOpFunction) {
          typeOf[w(2)] = w(1);
          if (inFunction) opOf[w(2)] = op;
        }
      },
      error);
  if (!walked) return false;
  auto shapeOf = [&](uint32_t type) {
    auto it = shapes.find(type);
    return it == shapes.end() ? FloatShape::None : it->second;
  };
  auto isFloatValueType = [&](uint32_t type) {
    FloatShape s = shapeOf(type);
    return s == FloatShape::Scalar || s == FloatShape::Vector;
  };
  // The relaxed float results this pass quantizes: after it, these ids name fp16 values.
  std::set<uint32_t> quantized;
  for (uint32_t id : relaxed) {
    auto op = opOf.find(id);
    if (op == opOf.end() || !isFloatValueType(typeOf[id])) continue;
    if (op->second == SpvOpPhi || isImageOp(op->second) || op->second == SpvOpUndef) continue;
    quantized.insert(id);
  }

  // Pass 2: rewrite.
  uint32_t bound = in[3];
  std::vector<uint32_t> out(in.begin(), in.begin() + 5);
  out.reserve(in.size() * 2);
  auto emitQuantize = [&](uint32_t type, uint32_t result, uint32_t value) {
    out.insert(out.end(), {(4u << 16) | SpvOpQuantizeToF16, type, result, value});
  };
  struct PendingParam {
    uint32_t type, original, fresh;
  };
  std::vector<PendingParam> params;
  bool firstBlockOpen = false;  // in the first block of a function, before its first non-variable
  bool seenLabel = false;
  inFunction = false;
  for (const Instruction& ins : instructions) {
    std::vector<uint32_t> w(in.begin() + long(ins.offset), in.begin() + long(ins.offset + ins.count));
    const uint32_t op = ins.op;
    if (op == SpvOpFunction) {
      inFunction = true;
      seenLabel = false;
      params.clear();
    } else if (op == SpvOpFunctionEnd) {
      inFunction = false;
    }
    if (!inFunction) {
      out.insert(out.end(), w.begin(), w.end());
      continue;
    }
    if (op == SpvOpFunctionParameter && ins.count >= 3 && quantized.count(w[2])) {
      params.push_back({w[1], w[2], bound});
      w[2] = bound++;
      ++counts->results;
      out.insert(out.end(), w.begin(), w.end());
      continue;
    }
    if (op == SpvOpLabel) {
      firstBlockOpen = !seenLabel;
      seenLabel = true;
      out.insert(out.end(), w.begin(), w.end());
      continue;
    }
    if (firstBlockOpen && op != SpvOpVariable && op != SpvOpLine && op != SpvOpNoLine) {
      for (const PendingParam& p : params) emitQuantize(p.type, p.original, p.fresh);
      params.clear();
      firstBlockOpen = false;
    }

    bool hasResult = false, hasType = false;
    SpvHasResultAndType(SpvOp(op), &hasResult, &hasType);
    const bool isRelaxed = hasResult && hasType && ins.count >= 3 && op != SpvOpFunction && relaxed.count(w[2]);
    if (!isRelaxed) {
      out.insert(out.end(), w.begin(), w.end());
      continue;
    }
    const FloatShape shape = shapeOf(w[1]);
    if (shape == FloatShape::Matrix) ++counts->skippedMatrices;
    if (isImageOp(op) && shape != FloatShape::None) ++counts->skippedImageOps;
    if (op == SpvOpPhi && shape != FloatShape::None) ++counts->skippedPhis;

    // Float operands that enter relaxed arithmetic unquantized: quantize them for this
    // instruction only (the same operand twice, e.g. x * x, shares one quantize).
    if (!isImageOp(op)) {
      std::map<uint32_t, uint32_t> substitute;
      for (uint32_t pos : valueOperands(w.data(), ins.count, glslStd)) {
        uint32_t id = w[pos];
        auto type = typeOf.find(id);
        if (type == typeOf.end() || !isFloatValueType(type->second) || quantized.count(id)) continue;
        auto [it, fresh] = substitute.emplace(id, bound);
        if (fresh) {
          emitQuantize(type->second, bound++, id);
          ++counts->operands;
        }
        w[pos] = it->second;
      }
    }
    if (!quantized.count(w[2])) {
      out.insert(out.end(), w.begin(), w.end());
      continue;
    }
    // Rename in place: the instruction defines a fresh id, the quantize takes the original.
    const uint32_t original = w[2], fresh = bound++;
    w[2] = fresh;
    out.insert(out.end(), w.begin(), w.end());
    emitQuantize(w[1], original, fresh);
    ++counts->results;
  }
  if (!params.empty()) {
    *error = "function parameters without a body to quantize them in";
    return false;
  }
  out[3] = bound;
  *words = std::move(out);
  return true;
}

}  // namespace facet::compiler
