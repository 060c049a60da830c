#include "facet/ir/precision.h"

#include <algorithm>
#include <cmath>

namespace facet::ir {

bool isTextureRead(const Value& v) { return v.op == Op::Builtin && (v.name == "sample" || v.name == "sample_normal"); }

PrecisionMap analyse_precision(const Material& material, const RangeMap& ranges) {
  const Module& module = material.surface;
  PrecisionMap map;
  map.highp_.assign(module.size(), false);
  // Operands always have smaller ids than their users (module.h), so one pass in id order sees
  // every operand decided before its users.
  for (ValueId id = 0; id < module.size(); ++id) {
    const Value& v = module.value(id);
    bool h = v.op == Op::Attribute && findAttribute(v.name)->highp;
    if (!isTextureRead(v))
      for (ValueId a : v.args) h = h || map.highp_[a];
    Interval r = ranges.of(id).hull();
    h = h || (r.bounded() && std::max(std::abs(r.lo), std::abs(r.hi)) > kFp16Max);
    map.highp_[id] = h;
  }
  return map;
}

}  // namespace facet::ir
