#include "vk_convert.h"

#include <cmath>
#include <limits>

namespace facet::runtime::vulkan {

void glToVulkanClip(const float gl[16], float out[16]) {
  // Column c of C*M is C applied to column c of M.
  for (int c = 0; c < 4; ++c) {
    const float* in = gl + 4 * c;
    float* o = out + 4 * c;
    o[0] = in[0];
    o[1] = -in[1];
    o[2] = 0.5f * in[2] + 0.5f * in[3];
    o[3] = in[3];
  }
}

float halfToFloat(uint16_t half) {
  const bool negative = (half & 0x8000u) != 0;
  const int exponent = (half >> 10) & 0x1f;
  const int mantissa = half & 0x3ff;
  float value;
  if (exponent == 0) {
    value = std::ldexp(static_cast<float>(mantissa), -24);  // zero or subnormal
  } else if (exponent == 31) {
    value =
        mantissa ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  } else {
    value = std::ldexp(static_cast<float>(mantissa | 0x400), exponent - 25);
  }
  return negative ? -value : value;
}

}  // namespace facet::runtime::vulkan
