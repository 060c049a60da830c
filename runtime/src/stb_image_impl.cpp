// stb_image's implementation, in a file of its own so that sanitizer builds can treat it as the
// third-party code it is: it passes a null pointer to memcpy for zero-length PNG chunks
// (stbi__getn with an IDAT of length 0; found by fuzz_image), harmless but reported by UBSan's
// nonnull-attribute check, which runtime/CMakeLists.txt turns off for this file only.
//
// Formats: PNG for textures and 8-bit environments, Radiance .hdr for environments. JPEG and TGA
// are left out: fuzz_image found this stb_image's JPEG Huffman-table builder reading past its
// array (stb_image.h:1990, input in tests/fuzz/image_regressions/), and a texture format whose
// decoder reads out of bounds on hostile input is not one the runtime can offer. JPEG is read by
// libjpeg-turbo instead (jpeg.cpp).
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_HDR  // environments (environment.cpp): Radiance .hdr via stbi_loadf
#include <stb_image.h>
