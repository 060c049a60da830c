#include "facet/lint/precision_rules.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "facet/ir/precision.h"
#include "facet/ir/ranges.h"

namespace facet::lint {
namespace {

using ir::Interval;
using ir::kFp16Max;
using ir::kFp16MinNormal;
using ir::Op;
using ir::ValueId;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string describe(Interval r) { return "[" + number(r.lo) + ", " + number(r.hi) + "]"; }

bool isFloat(ir::Type t) { return t != ir::Type::Bool && t != ir::Type::Int && t != ir::Type::Texture2D; }

class Rules {
 public:
  Rules(const ir::Material& m, bool mediump, ir::Diagnostics& diags)
      : m_(m),
        module_(m.surface),
        mediump_(mediump),
        diags_(diags),
        ranges_(ir::analyse_ranges(m)),
        precision_(ir::analyse_precision(m, ranges_)) {}

  void run() {
    if (mediump_) unrangedParams();
    for (ValueId id = 0; id < module_.size(); ++id) {
      const ir::Value& v = module_.value(id);
      if (v.op == Op::Constant || v.op == Op::Param || v.op == Op::Attribute) continue;
      if (mediump_ && !precision_.highp(id) && isFloat(v.type) && !ir::isTextureRead(v))
        for (ValueId a : v.args) constantOperand(a, id);
      if (v.op == Op::Div) divisor(v.args[1], id);
      if (v.op == Op::Builtin) builtinDomain(v, id);
      if (mediump_ && v.op == Op::Builtin && v.name == "normalize" && !precision_.highp(id) &&
          ir::componentCount(v.type) > 1)
        directionLength(v.args[0], id, "normalize's argument", true);
    }
    if (mediump_) outputs();
    if (mediump_) directionOutputs();
  }

 private:
  ir::SourceLoc locOf(ValueId id, ValueId fallback) const {
    if (const ir::SourceLoc* loc = module_.locOf(id)) return *loc;
    if (const ir::SourceLoc* loc = module_.locOf(fallback)) return *loc;
    return {};
  }

  Interval hullOf(ValueId id) const { return ranges_.of(id).hull(); }

  void unrangedParams() {
    for (const ir::Param& p : m_.params) {
      if (!p.used || p.isColor || p.rangeMin || !isFloat(p.type)) continue;
      diags_.warning(p.loc,
                     "parameter '" + p.name +
                         "' has no range: in mediump tiers nothing proves its uses stay within "
                         "fp16's ±65504; declare one with `in [lo, hi]`",
                     "unranged-param");
    }
  }

  // Constants are interned, so one literal used in several places is reported once.
  void constantOperand(ValueId arg, ValueId user) {
    const ir::Value& c = module_.value(arg);
    if (c.op != Op::Constant || !isFloat(c.type) || !reportedConstants_.insert(arg).second) return;
    for (int i = 0; i < ir::componentCount(c.type); ++i) {
      double x = std::abs(c.constant[size_t(i)]);
      if (x == 0.0 || (x >= kFp16MinNormal && x <= kFp16Max)) continue;
      std::string why = x > kFp16Max ? "is above fp16's largest value 65504 and becomes +inf"
                                     : "is below fp16's smallest normal value 2^-14 (6.1e-05) and flushes to 0";
      diags_.warning(locOf(arg, user), "constant " + number(c.constant[size_t(i)]) + " in a mediump expression " + why,
                     "fp16-constant");
      return;
    }
  }

  void divisor(ValueId d, ValueId division) {
    Interval r = hullOf(d);
    bool mediump = mediump_ && !precision_.highp(d);
    double bound = mediump ? kFp16MinNormal : 0.0;
    // |d| ≥ bound everywhere in the range: strictly for highp (0 itself is the problem).
    bool safe = mediump ? (r.lo >= bound || r.hi <= -bound) : (r.lo > 0.0 || r.hi < 0.0);
    if (safe) return;
    std::string what = mediump
                           ? "a mediump divisor with no proven magnitude ≥ 2^-14 (smaller values flush to 0 in fp16)"
                           : "a divisor that can be 0";
    diags_.warning(locOf(division, d), "division by " + what + "; its range is " + describe(r), "division-bound");
  }

