#include "facet/ir/passes.h"

#include <limits>
#include <set>

#include "evaluate.h"

namespace facet::ir {
namespace {

constexpr ValueId kDropped = std::numeric_limits<ValueId>::max();

// Rebuilds `in` value by value in id order (operands always have smaller ids than their users).
// `keep[id]` false drops a value; `replace(out, value with remapped operands)` returns the id of
// its replacement in `out`.
template <typename Replace>
Module rebuild(const Module& in, const std::vector<bool>& keep, Replace replace) {
  Module out;
  std::vector<ValueId> remap(in.size(), kDropped);
  for (ValueId id = 0; id < in.size(); ++id) {
    if (!keep[id]) continue;
    Value v = in.value(id);
    for (ValueId& a : v.args) a = remap[a];
    ValueId to = replace(out, v);
    remap[id] = to;
    if (const std::string* name = in.nameOf(id)) out.nameValue(to, *name);
    if (const SourceLoc* loc = in.locOf(id)) out.setLoc(to, *loc);
  }
  for (const auto& [name, id] : in.outputs) out.outputs[name] = remap[id];
  return out;
}

}  // namespace

void opt_fold_constants(Material& material) {
  const Module& in = material.surface;
  std::vector<bool> keepAll(in.size(), true);
  material.surface = rebuild(in, keepAll, [](Module& out, const Value& v) -> ValueId {
    if (v.op == Op::Constant || v.op == Op::Param || v.op == Op::Attribute) return out.add(v);
    if (v.op == Op::Select && out.value(v.args[0]).op == Op::Constant)
      return out.value(v.args[0]).constant[0] != 0.0 ? v.args[1] : v.args[2];
    std::vector<Components> args;
    std::vector<Type> types;
    for (ValueId a : v.args) {
      const Value& operand = out.value(a);
      if (operand.op != Op::Constant) return out.add(v);
      args.push_back(operand.constant);
      types.push_back(operand.type);
    }
    auto folded = evaluate(v, args, types);
    return folded ? out.constant(v.type, *folded) : out.add(v);
  });
}

void opt_eliminate_dead_code(Material& material) {
  const Module& in = material.surface;
  std::vector<bool> live(in.size(), false);
  for (const auto& [name, id] : in.outputs) live[id] = true;
  // Users have larger ids than their operands: one backwards sweep finds everything reachable.
  for (ValueId id = ValueId(in.size()); id-- > 0;)
    if (live[id])
      for (ValueId a : in.value(id).args) live[a] = true;

  std::set<std::string> read;
  for (ValueId id = 0; id < in.size(); ++id)
    if (live[id] && in.value(id).op == Op::Param) read.insert(in.value(id).name);
  for (Param& p : material.params) p.used = read.count(p.name) > 0;

  material.surface = rebuild(in, live, [](Module& out, const Value& v) { return out.add(v); });
}

void optimize(Material& material) {
  opt_fold_constants(material);
  opt_eliminate_dead_code(material);
}

}  // namespace facet::ir
