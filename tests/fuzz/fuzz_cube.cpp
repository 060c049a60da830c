// libFuzzer target for the colour-grading .cube reader (runtime::parseCubeLut): any bytes end in
// a table the GPU can hold or in an error at a line of the file, never a crash, a hang or an
// exception. Seeded with examples/scenes/looks/ and tests/fuzz/cube_corpus/. Built by
// scripts/fuzz.sh with ASan + UBSan.
//
// Reproduce a finding:  build/fuzz/tests/fuzz/fuzz_cube path/to/input
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "facet/runtime/color_grading.h"

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_cube: %s: %.200s\n", what, detail.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace facet::runtime;
  std::string error;
  const auto lut = parseCubeLut("fuzz.cube", std::string_view(reinterpret_cast<const char*>(data), size), &error);
  if (!lut) {
    // "fuzz.cube:<line>: error: ...", short whatever the input.
    const size_t colon = error.find(": error: ");
    if (error.rfind("fuzz.cube:", 0) != 0 || colon == std::string::npos || error.size() > 512)
      broken("malformed error message", error);
    return 0;
  }
  // What the runtime uploads: a table of size^3 finite entries within the half-float range,
  // over a domain that is not empty in any channel.
  if (lut->size < 2 || lut->size > kMaxCubeLutSize) broken("size outside 2..64", std::to_string(lut->size));
  if (lut->rgb.size() != size_t(lut->size) * lut->size * lut->size * 3)
    broken("entry count", std::to_string(lut->rgb.size()));
  for (float v : lut->rgb)
    if (!std::isfinite(v) || std::abs(v) > 65504.0f) broken("entry outside the half-float range", std::to_string(v));
  for (int c = 0; c < 3; ++c)
    if (!(lut->domainMin[c] < lut->domainMax[c])) broken("empty domain", std::to_string(c));
  return 0;
}
