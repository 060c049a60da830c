// One glTF accessor's elements as numbers, every byte it names bounds-checked against its buffer
// first (the file is untrusted). Sparse accessors are applied (glTF 2.0 §3.6.2.3): the base values
// (from the buffer view, or zeros without one) with the listed elements substituted.
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace facet::runtime::gltf {

class AccessorReader {
 public:
  // `types`/`components`: the accessor types and component types this use accepts. Non-index
  // uses (`integers` false) also need normalized set exactly on the integer component types.
  // Errors start with `field`, e.g. "/meshes/0/primitives/0/attributes/NORMAL: ...".
  static std::optional<AccessorReader> open(const tinygltf::Model& model, int index, std::initializer_list<int> types,
                                            std::initializer_list<int> components, bool integers,
                                            const std::string& field, std::string* error);

  size_t count() const { return count_; }
  int components() const { return components_; }

  // Component c of element e: floats as stored, unsigned integers normalised to [0, 1] (or, for
  // indices, as integers when normalise is false).
  double get(size_t e, int c, bool normalise = true) const;

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
  size_t componentSize_ = 0;
};

}  // namespace facet::runtime::gltf
