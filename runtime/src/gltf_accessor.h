// One glTF accessor's elements as numbers, every byte it names bounds-checked against its buffer
// first (the file is untrusted). Sparse accessors are applied (glTF 2.0 §3.6.2.3): the base values
// (from the buffer view, or zeros without one) with the listed elements substituted.
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace facet::runtime::gltf {

// A component type a use accepts, and whether the accessor must say normalized (glTF 2.0
// §3.7.2.1's table; KHR_mesh_quantization's for the integer attributes it adds).
struct ComponentRule {
  int componentType;
  bool normalized;
};

class AccessorReader {
 public:
  // `types`/`components`: the accessor types and (component type, normalized) pairs this use
  // accepts. Errors start with `field`, e.g. "/meshes/0/primitives/0/attributes/NORMAL: ...".
  static std::optional<AccessorReader> open(const tinygltf::Model& model, int index, std::initializer_list<int> types,
                                            std::span<const ComponentRule> components, const std::string& field,
                                            std::string* error);

  size_t count() const { return count_; }
  int components() const { return components_; }

  // Component c of element e: floats as stored; normalized integers as glTF 2.0 §3.11 maps them
  // (unsigned c / (2^b − 1), signed max(c / (2^(b−1) − 1), −1)); other integers as they are.
  double get(size_t e, int c) const;

 private:
  // Elements laid out in a buffer: `base` null means zeros.
  struct Strided {
    const unsigned char* base = nullptr;
    size_t stride = 0;
  };
  double raw(const unsigned char* element, int c) const;

  Strided dense_;
  // Sparse substitutions, by strictly increasing element index (so found by binary search).
  std::vector<size_t> sparseIndices_;
  Strided sparseValues_;
  size_t count_ = 0;
  int components_ = 0;
  int componentType_ = 0;
  bool normalized_ = false;
  size_t componentSize_ = 0;
};

}  // namespace facet::runtime::gltf
