// Estimated cycles of a shader stage on a Valhall-class mobile GPU (Mali-G57 and its kin), read
// from the optimised SPIR-V: the one cost model of `matc info`, `matc eval` and `matc lint`
// (docs/eval.md, "The mobile cost model").
//
// Two steps, so that the weights can be studied apart from the counting:
//   countOpClasses   SPIR-V -> how many operations of each class, per scalar component
//                    (a vec3 multiply is 3), with the expansions that do not depend on a weight
//                    (normalize = dot + inversesqrt + multiply) already applied;
//   weighMobileCost  counts × MobileCostWeights -> FMA slots, SFU ops and cycles per pipe.
// Static counts, not timings: branches are counted once, loops once per body, uniform-only work
// is counted where the shader does it (a mobile driver has no preshader).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace facet::compiler {

// Operation classes. Each is counted per scalar component of its result (or operands, for a
// dot product) and turned into FMA slots and SFU ops by MobileCostWeights.
enum class OpClass {
  Fma,                // add, mul, fma, min/max, compare, select, logic, integer and bit ops (1 FMA slot)
  Convert,            // type conversions, floor/ceil/round/trunc (the CVT pipe; 1 slot)
  Modifier,           // negate, abs, saturate (clamp to [0, 1]), fp16 rounding: free source/output modifiers
  FusedAdd,           // an add folded into the multiply that feeds it (an FMA): free
  Sfu,                // one special-function op: exp2, log2, inversesqrt (also inside normalize)
  ExpLog,             // exp, log: exp2/log2 and a multiply by log2(e) or ln(2)
  Sqrt,               // sqrt (also inside length and distance)
  Pow,                // pow: exp2(y · log2(x))
  SinCos,             // sin, cos: range reduction and the SFU op
  Tan,                // tan: sin, cos and a division
  InverseTrig,        // asin, acos, atan: polynomial expansions
  Atan2,              // atan(y, x): atan's expansion and the quadrant fix-up
  Hyperbolic,         // sinh, cosh, tanh: built from exp
  InverseHyperbolic,  // asinh, acosh, atanh: built from log and sqrt
  Division,           // float division by a value (rcp + mul); by a constant it is counted as Fma
  IntegerDivision,    // integer division and remainder
  Derivative,         // dFdx, dFdy, fwidth: lane exchange
  TextureSample,      // sample, fetch, gather (one per instruction, not per component)
  Count,
};
inline constexpr size_t kOpClassCount = size_t(OpClass::Count);
const char* toString(OpClass c);

// The stage's SPIR-V instructions as they are, before the model classes or weighs them
// (docs/eval.md, "The mobile cost model"): the op counts `matc info` prints and `matc lint`'s
// budgets and baselines read. One per instruction (a vec3 multiply is 1 ALU op, 3 scalar ones);
// counted by the same walk as the op classes.
struct InstructionCounts {
  uint32_t aluOps = 0;             // arithmetic, logic, comparison, conversion instructions
  uint32_t scalarAluOps = 0;       // the same, weighted by result components (scalar-ALU cost)
  uint32_t transcendentalOps = 0;  // exp/log/pow/sin/cos/sqrt/inversesqrt (incl. inside normalize, length)
  uint32_t divisions = 0;          // float and integer divisions and remainders
  uint32_t textureSamples = 0;     // sample, fetch and gather instructions
  uint32_t varyingComponents = 0;  // scalar components of the stage's non-built-in inputs (any stage)
  uint32_t relaxedOps = 0;         // ALU + transcendental results decorated RelaxedPrecision (mediump)

  double relaxedPercent() const {
    uint32_t all = aluOps + transcendentalOps;
    return all == 0 ? 0.0 : 100.0 * relaxedOps / all;
  }
};

struct OpClassCounts {
  std::array<double, kOpClassCount> ops{};  // indexed by OpClass
  double fmaRelaxed = 0;                    // the part of ops[Fma] whose result is RelaxedPrecision (mediump)
  uint32_t varyingComponents = 0;           // fragment stage: scalar components of highp inputs
  uint32_t varyingComponentsRelaxed = 0;    // ... and of mediump (RelaxedPrecision) inputs
  bool fragment = false;                    // the module's entry point is a fragment shader
  InstructionCounts instructions;

  double& operator[](OpClass c) { return ops[size_t(c)]; }
  double operator[](OpClass c) const { return ops[size_t(c)]; }
};

// What an operation that is not one FMA-pipe instruction costs: FMA slots and SFU ops.
struct Expansion {
  double fma = 0;
  double sfu = 0;
};

// How the arithmetic pipes combine. Valhall's FMA, CVT and SFU pipes accept work concurrently,
// so the busiest one bounds the stage (Concurrent: Mesa's and Arm's offline compilers report this
// bound); Shared charges every op to one issue slot stream (SFU ops at sfuFmaSlots each), an upper
// bound for code whose SFU work cannot overlap its FMA work.
enum class ArithmeticPipes { Concurrent, Shared };

