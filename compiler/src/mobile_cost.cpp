#include "facet/compiler/mobile_cost.h"

#include <spirv/unified1/GLSL.std.450.h>
#define SPV_ENABLE_UTILITY_CODE
#include <spirv/unified1/spirv.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <set>
#include <unordered_map>

#include "spirv_walk.h"

namespace facet::compiler {
namespace {

// One instruction of a function body, copied out of the module (operand(i) is word i).
struct BodyInstruction {
  uint32_t opcode = 0;
  std::vector<uint32_t> words;  // every word, the opcode word first
  uint32_t operand(size_t i) const { return i < words.size() ? words[i] : 0; }
};

// Whether an instruction has a result type and a result id (words 1 and 2).
bool hasResult(uint32_t op) {
  bool result = false, type = false;
  SpvHasResultAndType(SpvOp(op), &result, &type);
  return result && type;
}

// The words of a body instruction that may hold ids (literal operands are skipped where they
// are known: a literal mistaken for an id only blocks a fusion, never adds one).
std::pair<size_t, size_t> idOperands(const BodyInstruction& ins) {
  const size_t n = ins.words.size();
  auto range = [&](size_t first, size_t last) {
    return std::pair<size_t, size_t>{std::min(first, n), std::min(last, n)};
  };
  switch (ins.opcode) {
    case SpvOpExtInst: return range(5, n);
    case SpvOpVectorShuffle: return range(3, 5);
    case SpvOpCompositeExtract: return range(3, 4);
    case SpvOpCompositeInsert: return range(3, 5);
    default: return range(hasResult(ins.opcode) ? 3 : 1, n);
  }
}

bool isFmaPipe(uint32_t op) {
  switch (op) {
    case SpvOpFAdd:
    case SpvOpFSub:
    case SpvOpFMul:
    case SpvOpIAdd:
    case SpvOpISub:
    case SpvOpIMul:
    case SpvOpSNegate:
    case SpvOpSelect:
    case SpvOpLogicalAnd:
    case SpvOpLogicalOr:
    case SpvOpLogicalNot:
    case SpvOpLogicalEqual:
    case SpvOpLogicalNotEqual:
    case SpvOpAny:
    case SpvOpAll:
    case SpvOpIsNan:
    case SpvOpIsInf:
    case SpvOpShiftRightLogical:
    case SpvOpShiftRightArithmetic:
    case SpvOpShiftLeftLogical:
    case SpvOpBitwiseOr:
    case SpvOpBitwiseXor:
    case SpvOpBitwiseAnd:
    case SpvOpNot:
    case SpvOpBitFieldInsert:
    case SpvOpBitFieldSExtract:
    case SpvOpBitFieldUExtract:
    case SpvOpBitReverse:
    case SpvOpBitCount:
    case SpvOpVectorTimesScalar:
    case SpvOpMatrixTimesScalar: return true;
    default: return (op >= SpvOpIEqual && op <= SpvOpFUnordGreaterThanEqual);  // comparisons
  }
}

bool isConversion(uint32_t op) { return op >= SpvOpConvertFToU && op <= SpvOpFConvert && op != SpvOpQuantizeToF16; }

bool isTextureSample(uint32_t op) {
  return (op >= SpvOpImageSampleImplicitLod && op <= SpvOpImageDrefGather) ||
         (op >= SpvOpImageSparseSampleImplicitLod && op <= SpvOpImageSparseDrefGather);
}

bool isDerivative(uint32_t op) { return op >= SpvOpDPdx && op <= SpvOpFwidthCoarse; }

// InstructionCounts' classes: one SPIR-V instruction each, whatever the model makes of it.
bool isAluInstruction(uint32_t op) {
  return (op >= SpvOpConvertFToU && op <= SpvOpQuantizeToF16) ||   // conversions
         (op >= SpvOpSNegate && op <= SpvOpDot) ||                 // arithmetic
         (op >= SpvOpAny && op <= SpvOpFUnordGreaterThanEqual) ||  // logic, select, comparisons
         (op >= SpvOpShiftRightLogical && op <= SpvOpNot);         // bit operations
}

bool isDivisionInstruction(uint32_t op) {
  return op == SpvOpFDiv || op == SpvOpSDiv || op == SpvOpUDiv || op == SpvOpFRem || op == SpvOpFMod ||
         op == SpvOpSRem || op == SpvOpSMod || op == SpvOpUMod;
}

// GLSL.std.450 instructions that run on the special-function unit (or contain such an op:
// normalize and length take an inverse square root or a square root).
bool isTranscendentalInstruction(uint32_t ext) {
  switch (ext) {
    case GLSLstd450Sin:
    case GLSLstd450Cos:
    case GLSLstd450Tan:
    case GLSLstd450Asin:
    case GLSLstd450Acos:
    case GLSLstd450Atan:
    case GLSLstd450Sinh:
    case GLSLstd450Cosh:
    case GLSLstd450Tanh:
    case GLSLstd450Asinh:
    case GLSLstd450Acosh:
    case GLSLstd450Atanh:
    case GLSLstd450Atan2:
    case GLSLstd450Pow:
    case GLSLstd450Exp:
    case GLSLstd450Log:
    case GLSLstd450Exp2:
    case GLSLstd450Log2:
    case GLSLstd450Sqrt:
    case GLSLstd450InverseSqrt:
    case GLSLstd450Length:
    case GLSLstd450Distance:
    case GLSLstd450Normalize:
    case GLSLstd450Refract: return true;
    default: return false;
  }
}

// The module's types, constants and decorations: what the body instructions refer to.
struct ModuleFacts {
  std::unordered_map<uint32_t, uint32_t> components;                     // type id -> scalar components
  std::unordered_map<uint32_t, std::pair<uint32_t, uint32_t>> matrices;  // matrix type -> (columns, rows)
  std::unordered_map<uint32_t, uint32_t> typeOf;                         // result id -> type id
  std::unordered_map<uint32_t, double> constants;                        // id -> value (scalars, and splat composites)
  std::set<uint32_t> constantIds;                                        // every constant, splat or not
  std::unordered_map<uint32_t, uint32_t> pointee;                        // pointer type -> pointee type
  std::set<uint32_t> relaxed, builtins;
  std::vector<std::pair<uint32_t, uint32_t>> inputs;  // (variable, pointer type)
  uint32_t glslStd = 0;
  bool fragment = false;

