// The precision policy of mediump tiers (docs/architecture.md, "Tiers"): which surface values
// must stay highp. One answer for every consumer: GLSL emission declares those values highp,
// and the lint's fp16 rules look only at the values left mediump.
#pragma once

#include <vector>

#include "facet/ir/module.h"
#include "facet/ir/ranges.h"

namespace facet::ir {

// binary16's largest finite value, (2 − 2^-10) · 2^15. A mediump result beyond it is +inf on a
// GPU that computes mediump in fp16.
inline constexpr double kFp16Max = 65504.0;
// binary16's smallest normal value, 2^-14 ≈ 6.1e-5. Mobile GPUs flush smaller magnitudes to 0.
inline constexpr double kFp16MinNormal = 0x1p-14;

class PrecisionMap {
 public:
  bool highp(ValueId id) const { return highp_[id]; }

 private:
  friend PrecisionMap analyse_precision(const Material& material, const RangeMap& ranges);
  std::vector<bool> highp_;
};

// A value is highp when
//   - it reads a highp attribute (positions, UVs: the policy keeps them highp), directly or through
//     its operands, except across a texture read: the coordinate needs highp, the 8-bit result
//     has the sampler's precision;
//   - or its proven range leaves fp16's finite range (|x| > 65504, e.g. a parameter declared
//     `in [0, 100000]`): fp32 rather than +inf on a mobile GPU. Unbounded values (unranged
//     parameters) keep the tier's precision: their range is a promise the author has not made.
// Every other value takes the tier's default precision.
PrecisionMap analyse_precision(const Material& material, const RangeMap& ranges);

// sample() and sample_normal(): their results take the sampler's precision.
bool isTextureRead(const Value& v);

}  // namespace facet::ir
