#include "evaluate.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace facet::ir {
namespace {

double component(const Components& c, Type t, int i) { return componentCount(t) == 1 ? c[0] : c[size_t(i)]; }

std::optional<Components> builtin(const std::string& name, Type result, const std::vector<Components>& a,
                                  const std::vector<Type>& t) {
  Components r{};
  const int n = componentCount(result);
  auto each = [&](auto f) {
    for (int i = 0; i < n; ++i) r[size_t(i)] = f(i);
    return r;
  };
  auto arg = [&](size_t k, int i) { return component(a[k], t[k], i); };
  auto sum = [&](auto f) {
    double s = 0;
    for (int i = 0; i < componentCount(t[0]); ++i) s += f(i);
    return s;
  };
  if (name == "abs") return each([&](int i) { return std::fabs(arg(0, i)); });
  if (name == "floor") return each([&](int i) { return std::floor(arg(0, i)); });
  if (name == "fract") return each([&](int i) { return arg(0, i) - std::floor(arg(0, i)); });
  if (name == "sqrt") return each([&](int i) { return std::sqrt(arg(0, i)); });
  if (name == "exp2") return each([&](int i) { return std::exp2(arg(0, i)); });
  if (name == "log2") return each([&](int i) { return std::log2(arg(0, i)); });
  if (name == "sin") return each([&](int i) { return std::sin(arg(0, i)); });
  if (name == "cos") return each([&](int i) { return std::cos(arg(0, i)); });
  if (name == "saturate") return each([&](int i) { return std::clamp(arg(0, i), 0.0, 1.0); });
  if (name == "pow") return each([&](int i) { return std::pow(arg(0, i), arg(1, i)); });
  if (name == "min") return each([&](int i) { return std::min(arg(0, i), arg(1, i)); });
  if (name == "max") return each([&](int i) { return std::max(arg(0, i), arg(1, i)); });
  if (name == "step") return each([&](int i) { return arg(1, i) < arg(0, i) ? 0.0 : 1.0; });
  if (name == "mix") return each([&](int i) { return arg(0, i) + (arg(1, i) - arg(0, i)) * arg(2, i); });
  if (name == "clamp") return each([&](int i) { return std::min(std::max(arg(0, i), arg(1, i)), arg(2, i)); });
  if (name == "smoothstep")
    return each([&](int i) {
      double x = std::clamp((arg(2, i) - arg(0, i)) / (arg(1, i) - arg(0, i)), 0.0, 1.0);
      return x * x * (3.0 - 2.0 * x);
    });
  if (name == "length") return Components{std::sqrt(sum([&](int i) { return arg(0, i) * arg(0, i); }))};
  if (name == "dot") return Components{sum([&](int i) { return arg(0, i) * arg(1, i); })};
  if (name == "normalize") {
    double len = std::sqrt(sum([&](int i) { return arg(0, i) * arg(0, i); }));
    return each([&](int i) { return arg(0, i) / len; });
  }
  if (name == "cross")
    return Components{a[0][1] * a[1][2] - a[0][2] * a[1][1], a[0][2] * a[1][0] - a[0][0] * a[1][2],
                      a[0][0] * a[1][1] - a[0][1] * a[1][0], 0};
  return std::nullopt;
}

}  // namespace

std::optional<Components> evaluate(const Value& v, const std::vector<Components>& a, const std::vector<Type>& t) {
  Components r{};
  const int n = componentCount(v.type);
  auto arg = [&](size_t k, int i) { return component(a[k], t[k], i); };
  auto each = [&](auto f) {
    for (int i = 0; i < n; ++i) r[size_t(i)] = f(i);
  };
  switch (v.op) {
    case Op::Constant: r = v.constant; break;
    case Op::Param:
    case Op::Attribute: return std::nullopt;
    case Op::Swizzle:
      for (size_t i = 0; i < v.name.size(); ++i) r[i] = a[0][size_t(std::string("xyzw").find(v.name[i]))];
      break;
    case Op::Construct: {
      if (a.size() == 1 && componentCount(t[0]) == 1) {
        each([&](int) { return a[0][0]; });
        break;
      }
      size_t k = 0;
      for (size_t j = 0; j < a.size(); ++j)
        for (int i = 0; i < componentCount(t[j]) && k < 4; ++i) r[k++] = a[j][size_t(i)];
      break;
    }
    case Op::Neg: each([&](int i) { return -arg(0, i); }); break;
    case Op::Not: r[0] = a[0][0] != 0.0 ? 0.0 : 1.0; break;
    case Op::Add: each([&](int i) { return arg(0, i) + arg(1, i); }); break;
    case Op::Sub: each([&](int i) { return arg(0, i) - arg(1, i); }); break;
    case Op::Mul: each([&](int i) { return arg(0, i) * arg(1, i); }); break;
    case Op::Div:
      if (v.type == Type::Int) {
        if (a[1][0] == 0.0) return std::nullopt;
        r[0] = std::trunc(a[0][0] / a[1][0]);
      } else {
        each([&](int i) { return arg(0, i) / arg(1, i); });
      }
      break;
    case Op::Less: r[0] = a[0][0] < a[1][0]; break;
    case Op::LessEqual: r[0] = a[0][0] <= a[1][0]; break;
    case Op::Greater: r[0] = a[0][0] > a[1][0]; break;
    case Op::GreaterEqual: r[0] = a[0][0] >= a[1][0]; break;
    case Op::Equal: r[0] = a[0][0] == a[1][0]; break;
    case Op::NotEqual: r[0] = a[0][0] != a[1][0]; break;
    case Op::And: r[0] = a[0][0] != 0.0 && a[1][0] != 0.0; break;
    case Op::Or: r[0] = a[0][0] != 0.0 || a[1][0] != 0.0; break;
    case Op::Select: r = a[0][0] != 0.0 ? a[1] : a[2]; break;
    case Op::Builtin: {
      auto b = builtin(v.name, v.type, a, t);
      if (!b) return std::nullopt;
      r = *b;
      break;
    }
  }
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(r[size_t(i)])) return std::nullopt;
  for (int i = n; i < 4; ++i) r[size_t(i)] = 0.0;
  return r;
}

namespace {

std::optional<Components> evaluateMemo(const Module& m, ValueId id,
                                       std::map<ValueId, std::optional<Components>>& memo) {
  if (auto it = memo.find(id); it != memo.end()) return it->second;
  const Value& v = m.value(id);
  std::vector<Components> args;
  std::vector<Type> types;
  std::optional<Components> result;
  bool constant = true;
  for (ValueId a : v.args) {
    auto c = evaluateMemo(m, a, memo);
    if (!c) {
      constant = false;
      break;
    }
    args.push_back(*c);
    types.push_back(m.value(a).type);
  }
  if (constant) result = evaluate(v, args, types);
  memo.emplace(id, result);
  return result;
}

}  // namespace

std::optional<Components> evaluateConstant(const Module& m, ValueId id) {
  std::map<ValueId, std::optional<Components>> memo;
  return evaluateMemo(m, id, memo);
}

}  // namespace facet::ir