  uint32_t componentsOf(uint32_t type) const {
    auto it = components.find(type);
    return it == components.end() ? 1 : std::max<uint32_t>(it->second, 1);
  }
  uint32_t componentsOfValue(uint32_t id) const {
    auto it = typeOf.find(id);
    return it == typeOf.end() ? 1 : componentsOf(it->second);
  }
  std::optional<double> constant(uint32_t id) const {
    auto it = constants.find(id);
    if (it == constants.end()) return std::nullopt;
    return it->second;
  }
};

float wordAsFloat(uint32_t w) {
  float f;
  std::memcpy(&f, &w, sizeof f);
  return f;
}

class Counter {
 public:
  Counter(const ModuleFacts& facts, OpClassCounts* counts) : facts_(facts), c_(*counts) {}

  // InstructionCounts of the body: the instructions as written, no fusion or expansion.
  void countInstructions(const std::vector<BodyInstruction>& body) {
    InstructionCounts& k = c_.instructions;
    for (const BodyInstruction& ins : body) {
      const uint32_t op = ins.opcode;
      if (ins.words.size() < 3) continue;
      const uint32_t n = facts_.componentsOf(ins.operand(1)), result = ins.operand(2);
      bool counted = false;
      if (op == SpvOpExtInst && ins.words.size() >= 5 && ins.operand(3) == facts_.glslStd) {
        if (isTranscendentalInstruction(ins.operand(4))) {
          ++k.transcendentalOps;
        } else {
          ++k.aluOps;
          k.scalarAluOps += n;
        }
        counted = true;
      } else if (isAluInstruction(op)) {
        ++k.aluOps;
        k.scalarAluOps += n;
        counted = true;
      }
      if (isDivisionInstruction(op)) ++k.divisions;
      if (isTextureSample(op)) ++k.textureSamples;
      if (counted && facts_.relaxed.count(result)) ++k.relaxedOps;
    }
  }

