#include "facet/ir/uniform_values.h"

#include <vector>

namespace facet::ir {

bool isUniformOnly(const Material& material, ValueId id) {
  const Module& m = material.surface;
  // Operands precede their users (SSA, module.h), so one walk over the reachable values suffices.
  std::vector<ValueId> pending{id};
  std::vector<bool> seen(m.size(), false);
  while (!pending.empty()) {
    const ValueId v = pending.back();
    pending.pop_back();
    if (v >= m.size() || seen[v]) continue;
    seen[v] = true;
    const Value& value = m.value(v);
    if (value.op == Op::Attribute) return false;
    if (value.op == Op::Param && value.type == Type::Texture2D) return false;
    pending.insert(pending.end(), value.args.begin(), value.args.end());
  }
  return true;
}

bool readsParameter(const Material& material, ValueId id) {
  const Module& m = material.surface;
  std::vector<ValueId> pending{id};
  std::vector<bool> seen(m.size(), false);
  while (!pending.empty()) {
    const ValueId v = pending.back();
    pending.pop_back();
    if (v >= m.size() || seen[v]) continue;
    seen[v] = true;
    if (m.value(v).op == Op::Param) return true;
    pending.insert(pending.end(), m.value(v).args.begin(), m.value(v).args.end());
  }
  return false;
}

std::optional<ValueId> outputValue(const Material& material, std::string_view output) {
  auto it = material.surface.outputs.find(std::string(output));
  if (it == material.surface.outputs.end()) return std::nullopt;
  return it->second;
}

}  // namespace facet::ir
