// Pure data conversions between the API-neutral frame description and what Vulkan consumes or
// produces. No Vulkan calls here, so the arithmetic is easy to check on its own.
#pragma once

#include <cstdint>

namespace facet::runtime::vulkan {

// clip' = C * m, where C flips y (Vulkan's framebuffer y points down) and maps z from
// OpenGL's [-w, w] to Vulkan's [0, w]: z' = 0.5 z + 0.5 w. Column-major 4×4, like shader_abi.h.
// With this, Vulkan's row 0 is the top of the picture, the same picture a GL render shows
// after its rows are flipped on readback.
void glToVulkanClip(const float gl[16], float out[16]);
// The shadow pass's form: z to [0, w] only, y kept, so atlas row r is GL's window y = r
// (runtime/sun_shadow.h) and the receivers' atlas coordinates hold in both APIs.
void glToVulkanDepthClip(const float gl[16], float out[16]);

// IEEE 754 binary16 → binary32, exact (normals, subnormals, infinities, NaN).
float halfToFloat(uint16_t half);

// One VK_FORMAT_B10G11R11_UFLOAT_PACK32 texel → RGB: red bits 0..10 and green 11..21 (5-bit
// exponent, 6-bit mantissa), blue 22..31 (5-bit exponent, 5-bit mantissa), unsigned, bias 15.
void unpackB10G11R11(uint32_t texel, float rgb[3]);

}  // namespace facet::runtime::vulkan
