// JPEG images through libjpeg-turbo (Debian's libjpeg62-turbo), for textures and environments.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace facet::runtime {

// True when the bytes start with a JPEG start-of-image marker followed by another marker.
bool isJpeg(std::span<const uint8_t> bytes);

// Reads a JPEG's size from its frame header without decoding any pixels. False with *why (no
// file name) when the header cannot be read or the image is not one decodeJpeg accepts.
bool probeJpeg(std::span<const uint8_t> bytes, int* width, int* height, std::string* why);

// Decodes a JPEG to 8-bit RGBA (alpha 255), the top row first. Refuses, with *why: CMYK and YCCK
// images, progressive files of more scans than any encoder writes, and any data libjpeg only warns
// about (a truncated or corrupt entropy-coded segment it would fill with grey). The caller checks
// the size (probeJpeg) before calling.
bool decodeJpeg(std::span<const uint8_t> bytes, std::vector<uint8_t>* rgba, int* width, int* height, std::string* why);

}  // namespace facet::runtime
