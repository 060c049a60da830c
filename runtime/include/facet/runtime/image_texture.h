// Textures from image files, and the 1×1 textures that stand in for images a scene does not give.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "facet/ibl/equirect_image.h"
#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// Images larger than this on either side are refused rather than decoded.
inline constexpr int kMaxImageSide = 8192;

// Reads the size of an image held in memory without decoding it (`name` is used in messages);
// false, with *error naming it, when stb_image (PNG, Radiance) or libjpeg-turbo (JPEG, a CMYK one
// refused) cannot read its header, it is larger than kMaxImageSide
// on a side, or its container is unsafe or incomplete: a PNG chunk declaring more bytes than the
// file holds (stb_image would allocate what it declares), a Radiance .hdr whose pixel block is
// cut short (stb_image would decode the missing pixels as black). Every decoder calls it first.
bool probeImage(std::span<const uint8_t> bytes, const std::string& name, int* width, int* height, std::string* error);

// stb_image's reason for its last failure, or "corrupt or truncated data" when it gives none.
std::string decodeFailure();

// Image files larger than this are refused before they are read.
inline constexpr uintmax_t kMaxImageFileBytes = 256u << 20;

// Reads a whole image file: a regular file (a FIFO or a device would block), at most
// kMaxImageFileBytes. False with *error naming the file otherwise.
bool readImageFile(const std::string& path, std::vector<uint8_t>* bytes, std::string* error);

// Decodes a PNG or JPEG held in memory (loadImageTexture without the file); `name` is used in
// messages. The fuzz target fuzz_image drives it with arbitrary bytes.
std::optional<Texture> decodeImageTexture(std::span<const uint8_t> bytes, bool srgb, const std::string& name,
                                          std::string* error);

// Loads a PNG (stb_image) or JPEG (libjpeg-turbo, runtime/src/jpeg.cpp; TGA is not decoded:
// stb_image_impl.cpp) as RGBA8, with every mip level down to 1×1.
// `srgb` tags the image as sRGB-encoded (colour data): levels are then averaged in linear light, not in the encoded
// values (which would darken every level), and the sampler decodes.
std::optional<Texture> loadImageTexture(const std::string& path, bool srgb, std::string* error);

// An equirect environment image held in memory (`name` is used in messages), as linear RGB: a
// Radiance .hdr as stored, a PNG or JPEG decoded from sRGB. Checked by probeImage first; 2:1, finite and
// non-negative. The fuzz target fuzz_image drives it with arbitrary bytes.
std::optional<ibl::EquirectImage> decodeEquirectImage(std::span<const uint8_t> bytes, const std::string& name,
                                                      std::string* error);

// A 1×1 texture of one RGBA value (components in [0, 1], as encoded).
Texture solidTexture(const std::array<double, 4>& rgba, bool srgb);

}  // namespace facet::runtime
