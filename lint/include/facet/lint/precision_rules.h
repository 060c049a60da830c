// `matc lint`'s precision rules: facts the value-range analysis (ir/ranges.h) proves about a
// checked, optimised material, each reported at the material line that wrote the value.
//
// Rule ids (stable: CI configurations and SARIF consumers key on them):
//   fp16-constant       a constant outside binary16's normal range, |c| < 2^-14 (a mobile GPU
//                       flushes it to 0) or |c| > 65504 (+inf), in a mediump expression
//   fp16-overflow       a value computed in mediump whose proven range leaves ±65504: a surface
//                       output (MaterialInputs is mediump in mediump tiers, whatever the value's
//                       own precision)
//   unranged-param      a float parameter without `in [lo, hi]` read by a mediump tier: nothing
//                       proves its uses stay finite in fp16
//   division-bound      a divisor whose range reaches 0 (highp) or below 2^-14 in magnitude
//                       (mediump, where smaller magnitudes flush to 0): the quotient can be ±inf
//   domain              sqrt of a value that can be negative, log2 of one that can be ≤ 0,
//                       pow(x, y) where x can be negative (undefined in GLSL): an error when
//                       every value of the range is outside the domain, a warning when some are
//   direction-length    a direction the shaders normalize in mediump (`normal`, `clearCoatNormal`,
//                       `anisotropyDirection`, the material's own normalize) whose squared length
//                       can fall below 2^-14 (flushed: NaN) or above 65504 (+inf: 0 or NaN); an
//                       error when every value of the range does
#pragma once

#include "facet/ir/diagnostics.h"
#include "facet/ir/module.h"

namespace facet::lint {

// `mediump`: whether any tier the material is built for computes in mediump (every tier but
// `reference`); the fp16 rules are silent otherwise.
void lint_precision(const ir::Material& optimized, bool mediump, ir::Diagnostics& diagnostics);

}  // namespace facet::lint