  void builtinDomain(const ir::Value& v, ValueId id) {
    if (v.name == "sqrt") {
      Interval x = hullOf(v.args[0]);
      if (x.hi < 0.0)
        domainError(id, "sqrt of a value that is always negative " + describe(x) + " is NaN");
      else if (x.lo < 0.0)
        domainWarning(id, "sqrt of a value that can be negative " + describe(x) + " is NaN there");
    } else if (v.name == "log2") {
      Interval x = hullOf(v.args[0]);
      if (x.hi <= 0.0)
        domainError(id, "log2 of a value that is never positive " + describe(x) + " is -inf or NaN");
      else if (x.lo <= 0.0)
        domainWarning(id, "log2 of a value that can be 0 or negative " + describe(x) + " is -inf or NaN there");
    } else if (v.name == "pow") {
      Interval x = hullOf(v.args[0]), y = hullOf(v.args[1]);
      if (x.hi < 0.0)
        domainError(id, "pow(x, y) with x always negative " + describe(x) + " is undefined in GLSL");
      else if (x.lo < 0.0)
        domainWarning(id, "pow(x, y) with x that can be negative " + describe(x) + " is undefined in GLSL there");
      else if (x.lo <= 0.0 && y.lo <= 0.0)
        domainWarning(id, "pow(x, y) with x that can be 0 and y that can be ≤ 0 is undefined in GLSL there");
    } else if (v.name == "smoothstep") {
      // smoothstep divides by (edge1 − edge0); GLSL leaves edge0 ≥ edge1 undefined.
      Interval e0 = hullOf(v.args[0]), e1 = hullOf(v.args[1]);
      if (e1.lo - e0.hi <= 0.0)
        domainWarning(id, "smoothstep's edges can meet or cross (edge0 " + describe(e0) + ", edge1 " + describe(e1) +
                              "): it divides by edge1 − edge0");
    }
  }

  void domainError(ValueId id, const std::string& message) { diags_.error(locOf(id, id), message, "domain"); }
  void domainWarning(ValueId id, const std::string& message) { diags_.warning(locOf(id, id), message, "domain"); }

  // MaterialInputs is declared at the fragment stage's default precision: in a mediump tier an
  // output holds fp16 even when the value written to it was computed in highp.
  void outputs() {
    for (const auto& [name, id] : module_.outputs) {
      const ir::Value& v = module_.value(id);
      if (!isFloat(v.type)) continue;
      Interval r = hullOf(id);
      if (!r.bounded() || std::max(std::abs(r.lo), std::abs(r.hi)) <= kFp16Max) continue;
      diags_.warning(
          locOf(id, id),
          "output '" + name + "' can reach " + describe(r) + ", beyond fp16's ±65504: mediump tiers store it as +inf",
          "fp16-overflow");
    }
  }

  // |x|² of a vector, bounded tighter than its components' intervals allow where the IR shows
  // the structure: a unit vector (normalize, a normal map's sample), a scale of one, a vector
  // built from parts. A normal map's texels are taken as unit vectors, as the map's author made
  // them: the rule checks what the material's arithmetic does to them, not the image.
  Interval lengthSquared(ValueId id, int depth = 0) const {
    const ir::Value& v = module_.value(id);
    auto squared = [](Interval r) {
      const double a = r.lo * r.lo, b = r.hi * r.hi;
      return r.contains(0.0) ? Interval{0.0, std::max(a, b)} : Interval{std::min(a, b), std::max(a, b)};
    };
    auto sum = [](Interval a, Interval b) { return Interval{a.lo + b.lo, a.hi + b.hi}; };
    if (depth < 32) {
      if (v.op == Op::Builtin && (v.name == "normalize" || v.name == "sample_normal")) return {1.0, 1.0};
      if (v.op == Op::Neg) return lengthSquared(v.args[0], depth + 1);
      if (v.op == Op::Mul && v.args.size() == 2) {
        for (int scalar = 0; scalar < 2; ++scalar) {
          const ValueId s = v.args[size_t(scalar)], x = v.args[size_t(1 - scalar)];
          if (ir::componentCount(module_.value(s).type) != 1 || ir::componentCount(module_.value(x).type) == 1)
            continue;
          const Interval k = squared(hullOf(s)), n = lengthSquared(x, depth + 1);
          auto product = [](double a, double b) { return a == 0.0 || b == 0.0 ? 0.0 : a * b; };  // 0 · inf: 0
          return {product(k.lo, n.lo), product(k.hi, n.hi)};
        }
      }
      if (v.op == Op::Construct && v.args.size() > 1) {
        Interval total{0.0, 0.0};
        for (ValueId a : v.args)
          total = sum(
              total, ir::componentCount(module_.value(a).type) == 1 ? squared(hullOf(a)) : lengthSquared(a, depth + 1));
        return total;
      }
      if (v.op == Op::Select) {
        const Interval a = lengthSquared(v.args[1], depth + 1), b = lengthSquared(v.args[2], depth + 1);
        return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
      }
    }
    const ir::ValueRange& r = ranges_.of(id);
    Interval total{0.0, 0.0};
    for (int i = 0; i < r.components; ++i) total = sum(total, squared(r.c[size_t(i)]));
    return total;
  }

