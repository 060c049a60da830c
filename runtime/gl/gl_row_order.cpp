#include "gl_row_order.h"

namespace facet::runtime::gl {

// Row 1 of a column-major matrix is element 1 of each column.
void topDownClip(const float gl[16], float out[16]) {
  for (int i = 0; i < 16; ++i) out[i] = i % 4 == 1 ? -gl[i] : gl[i];
}

// Column 1 (the y column) is elements 4..7.
void topDownBackground(abi::BackgroundParams* params) {
  for (int row = 0; row < 4; ++row) params->clipToDirection[4 + row] = -params->clipToDirection[4 + row];
}

}  // namespace facet::runtime::gl
