// What tinygltf would hold in memory for a glTF's JSON, estimated before anything is built. Its
// model amplifies small JSON a lot: an empty material `{}` (3 bytes with its comma) becomes a
// 2 KB tinygltf::Material, an empty node 456 bytes, every value under `extras` a 152-byte
// tinygltf::Value; 16 MiB of `{},` in `nodes` took 4.2 GB and 10 s.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace facet::runtime::gltf {

// The most the estimate may reach: far above what a file within GltfBudget's vertex limit needs
// (a few MB of JSON for tens of thousands of nodes and accessors), and as much as the file
// itself may take (GltfBudget::kMaxFileBytes).
inline constexpr uint64_t kMaxModelBytes = uint64_t(256) << 20;

struct ModelCost {
  uint64_t bytes = 0;   // the estimate, or the first sum above kMaxModelBytes
  std::string largest;  // the top-level property that costs most, e.g. "/nodes"
  uint64_t largestBytes = 0;
};

// Walks `text` as JSON events (no document is built), pricing each value as tinygltf stores it:
// its own JSON document (a value, a map node per object member, string bytes), the struct each
// element of the top-level arrays, mesh primitives, animation channels and samplers and
// KHR_lights_punctual lights become, and a tinygltf::Value for everything under `extras`,
// `extensions` and `materials` (whose members tinygltf keeps as parameters). Stops once past
// kMaxModelBytes. Text that is not JSON costs what was read before the error; the caller's
// parser reports the error. The text's nesting must be bounded first (jsonTooDeepAt).
ModelCost estimateModelCost(std::string_view text);

}  // namespace facet::runtime::gltf