  void count(const std::vector<BodyInstruction>& body) {
    // How often each value is used: a multiply used once, by an add, fuses into an FMA.
    std::unordered_map<uint32_t, uint32_t> uses;
    std::unordered_map<uint32_t, const BodyInstruction*> definition;
    for (const BodyInstruction& ins : body) {
      if (hasResult(ins.opcode)) definition[ins.operand(2)] = &ins;
      auto [first, last] = idOperands(ins);
      for (size_t i = first; i < last; ++i) ++uses[ins.words[i]];
    }
    std::set<uint32_t> fusedMultiplies;
    for (const BodyInstruction& ins : body) {
      const uint32_t op = ins.opcode;
      if (!hasResult(op) || ins.words.size() < 3) continue;
      const uint32_t result = ins.operand(2);
      const double n = facts_.componentsOf(ins.operand(1));
      if (op == SpvOpFAdd || op == SpvOpFSub) {
        bool fused = false;
        for (size_t k : {size_t(3), size_t(4)}) {
          auto it = definition.find(ins.operand(k));
          if (it == definition.end() || fusedMultiplies.count(ins.operand(k))) continue;
          const uint32_t producer = it->second->opcode;
          if ((producer == SpvOpFMul || producer == SpvOpVectorTimesScalar) && uses[ins.operand(k)] == 1 &&
              facts_.componentsOf(it->second->operand(1)) == n) {
            fusedMultiplies.insert(ins.operand(k));
            fused = true;
            break;
          }
        }
        if (fused) {
          c_[OpClass::FusedAdd] += n;
          continue;
        }
      }
      if (op == SpvOpExtInst && ins.operand(3) == facts_.glslStd && facts_.glslStd != 0) {
        extInst(ins, n);
      } else if (op == SpvOpFNegate || op == SpvOpQuantizeToF16) {
        c_[OpClass::Modifier] += n;
      } else if (op == SpvOpFDiv) {
        if (facts_.constantIds.count(ins.operand(4)))
          fma(result, n);  // a constant divisor becomes a multiply by its reciprocal
        else
          c_[OpClass::Division] += n;
      } else if (op == SpvOpFRem || op == SpvOpFMod) {
        c_[OpClass::Division] += n;  // x − y·floor(x / y)
        c_[OpClass::Convert] += n;
        fma(result, n);
      } else if (op == SpvOpSDiv || op == SpvOpUDiv || op == SpvOpSRem || op == SpvOpSMod || op == SpvOpUMod) {
        c_[OpClass::IntegerDivision] += n;
      } else if (op == SpvOpDot) {
        fma(result, facts_.componentsOfValue(ins.operand(3)));
      } else if (op == SpvOpMatrixTimesVector || op == SpvOpVectorTimesMatrix || op == SpvOpMatrixTimesMatrix ||
                 op == SpvOpOuterProduct) {
        fma(result, matrixProduct(ins));
      } else if (isFmaPipe(op)) {
        fma(result, n);
      } else if (isConversion(op)) {
        c_[OpClass::Convert] += n;
      } else if (isTextureSample(op)) {
        c_[OpClass::TextureSample] += 1;
      } else if (isDerivative(op)) {
        c_[OpClass::Derivative] += n;
      }
      // Everything else costs no ALU slot: loads (uniforms live in the core's fast constant
      // storage), access chains, composite construction and extraction, shuffles, phis, copies.
    }
  }

 private:
  void fma(uint32_t result, double n) {
    c_[OpClass::Fma] += n;
    if (facts_.relaxed.count(result)) c_.fmaRelaxed += n;
  }

