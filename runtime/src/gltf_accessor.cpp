#include "gltf_accessor.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace facet::runtime::gltf {
namespace {

// An accessor without a buffer view is zeros (plus its sparse values): no data bounds its count,
// so it is bounded here. 1 M elements = 72 MB of runtime vertices (18 floats each).
constexpr size_t kMaxElementsWithoutBufferView = size_t(1) << 20;

// Where `count` elements of `elementSize` bytes, `stride` apart from `offset` in buffer view
// `viewIndex`, lie in memory; null and *error when any of them falls outside the view or its
// buffer. Sizes come from the file: every sum and product is checked for wrapping.
const unsigned char* locate(const tinygltf::Model& model, int viewIndex, size_t offset, size_t stride,
                            size_t elementSize, size_t count, const std::string& what, std::string* error) {
  if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size()) {
    *error = what + ": buffer view " + std::to_string(viewIndex) + " does not exist";
    return nullptr;
  }
  const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) {
    *error = what + ": buffer view " + std::to_string(viewIndex) + " names no buffer";
    return nullptr;
  }
  const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
  size_t viewEnd = 0, start = 0, last = 0, end = 0;
  const bool wraps = __builtin_add_overflow(view.byteOffset, view.byteLength, &viewEnd) ||
                     __builtin_add_overflow(view.byteOffset, offset, &start) ||
                     (count > 0 && __builtin_mul_overflow(stride, count - 1, &last)) ||
                     __builtin_add_overflow(start, last, &end) || __builtin_add_overflow(end, elementSize, &end);
  if (wraps || viewEnd > data.size() || (count > 0 && end > viewEnd) || start > viewEnd) {
    *error = what + " reaches past its buffer view or buffer";
    return nullptr;
  }
  return data.data() + start;
}

}  // namespace

std::optional<AccessorReader> AccessorReader::open(const tinygltf::Model& model, int index,
                                                   std::initializer_list<int> types,
                                                   std::span<const ComponentRule> components, const std::string& field,
                                                   std::string* error) {
  if (index < 0 || size_t(index) >= model.accessors.size()) {
    *error = field + ": accessor " + std::to_string(index) + " does not exist";
    return std::nullopt;
  }
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  const std::string name = field + ": accessor " + std::to_string(index);
  const bool accepted = std::any_of(components.begin(), components.end(), [&](const ComponentRule& r) {
    return r.componentType == a.componentType && r.normalized == a.normalized;
  });
  if (std::find(types.begin(), types.end(), a.type) == types.end() || !accepted) {
    *error = name + " has a type or component type this attribute cannot have";
    return std::nullopt;
  }
  AccessorReader r;
  r.count_ = a.count;
  r.components_ = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  r.componentType_ = a.componentType;
  r.normalized_ = a.normalized;
  r.componentSize_ = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
  const size_t elementSize = r.componentSize_ * size_t(r.components_);

  if (a.bufferView >= 0) {
    if (size_t(a.bufferView) >= model.bufferViews.size()) {
      *error = name + ": buffer view " + std::to_string(a.bufferView) + " does not exist";
      return std::nullopt;
    }
    const int stride = a.ByteStride(model.bufferViews[size_t(a.bufferView)]);
    if (stride <= 0 || size_t(stride) < elementSize) {
      *error = name + " has a byte stride smaller than its elements";
      return std::nullopt;
    }
    r.dense_.stride = size_t(stride);
    r.dense_.base = locate(model, a.bufferView, a.byteOffset, r.dense_.stride, elementSize, a.count, name, error);
    if (!r.dense_.base) return std::nullopt;
  } else if (!a.sparse.isSparse) {
    *error = name + " has no buffer view and is not sparse (all zeros)";
    return std::nullopt;
  } else if (a.count > kMaxElementsWithoutBufferView) {
    *error = name + ": " + std::to_string(a.count) + " elements without a buffer view (at most " +
             std::to_string(kMaxElementsWithoutBufferView) + ")";
    return std::nullopt;
  }

  if (a.sparse.isSparse) {
    const std::string sparse = name + " sparse";
    const int indexType = a.sparse.indices.componentType;
    if (a.sparse.count < 1 || size_t(a.sparse.count) > a.count) {
      *error = sparse + " count " + std::to_string(a.sparse.count) + " is outside 1.." + std::to_string(a.count);
      return std::nullopt;
    }
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      *error = sparse + " indices: component type " + std::to_string(indexType) + " is not an unsigned integer";
      return std::nullopt;
    }
    if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0) {
      *error = sparse + ": negative byteOffset";
      return std::nullopt;
    }
    const auto n = size_t(a.sparse.count);
    const size_t indexSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(indexType)));
    // Sparse buffer views are tightly packed (they may not declare a byteStride).
    const unsigned char* indices = locate(model, a.sparse.indices.bufferView, size_t(a.sparse.indices.byteOffset),
                                          indexSize, indexSize, n, sparse + " indices", error);
    if (!indices) return std::nullopt;
    r.sparseValues_.stride = elementSize;
    r.sparseValues_.base = locate(model, a.sparse.values.bufferView, size_t(a.sparse.values.byteOffset), elementSize,
                                  elementSize, n, sparse + " values", error);
    if (!r.sparseValues_.base) return std::nullopt;
    r.sparseIndices_.reserve(n);
    for (size_t i = 0; i < n; ++i) {
      uint32_t at = 0;
      const unsigned char* p = indices + i * indexSize;
      if (indexSize == 1) at = p[0];
      if (indexSize == 2) {
        uint16_t v;
        std::memcpy(&v, p, 2);
        at = v;
      }
      if (indexSize == 4) std::memcpy(&at, p, 4);
      if (at >= a.count || (!r.sparseIndices_.empty() && at <= r.sparseIndices_.back())) {
        *error = sparse + " index " + std::to_string(at) + " (entry " + std::to_string(i) +
                 ") is past the elements or not after the one before";
        return std::nullopt;
      }
      r.sparseIndices_.push_back(at);
    }
  }
  return r;
}

double AccessorReader::raw(const unsigned char* element, int c) const {
  const unsigned char* p = element + size_t(c) * componentSize_;
  switch (componentType_) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
    case TINYGLTF_COMPONENT_TYPE_BYTE: return int8_t(p[0]);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    default: {  // UNSIGNED_INT, indices only
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

double AccessorReader::get(size_t e, int c) const {
  double value = 0;
  const auto sparse = std::lower_bound(sparseIndices_.begin(), sparseIndices_.end(), e);
  if (sparse != sparseIndices_.end() && *sparse == e) {
    value = raw(sparseValues_.base + size_t(sparse - sparseIndices_.begin()) * sparseValues_.stride, c);
  } else if (dense_.base) {
    value = raw(dense_.base + e * dense_.stride, c);
  }
  if (!normalized_) return value;
  switch (componentType_) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return value / 255.0;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return value / 65535.0;
    case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(value / 127.0, -1.0);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return std::max(value / 32767.0, -1.0);
    default: return value;
  }
}

}  // namespace facet::runtime::gltf
