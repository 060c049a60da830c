#include "facet/ir/uniform_values.h"

#include <vector>

namespace facet::ir {
namespace {

// Whether `id` or any value it depends on satisfies `found`.
template <class Predicate>
bool anyDependency(const Module& m, ValueId id, Predicate found) {
  std::vector<ValueId> pending{id};
  std::vector<bool> seen(m.size(), false);
  while (!pending.empty()) {
    const ValueId v = pending.back();
    pending.pop_back();
    if (v >= m.size() || seen[v]) continue;
    seen[v] = true;
    if (found(m.value(v))) return true;
    pending.insert(pending.end(), m.value(v).args.begin(), m.value(v).args.end());
  }
  return false;
}

}  // namespace

bool isUniformOnly(const Material& material, ValueId id) {
  return !anyDependency(material.surface, id, [](const Value& v) {
    return v.op == Op::Attribute || (v.op == Op::Param && v.type == Type::Texture2D);
  });
}

bool readsParameter(const Material& material, ValueId id) {
  return anyDependency(material.surface, id, [](const Value& v) { return v.op == Op::Param; });
}

std::optional<ValueId> outputValue(const Material& material, std::string_view output) {
  auto it = material.surface.outputs.find(std::string(output));
  if (it == material.surface.outputs.end()) return std::nullopt;
  return it->second;
}

}  // namespace facet::ir
