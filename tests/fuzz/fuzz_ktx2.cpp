// libFuzzer target for the KTX2 reader the runtime uses on scene textures
// (runtime::decodeKtx2Texture: texture::readKtx2's checks, the format mapping) and the ASTC
// decoding a backend falls back to where the device cannot sample ASTC
// (runtime::decodeCompressedTexture: astcenc on whatever blocks the file holds). Any bytes end in
// a texture whose levels match its size, or an error naming the file; never a crash, a hang or a
// sanitizer report. Seeds: tests/fuzz/ktx2_corpus/ (files `matc texture` wrote); past findings:
// tests/fuzz/ktx2_regressions/ (replayed by tests/texture/test_ktx2.cpp).
// Files declaring more than 512 x 512 texels are only read, not decoded, to keep each run fast;
// the runtime's own limit is kMaxKtx2Side (8192).
//
// Reproduce a finding:  build/fuzz/tests/fuzz/fuzz_ktx2 path/to/input
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "facet/runtime/compressed_texture.h"
#include "facet/runtime/texture_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string error;
  for (bool srgb : {false, true}) {
    auto texture = facet::runtime::decodeKtx2Texture({data, size}, srgb, "fuzz.ktx2", &error);
    if (!texture) {
      if (error.rfind("fuzz.ktx2: ", 0) != 0) {
        std::fprintf(stderr, "fuzz_ktx2: rejected without naming the file: %s\n", error.c_str());
        std::abort();
      }
      continue;
    }
    for (size_t i = 0; i < texture->levels.size(); ++i) {
      const uint64_t expected = facet::runtime::textureLevelBytes(
          texture->format, facet::runtime::mipExtent(texture->width, i), facet::runtime::mipExtent(texture->height, i));
      if (texture->levels[i].size() != expected) {
        std::fprintf(stderr, "fuzz_ktx2: level %zu holds %zu bytes, not %llu\n", i, texture->levels[i].size(),
                     static_cast<unsigned long long>(expected));
        std::abort();
      }
    }
    if (texture->width > 512 || texture->height > 512) continue;
    auto rgba = facet::runtime::decodeCompressedTexture(*texture, &error);
    if (!rgba || rgba->levels[0].size() != size_t(texture->width) * texture->height * 4) {
      std::fprintf(stderr, "fuzz_ktx2: a texture that read does not decode: %s\n", rgba ? "wrong size" : error.c_str());
      std::abort();
    }
  }
  return 0;
}
