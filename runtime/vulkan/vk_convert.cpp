#include "vk_convert.h"

#include <cmath>
#include <limits>

namespace facet::runtime::vulkan {

namespace {

// Column c of C*M is C applied to column c of M; C scales y by ySign and maps z to [0, w].
void convertClip(const float gl[16], float ySign, float out[16]) {
  for (int c = 0; c < 4; ++c) {
    const float* in = gl + 4 * c;
    float* o = out + 4 * c;
    o[0] = in[0];
    o[1] = ySign * in[1];
    o[2] = 0.5f * in[2] + 0.5f * in[3];
    o[3] = in[3];
  }
}

}  // namespace

void glToVulkanClip(const float gl[16], float out[16]) { convertClip(gl, -1.0f, out); }

void glToVulkanDepthClip(const float gl[16], float out[16]) { convertClip(gl, 1.0f, out); }

float halfToFloat(uint16_t half) {
  const bool negative = (half & 0x8000u) != 0;
  const int exponent = (half >> 10) & 0x1f;
  const int mantissa = half & 0x3ff;
  float value;
  if (exponent == 0) {
    value = std::ldexp(static_cast<float>(mantissa), -24);  // zero or subnormal
  } else if (exponent == 31) {
    value = mantissa ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  } else {
    value = std::ldexp(static_cast<float>(mantissa | 0x400), exponent - 25);
  }
  return negative ? -value : value;
}

namespace {
// An unsigned float of 5 exponent bits (bias 15) and `mantissaBits`, as binary16 without sign.
float smallFloat(uint32_t bits, int mantissaBits) {
  const uint32_t exponent = bits >> mantissaBits, mantissa = bits & ((1u << mantissaBits) - 1);
  if (exponent == 31)
    return mantissa ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  if (exponent == 0) return std::ldexp(float(mantissa), -14 - mantissaBits);
  return std::ldexp(float(mantissa | (1u << mantissaBits)), int(exponent) - 15 - mantissaBits);
}
}  // namespace

void unpackB10G11R11(uint32_t texel, float rgb[3]) {
  rgb[0] = smallFloat(texel & 0x7ffu, 6);
  rgb[1] = smallFloat((texel >> 11) & 0x7ffu, 6);
  rgb[2] = smallFloat(texel >> 22, 5);
}

}  // namespace facet::runtime::vulkan
