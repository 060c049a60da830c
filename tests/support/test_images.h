// Image error for tests that compare rendered frames (links eval's metrics only).
#pragma once

#include <cstdint>
#include <vector>

namespace facet::test {

// 8-bit PSNR between two RGBA8 images of the same size, over RGB (99 dB when identical):
// facet::eval::psnr8, capped.
double psnr(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b);

}  // namespace facet::test