  // A vector the shader normalizes in mediump: normalize(x) is x · inversesqrt(x·x), and x·x
  // flushes to 0 below 2^-14 (|x| < 2^-7: normalize gives 0 · inf = NaN) and is +inf above 65504
  // (|x| > 255.9: normalize gives 0, or NaN). `shortIsHazard`: false where the shader replaces a
  // short vector itself (anisotropy_frame.glsl's fallback below |t|² = 1e-3).
  void directionLength(ValueId x, ValueId at, const std::string& what, bool shortIsHazard) {
    const Interval n = lengthSquared(x);
    const std::string range = "its squared length is in " + describe(n);
    // A length always beyond fp16's bound is an error, one that can reach it a warning.
    const auto report = [&](bool always, const char* bound, const char* consequence) {
      const std::string message =
          what + (always ? " is always " : " can be ") + bound + " (" + range + "): " + consequence;
      if (always)
        diags_.error(locOf(at, x), message, "direction-length");
      else
        diags_.warning(locOf(at, x), message, "direction-length");
    };
    if (shortIsHazard && n.hi == 0.0) {
      diags_.error(locOf(at, x), what + " is always the zero vector: normalize gives NaN (0 · inf) in every precision",
                   "direction-length");
    } else if (shortIsHazard && n.lo < kFp16MinNormal) {
      report(n.hi < kFp16MinNormal, "shorter than 2^-7",
             "in fp16 its squared length flushes to 0 and normalize gives NaN (0 · inf)");
    } else if (n.hi > kFp16Max) {
      const bool always = n.lo > kFp16Max;
      report(always, "longer than 255.9",
             always ? "in fp16 its squared length is +inf and normalize gives 0 or NaN"
                    : "in fp16 its squared length overflows to +inf and normalize gives 0 or NaN");
    }
  }

  // The tangent-space directions the shaders normalize (normal_mapping.glsl's tangent_to_world for
  // `normal` and `clearCoatNormal`: normalize(x t + y b + z n), |·|² ≈ x² + y² + z² on the unit
  // frame; anisotropy_frame.glsl for `anisotropyDirection`, whose own fallback takes a short one).
  void directionOutputs() {
    for (const auto& [name, id] : module_.outputs) {
      if (name != "normal" && name != "clearCoatNormal" && name != "anisotropyDirection") continue;
      directionLength(id, id, "output '" + name + "'", name != "anisotropyDirection");
    }
  }

  const ir::Material& m_;
  const ir::Module& module_;
  bool mediump_;
  ir::Diagnostics& diags_;
  ir::RangeMap ranges_;
  ir::PrecisionMap precision_;
  std::set<ValueId> reportedConstants_;
};

}  // namespace

void lint_precision(const ir::Material& optimized, bool mediump, ir::Diagnostics& diagnostics) {
  Rules(optimized, mediump, diagnostics).run();
}

}  // namespace facet::lint
