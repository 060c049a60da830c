// libFuzzer target for the scene loader (runtime::parseScene, and the shadow reference's
// shadow_reference::parseShadowScene around it): any bytes, read as a scene file, end in a Scene
// or an error message, never a crash, a hang or an exception (docs/security.md).
// Seeded with examples/scenes/. Built by scripts/fuzz.sh with ASan + UBSan.
//
// Reproduce a finding:  build/fuzz/tests/fuzz/fuzz_scene path/to/input
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "facet/scene/scene.h"
#include "facet/shadow_reference/shadow_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string error;
  auto scene = facet::runtime::parseScene("fuzz.json", std::string(reinterpret_cast<const char*>(data), size), &error);
  // A rejection always says why, names the file and stays short (no echo of a huge input).
  if (!scene && (error.rfind("fuzz.json", 0) != 0 || error.size() > 4096)) {
    std::fprintf(stderr, "fuzz_scene: malformed error message (%zu bytes): %.200s\n", error.size(), error.c_str());
    std::abort();
  }
  auto shadowScene = facet::shadow_reference::parseShadowScene(
      "fuzz.json", std::string(reinterpret_cast<const char*>(data), size), &error);
  if (!shadowScene && (error.rfind("fuzz.json", 0) != 0 || error.size() > 4096)) {
    std::fprintf(stderr, "fuzz_scene: malformed shadow-scene error (%zu bytes): %.200s\n", error.size(), error.c_str());
    std::abort();
  }
  return 0;
}
