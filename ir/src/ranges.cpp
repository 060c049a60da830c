#include "facet/ir/ranges.h"

#include <algorithm>
#include <cmath>

namespace facet::ir {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const Interval kAny{};
const Interval kUnit{0.0, 1.0};
const Interval kSigned{-1.0, 1.0};

// The interval spanned by some candidate values; any NaN (inf − inf, 0 × inf) makes it unknown.
Interval span(std::initializer_list<double> values) {
  Interval r{kInf, -kInf};
  for (double v : values) {
    if (std::isnan(v)) return kAny;
    r.lo = std::min(r.lo, v);
    r.hi = std::max(r.hi, v);
  }
  return r;
}

Interval add(Interval a, Interval b) { return span({a.lo + b.lo, a.hi + b.hi}); }
Interval sub(Interval a, Interval b) { return span({a.lo - b.hi, a.hi - b.lo}); }
Interval mul(Interval a, Interval b) { return span({a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi}); }
Interval div(Interval a, Interval b) {
  if (b.contains(0.0)) return a == Interval{0, 0} ? a : kAny;
  return mul(a, span({1.0 / b.lo, 1.0 / b.hi}));
}
Interval hull(Interval a, Interval b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }
Interval minOf(Interval a, Interval b) { return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)}; }
Interval maxOf(Interval a, Interval b) { return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)}; }
Interval clampTo(Interval a, Interval to) { return {std::clamp(a.lo, to.lo, to.hi), std::clamp(a.hi, to.lo, to.hi)}; }
Interval square(Interval a) {
  Interval m = mul(a, a);
  if (a.contains(0.0)) m.lo = 0.0;
  return m;
}

// f monotonic increasing on the interval.
template <typename F>
Interval increasing(Interval a, F f) {
  return span({f(a.lo), f(a.hi)});
}

// pow(x, y) for x ≥ 0 is monotonic in x for fixed y and in y for fixed x, so its extremes over a
// box lie at the corners. GLSL leaves pow undefined for x < 0: unknown.
Interval pow(Interval x, Interval y) {
  if (x.lo < 0.0) return kAny;
  return span({std::pow(x.lo, y.lo), std::pow(x.lo, y.hi), std::pow(x.hi, y.lo), std::pow(x.hi, y.hi)});
}

class Analysis {
 public:
  explicit Analysis(const Material& m) : m_(m), module_(m.surface) {}

  std::vector<ValueRange> run() {
    std::vector<ValueRange> out;
    out.reserve(module_.size());
    for (ValueId id = 0; id < module_.size(); ++id) out.push_back(range(module_.value(id), out));
    return out;
  }

 private:
  ValueRange range(const Value& v, const std::vector<ValueRange>& known) {
    ValueRange r;
    r.components = componentCount(v.type);
    auto arg = [&](size_t k, int i) {
      const ValueRange& a = known[v.args[k]];
      return a.components == 1 ? a.c[0] : a.c[size_t(i)];
    };
    auto each = [&](auto f) {
      for (int i = 0; i < r.components; ++i) r.c[size_t(i)] = f(i);
      return r;
    };
    switch (v.op) {
      case Op::Constant: return each([&](int i) { return Interval{v.constant[size_t(i)], v.constant[size_t(i)]}; });
      case Op::Param: return param(v, r);
      case Op::Attribute: return each([&](int) { return attributeRange(v.name); });
      case Op::Swizzle:
        return each([&](int i) { return known[v.args[0]].c[std::string("xyzw").find(v.name[size_t(i)])]; });
      case Op::Construct: {
        if (v.args.size() == 1 && known[v.args[0]].components == 1) return each([&](int) { return arg(0, 0); });
        size_t k = 0;
        for (ValueId a : v.args)
          for (int i = 0; i < known[a].components && k < 4; ++i) r.c[k++] = known[a].c[size_t(i)];
        return r;
      }
      case Op::Neg: return each([&](int i) { return Interval{-arg(0, i).hi, -arg(0, i).lo}; });
      case Op::Add: return each([&](int i) { return add(arg(0, i), arg(1, i)); });
      case Op::Sub: return each([&](int i) { return sub(arg(0, i), arg(1, i)); });
      case Op::Mul: return each([&](int i) { return mul(arg(0, i), arg(1, i)); });
      case Op::Div: return each([&](int i) { return div(arg(0, i), arg(1, i)); });
      case Op::Select: return each([&](int i) { return hull(arg(1, i), arg(2, i)); });
      case Op::Builtin: return builtin(v, r, arg, each);
      default: return each([&](int) { return kUnit; });  // comparisons and logic: bool as 0/1
    }
  }

