// The 64-bit content hash the backends' caches compare to notice data edited in place, or new
// data allocated at a freed object's address (textures, meshes).
#pragma once

#include <cstddef>
#include <cstdint>

namespace facet::runtime {

inline constexpr uint64_t kContentHashSeed = 0xCBF29CE484222325ull;

// Word-at-a-time multiply-xor hash of `size` bytes, the size mixed in first, continuing from
// `hash` (chain calls to hash several ranges). Not cryptographic: it detects edits, it does not
// resist adversaries.
uint64_t hashBytes(const void* data, size_t size, uint64_t hash = kContentHashSeed);

}  // namespace facet::runtime
