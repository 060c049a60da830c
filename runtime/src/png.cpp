#include "facet/runtime/png.h"

#include <cstdio>
#include <filesystem>
#include <unistd.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

namespace facet::runtime {

bool writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba,
              std::string* error) {
  if (rgba.size() != size_t(width) * height * 4 || width == 0 || height == 0) {
    *error = "writePng: pixel buffer does not match " + std::to_string(width) + "x" + std::to_string(height);
    return false;
  }
  std::string tmp = path + ".tmp." + std::to_string(getpid());
  if (!stbi_write_png(tmp.c_str(), int(width), int(height), 4, rgba.data(), int(width * 4))) {
    std::remove(tmp.c_str());
    *error = "cannot write '" + path + "'";
    return false;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    *error = "cannot write '" + path + "': " + ec.message();
    return false;
  }
  return true;
}

}  // namespace facet::runtime
