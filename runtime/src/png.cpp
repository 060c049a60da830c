#include "facet/runtime/png.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include "facet/package/package.h"

namespace facet::runtime {

bool encodePng(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba, std::vector<uint8_t>* png,
               std::string* error) {
  if (rgba.size() != size_t(width) * height * 4 || width == 0 || height == 0) {
    *error = "PNG: pixel buffer does not match " + std::to_string(width) + "x" + std::to_string(height);
    return false;
  }
  png->clear();
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
  };
  if (!stbi_write_png_to_func(append, png, int(width), int(height), 4, rgba.data(), int(width * 4))) {
    *error = "cannot encode a " + std::to_string(width) + "x" + std::to_string(height) + " image as PNG";
    return false;
  }
  return true;
}

bool writePng(const std::string& path, uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba,
              std::string* error) {
  // Encoded in memory, then written like every other output (package::writeFile: atomically,
  // only over a regular file).
  std::vector<uint8_t> png;
  if (!encodePng(width, height, rgba, &png, error)) {
    *error = "cannot write '" + path + "': " + *error;
    return false;
  }
  return package::writeFile(path, png, error);
}

}  // namespace facet::runtime