  double matrixProduct(const BodyInstruction& ins) const {
    auto shape = [&](uint32_t id) -> std::pair<uint32_t, uint32_t> {
      auto t = facts_.typeOf.find(id);
      if (t == facts_.typeOf.end()) return {1, 1};
      auto m = facts_.matrices.find(t->second);
      return m == facts_.matrices.end() ? std::pair<uint32_t, uint32_t>{1, facts_.componentsOf(t->second)} : m->second;
    };
    const uint32_t op = ins.opcode;
    if (op == SpvOpMatrixTimesVector) {
      auto [cols, rows] = shape(ins.operand(3));
      return double(cols) * rows;
    }
    if (op == SpvOpVectorTimesMatrix) {
      auto [cols, rows] = shape(ins.operand(4));
      return double(cols) * rows;
    }
    if (op == SpvOpMatrixTimesMatrix) {
      auto [colsA, rowsA] = shape(ins.operand(3));
      auto [colsB, rowsB] = shape(ins.operand(4));
      (void)rowsB;
      return double(rowsA) * colsA * colsB;
    }
    return facts_.componentsOf(ins.operand(1));  // outer product: one multiply per element
  }

  bool isConstantValue(uint32_t id, double value) const {
    auto v = facts_.constant(id);
    return v && *v == value;
  }

  void extInst(const BodyInstruction& ins, double n) {
    const uint32_t result = ins.operand(2);
    const uint32_t x = ins.operand(5);
    const double argN = facts_.componentsOfValue(x);
    switch (ins.operand(4)) {
      case GLSLstd450FAbs:
      case GLSLstd450SAbs: c_[OpClass::Modifier] += n; break;
      case GLSLstd450Round:
      case GLSLstd450RoundEven:
      case GLSLstd450Trunc:
      case GLSLstd450Floor:
      case GLSLstd450Ceil:
      case GLSLstd450Ldexp:
      case GLSLstd450Frexp:
      case GLSLstd450FrexpStruct:
      case GLSLstd450FindILsb:
      case GLSLstd450FindSMsb:
      case GLSLstd450FindUMsb: c_[OpClass::Convert] += n; break;
      case GLSLstd450Fract:
      case GLSLstd450Modf:
      case GLSLstd450ModfStruct:
        c_[OpClass::Convert] += n;
        fma(result, n);
        break;
      case GLSLstd450PackSnorm4x8:
      case GLSLstd450PackUnorm4x8:
      case GLSLstd450PackSnorm2x16:
      case GLSLstd450PackUnorm2x16:
      case GLSLstd450PackHalf2x16:
      case GLSLstd450PackDouble2x32:
      case GLSLstd450UnpackSnorm2x16:
      case GLSLstd450UnpackUnorm2x16:
      case GLSLstd450UnpackHalf2x16:
      case GLSLstd450UnpackSnorm4x8:
      case GLSLstd450UnpackUnorm4x8:
      case GLSLstd450UnpackDouble2x32: c_[OpClass::Convert] += std::max(n, argN); break;
      case GLSLstd450FSign:
      case GLSLstd450SSign:
      case GLSLstd450FMix:
      case GLSLstd450IMix:
      case GLSLstd450UClamp:
      case GLSLstd450SClamp: fma(result, 2 * n); break;
      case GLSLstd450FClamp:
      case GLSLstd450NClamp:
        // clamp(x, 0, 1) is the saturate output modifier of the op that produced x.
        if (isConstantValue(ins.operand(6), 0.0) && isConstantValue(ins.operand(7), 1.0))
          c_[OpClass::Modifier] += n;
        else
          fma(result, 2 * n);
        break;
      case GLSLstd450SmoothStep:
        // t = saturate((x − e0) / (e1 − e0)); t·t·(3 − 2t). Constant edges: the division is a multiply.
        fma(result, 5 * n);
        if (facts_.constantIds.count(ins.operand(5)) && facts_.constantIds.count(ins.operand(6)))
          fma(result, n);
        else
          c_[OpClass::Division] += n;
        break;
      case GLSLstd450Exp2:
      case GLSLstd450Log2:
      case GLSLstd450InverseSqrt: c_[OpClass::Sfu] += n; break;
      case GLSLstd450Exp:
      case GLSLstd450Log: c_[OpClass::ExpLog] += n; break;
      case GLSLstd450Sqrt: c_[OpClass::Sqrt] += n; break;
      case GLSLstd450Pow: c_[OpClass::Pow] += n; break;
      case GLSLstd450Sin:
      case GLSLstd450Cos: c_[OpClass::SinCos] += n; break;
      case GLSLstd450Tan: c_[OpClass::Tan] += n; break;
      case GLSLstd450Asin:
      case GLSLstd450Acos:
      case GLSLstd450Atan: c_[OpClass::InverseTrig] += n; break;
      case GLSLstd450Atan2: c_[OpClass::Atan2] += n; break;
      case GLSLstd450Sinh:
      case GLSLstd450Cosh:
      case GLSLstd450Tanh: c_[OpClass::Hyperbolic] += n; break;
      case GLSLstd450Asinh:
      case GLSLstd450Acosh:
      case GLSLstd450Atanh: c_[OpClass::InverseHyperbolic] += n; break;
      case GLSLstd450Length:
        // dot(x, x) and sqrt; of a scalar, abs.
        if (argN <= 1) {
          c_[OpClass::Modifier] += 1;
        } else {
          fma(result, argN);
          c_[OpClass::Sqrt] += 1;
        }
        break;
      case GLSLstd450Distance:
        fma(result, 2 * argN);  // difference, dot
        c_[OpClass::Sqrt] += 1;
        break;
      case GLSLstd450Normalize:
        if (argN <= 1) {
          fma(result, 2);  // sign(x)
        } else {
          fma(result, 2 * argN);  // dot, then the scale
          c_[OpClass::Sfu] += 1;  // inversesqrt
        }
        break;
      case GLSLstd450Cross:
        fma(result, 6);  // three multiplies, three FMAs
        break;
      case GLSLstd450Reflect:
        fma(result, 2 * argN + 1);  // I − 2·dot(N, I)·N
        break;
      case GLSLstd450FaceForward:
        fma(result, 2 * argN);  // dot, select
        break;
      case GLSLstd450Refract:
        fma(result, 3 * argN + 4);
        c_[OpClass::Sqrt] += 1;
        break;
      case GLSLstd450Determinant: fma(result, argN >= 16 ? 40 : argN >= 9 ? 12 : 3); break;
      case GLSLstd450MatrixInverse:
        fma(result, argN >= 16 ? 100 : argN >= 9 ? 30 : 6);
        c_[OpClass::Division] += 1;
        break;
      case GLSLstd450InterpolateAtCentroid:
      case GLSLstd450InterpolateAtSample:
      case GLSLstd450InterpolateAtOffset: break;  // a varying read, counted with the inputs
      default:                                    // min, max, fma, step and the rest: one FMA-pipe op per component
        fma(result, n);
        break;
    }
  }

