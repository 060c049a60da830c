// libFuzzer target for the image decoders the runtime uses on scene images: textures
// (runtime::decodeImageTexture: PNG through stb_image or JPEG through libjpeg-turbo, then the mip
// chain) and environments (runtime::decodeEquirectImage: Radiance .hdr, PNG or JPEG). Any bytes end
// in an image or an error naming it, never a crash, a hang or a sanitizer report. Seeds:
// examples/scenes/textures/ and tests/fuzz/image_corpus/ (small Radiance files, flat and run-length
// coded; baseline, progressive and greyscale JPEGs). libjpeg-turbo is Debian's shared library,
// not instrumented: coverage guides the fuzzer through Facet's side only, and ASan sees libjpeg's
// writes into the buffers Facet hands it, not its reads of its own.
// Inputs declaring more than 1024 × 1024 pixels are skipped here only to keep each run fast; the
// runtime's own limit is kMaxImageSide (8192).
//
// Reproduce a finding:  build/fuzz/tests/fuzz/fuzz_image path/to/input
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "facet/runtime/image_texture.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  int w = 0, h = 0;
  std::string error;
  if (facet::runtime::probeImage({data, size}, "fuzz", &w, &h, &error) && (w > 1024 || h > 1024)) return 0;
  for (bool srgb : {false, true}) {
    auto texture = facet::runtime::decodeImageTexture({data, size}, srgb, "fuzz.png", &error);
    if (!texture && error.rfind("fuzz.png: ", 0) != 0) {
      std::fprintf(stderr, "fuzz_image: rejected without naming the image: %s\n", error.c_str());
      std::abort();
    }
    if (texture &&
        (texture->levels.empty() || texture->levels[0].size() != size_t(texture->width) * texture->height * 4)) {
      std::fprintf(stderr, "fuzz_image: level 0 does not match %ux%u\n", texture->width, texture->height);
      std::abort();
    }
  }
  auto environment = facet::runtime::decodeEquirectImage({data, size}, "fuzz.hdr", &error);
  if (!environment && error.rfind("fuzz.hdr: ", 0) != 0) {
    std::fprintf(stderr, "fuzz_image: environment rejected without naming the image: %s\n", error.c_str());
    std::abort();
  }
  if (environment && environment->rgb.size() != size_t(environment->width) * size_t(environment->height) * 3) {
    std::fprintf(stderr, "fuzz_image: environment holds %zu floats for %dx%d\n", environment->rgb.size(),
                 environment->width, environment->height);
    std::abort();
  }
  return 0;
}