  // Unit vectors are in [-1, 1]; vertex colours are UNORM data by the mesh contract
  // (render_backend.h); positions and UVs are unbounded.
  static Interval attributeRange(const std::string& name) {
    if (name == "normal" || name == "viewDirection") return kSigned;
    if (name == "color") return kUnit;
    return kAny;
  }

  ValueRange param(const Value& v, ValueRange r) {
    for (const Param& p : m_.params) {
      if (p.name != v.name) continue;
      Interval declared;
      if (p.rangeMin) declared = {*p.rangeMin, *p.rangeMax};
      if (p.isColor) declared = kUnit;  // linear colour of an sRGB value in [0, 1]
      if (p.type == Type::Bool) declared = kUnit;
      for (int i = 0; i < r.components; ++i) r.c[size_t(i)] = declared;
    }
    return r;
  }

  template <typename Arg, typename Each>
  ValueRange builtin(const Value& v, ValueRange r, Arg arg, Each each) {
    const std::string& f = v.name;
    const int n = componentCount(m_.surface.value(v.args[0]).type);
    if (f == "abs")
      return each([&](int i) {
        Interval a = arg(0, i);
        if (a.lo >= 0) return a;
        if (a.hi <= 0) return Interval{-a.hi, -a.lo};
        return Interval{0.0, std::max(-a.lo, a.hi)};
      });
    if (f == "floor") return each([&](int i) { return increasing(arg(0, i), [](double x) { return std::floor(x); }); });
    if (f == "fract") return each([&](int) { return kUnit; });
    if (f == "sqrt")
      return each([&](int i) { return increasing(arg(0, i), [](double x) { return std::sqrt(std::max(x, 0.0)); }); });
    if (f == "exp2") return each([&](int i) { return increasing(arg(0, i), [](double x) { return std::exp2(x); }); });
    if (f == "log2")
      return each([&](int i) { return increasing(arg(0, i), [](double x) { return x <= 0 ? -kInf : std::log2(x); }); });
    if (f == "sin" || f == "cos" || f == "normalize") return each([&](int) { return kSigned; });
    if (f == "sample") return each([&](int) { return kUnit; });  // 8-bit UNORM / sRGB images
    if (f == "sample_normal") return each([&](int) { return Interval{-128.0 / 127.0, 1.0}; });  // emit_glsl's decode
    if (f == "saturate" || f == "step" || f == "smoothstep")
      return each([&](int i) { return f == "saturate" ? clampTo(arg(0, i), kUnit) : kUnit; });
    if (f == "pow") return each([&](int i) { return pow(arg(0, i), arg(1, i)); });
    if (f == "min") return each([&](int i) { return minOf(arg(0, i), arg(1, i)); });
    if (f == "max") return each([&](int i) { return maxOf(arg(0, i), arg(1, i)); });
    if (f == "clamp") return each([&](int i) { return minOf(maxOf(arg(0, i), arg(1, i)), arg(2, i)); });
    if (f == "mix")
      return each([&](int i) {
        Interval t = arg(2, i);
        // With t in [0, 1] the result lies between a and b; otherwise a + (b − a)·t.
        if (t.lo >= 0.0 && t.hi <= 1.0) return hull(arg(0, i), arg(1, i));
        return add(arg(0, i), mul(sub(arg(1, i), arg(0, i)), t));
      });
    if (f == "dot" || f == "length") {
      // dot(x, x) is a sum of squares: naive interval products would let it go negative.
      bool squares = f == "length" || v.args[0] == v.args[1];
      Interval sum{0, 0};
      for (int i = 0; i < n; ++i) sum = add(sum, squares ? square(arg(0, i)) : mul(arg(0, i), arg(1, i)));
      if (f == "length") sum = increasing(sum, [](double x) { return std::sqrt(std::max(x, 0.0)); });
      r.c[0] = sum;
      return r;
    }
    if (f == "cross") {
      auto c = [&](int a, int b) { return sub(mul(arg(0, a), arg(1, b)), mul(arg(0, b), arg(1, a))); };
      r.c[0] = c(1, 2);
      r.c[1] = c(2, 0);
      r.c[2] = c(0, 1);
      return r;
    }
    return each([&](int) { return kAny; });
  }

  const Material& m_;
  const Module& module_;
};

}  // namespace

Interval ValueRange::hull() const {
  Interval h = c[0];
  for (int i = 1; i < components; ++i) h = {std::min(h.lo, c[size_t(i)].lo), std::max(h.hi, c[size_t(i)].hi)};
  return h;
}

std::optional<ValueRange> RangeMap::output(const std::string& name) const {
  auto it = outputs_.find(name);
  if (it == outputs_.end()) return std::nullopt;
  return ranges_[it->second];
}

RangeMap analyse_ranges(const Material& material) {
  RangeMap map;
  map.ranges_ = Analysis(material).run();
  map.outputs_ = material.surface.outputs;
  return map;
}

}  // namespace facet::ir
