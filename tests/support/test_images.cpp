#include "test_images.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "facet/eval/metrics.h"

namespace facet::test {

double psnr(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  EXPECT_EQ(a.size(), b.size());
  return std::min(eval::psnr8(a, b), 99.0);
}

}  // namespace facet::test