  const ModuleFacts& facts_;
  OpClassCounts& c_;
};

}  // namespace

const char* toString(OpClass c) {
  static const char* const names[] = {
      "fma",      "convert",          "modifier",   "fused_add",     "sfu",   "exp_log",    "sqrt",
      "pow",      "sin_cos",          "tan",        "inverse_trig",  "atan2", "hyperbolic", "inverse_hyperbolic",
      "division", "integer_division", "derivative", "texture_sample"};
  static_assert(sizeof(names) / sizeof(names[0]) == kOpClassCount);
  return size_t(c) < kOpClassCount ? names[size_t(c)] : "?";
}

const char* MobileStageCost::bound() const {
  if (textureCycles > arithmeticCycles && textureCycles >= varyingCycles) return "texture";
  if (varyingCycles > arithmeticCycles && varyingCycles > textureCycles) return "varying";
  return "arithmetic";
}

double MobileStageCost::transcendentals() const {
  double n = 0;
  for (OpClass k : {OpClass::Sfu, OpClass::ExpLog, OpClass::Sqrt, OpClass::Pow, OpClass::SinCos, OpClass::Tan,
                    OpClass::InverseTrig, OpClass::Atan2, OpClass::Hyperbolic, OpClass::InverseHyperbolic})
    n += counts[k];
  return n;
}

double MobileStageCost::divisions() const { return counts[OpClass::Division] + counts[OpClass::IntegerDivision]; }

bool countOpClasses(const std::vector<uint32_t>& words, OpClassCounts* counts, std::string* error) {
  ModuleFacts facts;
  std::vector<BodyInstruction> body;
  bool inFunction = false;
  *counts = {};
  bool walked = forEachSpirvInstruction(
      words,
      [&](const SpirvInstruction& ins) {
        const uint32_t op = ins.opcode;
        auto w = [&](uint32_t i) { return ins.operand(i); };
        switch (op) {
          case SpvOpExtInstImport:
            if (ins.literalString(2) == "GLSL.std.450") facts.glslStd = w(1);
            break;
          case SpvOpEntryPoint:
            if (w(1) == SpvExecutionModelFragment) facts.fragment = true;
            break;
          case SpvOpTypeBool:
          case SpvOpTypeInt:
          case SpvOpTypeFloat: facts.components[w(1)] = 1; break;
          case SpvOpTypeVector: facts.components[w(1)] = facts.componentsOf(w(2)) * std::min<uint32_t>(w(3), 16); break;
          case SpvOpTypeMatrix: {
            uint32_t rows = facts.componentsOf(w(2)), cols = std::min<uint32_t>(w(3), 16);
            facts.components[w(1)] = rows * cols;
            facts.matrices[w(1)] = {cols, rows};
            break;
          }
          case SpvOpTypePointer: facts.pointee[w(1)] = w(3); break;
          case SpvOpDecorate:
            if (w(2) == SpvDecorationRelaxedPrecision) facts.relaxed.insert(w(1));
            if (w(2) == SpvDecorationBuiltIn) facts.builtins.insert(w(1));
            break;
          case SpvOpMemberDecorate:
            if (w(3) == SpvDecorationBuiltIn) facts.builtins.insert(w(1));  // gl_PerVertex-style blocks
            break;
          case SpvOpConstant:
            facts.constantIds.insert(w(2));
            // A 32-bit value read as a float: only float operands are ever compared with 0.0 and 1.0.
            if (ins.count == 4) facts.constants[w(2)] = wordAsFloat(w(3));
            break;
          case SpvOpConstantNull:
            facts.constantIds.insert(w(2));
            facts.constants[w(2)] = 0.0;
            break;
          case SpvOpConstantTrue:
          case SpvOpConstantFalse:
          case SpvOpSpecConstant:
          case SpvOpSpecConstantTrue:
          case SpvOpSpecConstantFalse: facts.constantIds.insert(w(2)); break;
          case SpvOpConstantComposite: {
            facts.constantIds.insert(w(2));
            std::optional<double> splat;
            bool same = ins.count > 3;
            for (uint32_t i = 3; i < ins.count && same; ++i) {
              auto v = facts.constant(w(i));
              if (!v || (splat && *splat != *v)) same = false;
              splat = v;
            }
            if (same && splat) facts.constants[w(2)] = *splat;
            break;
          }
          case SpvOpVariable:
            if (!inFunction && w(3) == SpvStorageClassInput) facts.inputs.emplace_back(w(2), w(1));
            break;
          case SpvOpFunction: inFunction = true; break;
          case SpvOpFunctionEnd: inFunction = false; break;
          default: break;
        }
        if (ins.count >= 3 && hasResult(op)) facts.typeOf[w(2)] = w(1);
        if (inFunction && op != SpvOpFunction)
          body.push_back({op, std::vector<uint32_t>(ins.words, ins.words + ins.count)});
      },
      error);
  if (!walked) return false;
  Counter counter(facts, counts);
  counter.count(body);
  counter.countInstructions(body);
  counts->fragment = facts.fragment;
  for (const auto& [variable, pointerType] : facts.inputs) {
    if (facts.builtins.count(variable)) continue;
    auto pointee = facts.pointee.find(pointerType);
    const uint32_t type = pointee == facts.pointee.end() ? 0 : pointee->second;
    if (facts.builtins.count(type)) continue;
    auto n = facts.components.find(type);  // an input block or array of them: no scalar components counted
    counts->instructions.varyingComponents += n == facts.components.end() ? 0 : n->second;
  }
  if (facts.fragment) {
    for (const auto& [variable, pointerType] : facts.inputs) {
      if (facts.builtins.count(variable)) continue;
      auto it = facts.pointee.find(pointerType);
      if (it == facts.pointee.end() || facts.builtins.count(it->second)) continue;
      uint32_t n = facts.componentsOf(it->second);
      (facts.relaxed.count(variable) ? counts->varyingComponentsRelaxed : counts->varyingComponents) += n;
    }
  }
  return true;
}

MobileStageCost weighMobileCost(const OpClassCounts& counts, const MobileCostWeights& w) {
  MobileStageCost cost;
  cost.counts = counts;
  const double relaxedFma = counts.fmaRelaxed;
  const double highpFma = counts[OpClass::Fma] - relaxedFma;
  cost.fmaSlots = highpFma + w.relaxedFmaWeight * relaxedFma;
  cost.cvtSlots = counts[OpClass::Convert];
  const std::pair<OpClass, const Expansion*> expansions[] = {
      {OpClass::Sfu, &w.sfu},
      {OpClass::ExpLog, &w.expLog},
      {OpClass::Sqrt, &w.sqrt},
      {OpClass::Pow, &w.pow},
      {OpClass::SinCos, &w.sinCos},
      {OpClass::Tan, &w.tan},
      {OpClass::InverseTrig, &w.inverseTrig},
      {OpClass::Atan2, &w.atan2},
      {OpClass::Hyperbolic, &w.hyperbolic},
      {OpClass::InverseHyperbolic, &w.inverseHyperbolic},
      {OpClass::Division, &w.division},
      {OpClass::IntegerDivision, &w.integerDivision},
      {OpClass::Derivative, &w.derivative},
  };
  for (const auto& [k, e] : expansions) {
    cost.fmaSlots += counts[k] * e->fma;
    cost.sfuOps += counts[k] * e->sfu;
  }
  cost.textureSamples = counts[OpClass::TextureSample];
  cost.varyingChannels = counts.varyingComponentsRelaxed + 2.0 * counts.varyingComponents;
  auto per = [](double n, double rate) { return rate > 0 ? n / rate : 0.0; };
  const double sfuSlots = w.sfuFmaSlots * cost.sfuOps;
  cost.arithmeticCycles = w.pipes == ArithmeticPipes::Concurrent
                              ? per(std::max({cost.fmaSlots, cost.cvtSlots, sfuSlots}), w.fmaPerCycle)
                              : per(cost.fmaSlots + cost.cvtSlots + sfuSlots, w.fmaPerCycle);
  cost.textureCycles = per(cost.textureSamples, w.texturesPerCycle);
  cost.varyingCycles = per(cost.varyingChannels, w.varyingChannelsPerCycle);
  cost.cycles = std::max({cost.arithmeticCycles, cost.textureCycles, cost.varyingCycles});
  return cost;
}

const GpuCalibration* findGpuCalibration(const std::string& gpu) {
  for (const GpuCalibration& c : gpuCalibrations())
    if (gpu == c.gpu) return &c;
  return nullptr;
}

double calibratedEstimate(const OpClassCounts& f, const GpuCalibration& c) {
  // The features of tools/mesa_stats/fit.py (FEATURES), in CalibratedClass order.
  const std::array<double, kCalibratedClassCount> features = {f.fmaRelaxed,
                                                              f[OpClass::Fma] - f.fmaRelaxed,
                                                              f[OpClass::Convert],
                                                              f[OpClass::Sfu],
                                                              f[OpClass::ExpLog],
                                                              f[OpClass::Sqrt],
                                                              f[OpClass::Pow],
                                                              f[OpClass::SinCos],
                                                              f[OpClass::Tan],
                                                              f[OpClass::InverseTrig],
                                                              f[OpClass::Atan2],
                                                              f[OpClass::Division],
                                                              f[OpClass::TextureSample]};
  double sum = 0;
  for (size_t k = 0; k < kCalibratedClassCount; ++k) sum += c.weights[k] * features[k];
  return sum;
}

bool estimateMobileCost(const std::vector<uint32_t>& words, MobileStageCost* cost, std::string* error,
                        const MobileCostWeights& weights) {
  OpClassCounts counts;
  if (!countOpClasses(words, &counts, error)) return false;
  *cost = weighMobileCost(counts, weights);
  return true;
}

}  // namespace facet::compiler
