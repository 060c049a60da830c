// ibl/hammersley.h
// The 2D Hammersley point set: the low-discrepancy sequence every IBL integral here samples with.
// Deterministic (no random device), so tables are byte-identical between runs, and its error
// falls close to 1/N instead of the 1/√N of random points.
#pragma once

#include <cstdint>

namespace facet::ibl {

/// Van der Corput radical inverse in base 2: the bits of i mirrored behind the binary point.
inline double radicalInverse2(uint32_t i) {
  i = (i << 16u) | (i >> 16u);
  i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
  i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
  i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
  i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
  return double(i) * 0x1p-32;
}

struct Point2 {
  double u = 0, v = 0;
};

/// Point i of an n-point set. u = (i + 0.5)/n rather than i/n: no point sits on u = 0, where the
/// GGX inversions below put a sample exactly at the pole, and the set is symmetric about 1/2.
inline Point2 hammersley(uint32_t i, uint32_t n) { return {(double(i) + 0.5) / double(n), radicalInverse2(i)}; }

}  // namespace facet::ibl
