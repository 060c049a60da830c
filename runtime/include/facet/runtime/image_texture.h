// Textures from image files, and the 1×1 textures that stand in for images a scene does not give.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>

#include "facet/render_backend.h"

namespace facet::runtime {

// Images larger than this on either side are refused rather than decoded.
inline constexpr int kMaxImageSide = 8192;

// Reads an image file's size without decoding it; false, with *error naming the file, when it is
// not an image stb_image reads or is larger than kMaxImageSide on a side. Every loader calls it
// first, so a hostile header cannot make it decode (and allocate) a huge image, and only regular
// files are opened (a FIFO or a device would block the read forever).
bool probeImageSize(const std::string& path, int* width, int* height, std::string* error);

// stb_image's reason for its last failure, or "corrupt or truncated data" when it gives none.
std::string decodeFailure();

// Image files larger than this are refused before they are read.
inline constexpr uintmax_t kMaxImageFileBytes = 256u << 20;

// Reads a whole image file: a regular file (a FIFO or a device would block), at most
// kMaxImageFileBytes. False with *error naming the file otherwise.
bool readImageFile(const std::string& path, std::vector<uint8_t>* bytes, std::string* error);

// Decodes a PNG held in memory (loadImageTexture without the file); `name` is used in
// messages. The fuzz target fuzz_image drives it with arbitrary bytes.
std::optional<Texture> decodeImageTexture(std::span<const uint8_t> bytes, bool srgb, const std::string& name,
                                          std::string* error);

// Loads a PNG (stb_image; JPEG and TGA are not decoded: stb_image_impl.cpp) as RGBA8, with every mip level down to 1×1. `srgb` tags the
// image as sRGB-encoded (colour data): levels are then averaged in linear light, not in the
// encoded values (which would darken every level), and the sampler decodes.
std::optional<Texture> loadImageTexture(const std::string& path, bool srgb, std::string* error);

// A 1×1 texture of one RGBA value (components in [0, 1], as encoded).
Texture solidTexture(const std::array<double, 4>& rgba, bool srgb);

}  // namespace facet::runtime
