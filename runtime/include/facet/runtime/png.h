#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::runtime {

// RGBA8 pixels (rows top to bottom) as PNG file bytes; false with *error when the buffer does
// not match the size.
bool encodePng(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba, std::vector<uint8_t>* png,
               std::string* error);

// Writes RGBA8 pixels (rows top to bottom) as PNG, atomically (temporary file + rename).
bool writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba,
              std::string* error);

}  // namespace facet::runtime
