#include "facet/lint/precision_rules.h"

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
    }
    if (mediump_) outputs();
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