// The weights of the model, in one table. Sources: docs/platform-facts.md, "Mobile GPU compilers"
// (the facts), and Mesa's Valhall cycle model (src/panfrost/compiler,
// va_print_stats: per-core peak rates of Mali-G78, which Mesa applies to every Valhall GPU, and
// the bound over pipes). docs/eval.md compares the result with the measured Mali-G57 cycles.
struct MobileCostWeights {
  // Issue rates per shader core per cycle (Mesa: 64 FMA, 64 CVT, 16 SFU, 4 texture instructions,
  // 16 16-bit varying channels). A "cycle" is a figure of the same scale as Mesa's shader-db
  // statistics, the scale of the Mali-G57 measurements.
  double fmaPerCycle = 64;  // FMA and CVT pipes alike
  double sfuFmaSlots = 4;   // facts: an SFU op issues at a quarter of the FMA rate = 4 FMA slots
  double texturesPerCycle = 4;
  double varyingChannelsPerCycle = 16;  // 16-bit channels: a mediump component is 1, a highp one 2
  ArithmeticPipes pipes = ArithmeticPipes::Concurrent;
  // Expansions, per scalar component.
  Expansion sfu{0, 1};  // facts: exp2, log2, rsq, rcp, sin, cos are one SFU op each
  Expansion expLog{1, 1};
  Expansion sqrt{0, 2};  // facts: sqrt costs two SFU ops
  Expansion pow{1, 2};   // facts: pow costs two SFU ops (log2, exp2) + the multiply
  Expansion sinCos{1, 1};
  Expansion tan{2, 3};           // sin, cos, rcp; range reduction and the multiply
  Expansion inverseTrig{20, 1};  // facts: 15–25 FMA-class ops plus SFU ops; the middle of the range
  Expansion atan2{23, 1};        // atan's, plus compare/select/add for the quadrant
  Expansion hyperbolic{3, 2};
  Expansion inverseHyperbolic{3, 3};
  Expansion division{1, 1};         // rcp + mul
  Expansion integerDivision{4, 1};  // reciprocal estimate and a correction step
  Expansion derivative{1, 1};       // Valhall v9: lane exchange (CLPER) on the SFU pipe, then a subtract
  // A mediump (RelaxedPrecision) FMA-pipe op: Valhall's FMA pipe runs two fp16 lanes per slot
  // (v2f16), and Mesa lowers mediump to fp16 and pairs 16-bit ALU ops into vec2s, so a mediump
  // component weighs half a slot. (Expansions and highp ops weigh 1.)
  double relaxedFmaWeight = 0.5;
};

// The estimate of one stage.
struct MobileStageCost {
  OpClassCounts counts;
  double fmaSlots = 0;  // FMA-pipe slots, expansions included
  double cvtSlots = 0;  // CVT-pipe slots
  double sfuOps = 0;    // SFU ops, expansions included
  double textureSamples = 0;
  double varyingChannels = 0;  // 16-bit channels interpolated
  // Concurrent: max(fmaSlots, cvtSlots, sfuFmaSlots · sfuOps) / fmaPerCycle;
  // Shared: (fmaSlots + cvtSlots + sfuFmaSlots · sfuOps) / fmaPerCycle.
  double arithmeticCycles = 0;
  double textureCycles = 0;
  double varyingCycles = 0;
  // The estimate: the busiest unit. Arithmetic, texture and varying units run concurrently on
  // Valhall, so the slowest bounds the stage (Mesa reports the same bound).
  double cycles = 0;
  const char* bound() const;  // "arithmetic" | "texture" | "varying"
  // Convenience counts for reports and lint.
  double transcendentals() const;  // every op with an SFU part except division and derivatives
  double divisions() const;        // float and integer divisions by a non-constant
};

// The cost model calibrated per GPU against Mesa's compilers (docs/mesa-statistics.md,
// "Calibration"): non-negative weights of the op classes, fitted on the example materials'
// fragment shaders and single-operation shaders. An estimate of a fragment stage's Mesa figure
// (Mali: cycles; Adreno: non-nop instructions) where the compilers are not at hand; meaningless
// for a vertex stage (Mali's are bound by load/store, which no class counts).
enum class CalibratedClass {
  FmaMediump,
  FmaHighp,
  Convert,
  Sfu,
  ExpLog,
  Sqrt,
  Pow,
  SinCos,
  Tan,
  InverseTrig,
  Atan2,
  Division,
  TextureSample,
  Count,
};
inline constexpr size_t kCalibratedClassCount = size_t(CalibratedClass::Count);

struct GpuCalibration {
  const char* gpu;                                    // as `--gpu` names it, e.g. "mali-g57"
  const char* measure;                                // what the weights estimate, e.g. "fragment cycles"
  std::array<double, kCalibratedClassCount> weights;  // per scalar component, by CalibratedClass
  // The fit's relative error over the example variants, and cross-validated (fitted without the
  // variant's material).
  double meanError, maxError, crossValidatedMeanError, crossValidatedMaxError;
};

// Every calibrated GPU (compiler/src/mesa_calibration.cpp, generated by tools/mesa_stats/fit.py).
const std::vector<GpuCalibration>& gpuCalibrations();
const GpuCalibration* findGpuCalibration(const std::string& gpu);  // nullptr when not calibrated
double calibratedEstimate(const OpClassCounts& fragment, const GpuCalibration& calibration);

// Counts the operations inside function bodies. False with *error on malformed SPIR-V (the
// words may come from a package file).
bool countOpClasses(const std::vector<uint32_t>& words, OpClassCounts* counts, std::string* error);

MobileStageCost weighMobileCost(const OpClassCounts& counts, const MobileCostWeights& weights = {});

// countOpClasses + weighMobileCost.
bool estimateMobileCost(const std::vector<uint32_t>& words, MobileStageCost* cost, std::string* error,
                        const MobileCostWeights& weights = {});

}  // namespace facet::compiler
