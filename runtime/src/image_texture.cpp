#include "facet/runtime/image_texture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <stb_image.h>  // implementation: stb_image_impl.cpp

#include "jpeg.h"

namespace facet::runtime {
namespace {

double decode(uint8_t v) {
  double c = v / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

uint8_t encode(double linear) {
  double c = linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
  return uint8_t(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}

// The next mip level: each texel averages the 2×2 (or 2×1 / 1×2 at odd edges) it covers.
// Colour channels of sRGB images are averaged in linear light; alpha is always linear.
std::vector<uint8_t> halve(const std::vector<uint8_t>& src, uint32_t w, uint32_t h, bool srgb) {
  uint32_t nw = std::max(1u, w / 2), nh = std::max(1u, h / 2);
  std::vector<uint8_t> dst(size_t(nw) * nh * 4);
  for (uint32_t y = 0; y < nh; ++y) {
    for (uint32_t x = 0; x < nw; ++x) {
      for (int c = 0; c < 4; ++c) {
        double sum = 0;
        int n = 0;
        for (uint32_t dy = 0; dy < 2; ++dy) {
          for (uint32_t dx = 0; dx < 2; ++dx) {
            uint32_t sx = std::min(w - 1, x * 2 + dx), sy = std::min(h - 1, y * 2 + dy);
            uint8_t v = src[(size_t(sy) * w + sx) * 4 + size_t(c)];
            sum += (srgb && c < 3) ? decode(v) : v / 255.0;
            ++n;
          }
        }
        double mean = sum / n;
        dst[(size_t(y) * nw + x) * 4 + size_t(c)] =
            (srgb && c < 3) ? encode(mean) : uint8_t(std::lround(std::clamp(mean, 0.0, 1.0) * 255.0));
      }
    }
  }
  return dst;
}

// stb_image grows its PNG data buffer to whatever length a chunk header declares before it
// checks the bytes are there: a 200-byte file declaring a 2 GB IDAT made it allocate 2 GB
// (fuzz_image). Every chunk must fit in the file: then the buffer is bounded by the file size.
bool isPng(std::span<const uint8_t> bytes) {
  static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return bytes.size() >= 8 && std::equal(kSignature, kSignature + 8, bytes.begin());
}

std::string pngChunkError(std::span<const uint8_t> bytes) {
  if (!isPng(bytes)) return "";
  size_t at = 8;
  while (at + 8 <= bytes.size()) {
    const uint64_t length =
        uint64_t(bytes[at]) << 24 | uint64_t(bytes[at + 1]) << 16 | uint64_t(bytes[at + 2]) << 8 | bytes[at + 3];
    const std::string type(reinterpret_cast<const char*>(bytes.data() + at + 4), 4);
    if (length + 12 > bytes.size() - at)
      return "PNG chunk at byte " + std::to_string(at) + " declares " + std::to_string(length) + " bytes; " +
             std::to_string(bytes.size() - at) + " remain in the file";
    at += size_t(length) + 12;
    if (type == "IEND") return "";
  }
  return "";  // stb_image reports a missing IEND or a cut chunk header itself
}

// stb_image decodes a Radiance .hdr whose pixel block is cut short as if the missing bytes were
// zeros (its reader returns 0 at the end of the input): the environment comes out partly black,
// with no error. This walks the pixel block as stb_image does (Ward's RGBE: flat 4-byte pixels,
// or per-scanline run-length coding when 8 <= width < 32768) and says where it ends early.
std::string radianceHdrError(std::span<const uint8_t> bytes) {
  size_t at = 0;
  bool oddLine = false;  // a NUL byte, or longer than stb_image's 1023-character token
  auto line = [&] {
    std::string text;
    while (at < bytes.size() && bytes[at] != '\n') {
      oddLine = oddLine || bytes[at] == 0 || text.size() == 1023;
      text += char(bytes[at++]);
    }
    if (at < bytes.size()) ++at;
    return text;
  };
  const std::string id = line();
  if (id != "#?RADIANCE" && id != "#?RGBE") return "";  // not a Radiance file
  // stb_image will decode this file, so its header must be one this walk reads exactly as
  // stb_image does (it compares lines as C strings, cut at 1023 characters): a header it read
  // otherwise could take it into its run-length loop past the data, where it spins forever
  // (found by fuzz_image). Anything else is refused, not left to stb_image.
  bool rgbe = false;
  for (std::string text = line(); !text.empty(); text = line()) rgbe = rgbe || text == "FORMAT=32-bit_rle_rgbe";
  const std::string resolution = line();
  long height = 0, width = 0;
  if (oddLine) return "Radiance header: a line holds a NUL byte or is longer than 1023 characters";
  if (!rgbe) return "Radiance header: no FORMAT=32-bit_rle_rgbe line (the only pixel format read)";
  if (std::sscanf(resolution.c_str(), "-Y %ld +X %ld", &height, &width) != 2 || width <= 0 || height <= 0)
    return "Radiance header: the resolution line is not \"-Y <height> +X <width>\" with sizes above 0";
  const uint64_t pixels = uint64_t(width) * uint64_t(height);
  auto cut = [&](const std::string& where) {
    return "Radiance pixel data ends at byte " + std::to_string(bytes.size()) + ", " + where + " of a " +
           std::to_string(width) + "x" + std::to_string(height) + " picture (the file is truncated)";
  };
  auto flatFrom = [&](size_t from) -> std::string {
    return bytes.size() - from < pixels * 4 ? cut("within its flat pixels") : "";
  };
  if (width < 8 || width >= 32768) return flatFrom(at);
  for (long row = 0; row < height; ++row) {
    const std::string inRow = "in scanline " + std::to_string(row);
    if (bytes.size() - at < 4) return cut(inRow);
    // A scanline that does not start with the run-length header makes stb_image read the whole
    // picture as flat pixels from here.
    if (bytes[at] != 2 || bytes[at + 1] != 2 || (bytes[at + 2] & 0x80)) return flatFrom(at);
    if ((long(bytes[at + 2]) << 8 | bytes[at + 3]) != width) return "";  // stb_image reports the length
    at += 4;
    for (int channel = 0; channel < 4; ++channel) {
      for (long filled = 0; filled < width;) {
        if (at >= bytes.size()) return cut(inRow);
        long count = bytes[at++];
        const bool run = count > 128;
        if (run) count -= 128;
        if (count > width - filled) return "";  // stb_image reports bad RLE data
        const size_t need = run ? 1 : size_t(count);
        if (bytes.size() - at < need) return cut(inRow);
        at += need;
        filled += count;
      }
    }
  }
  return "";
}

// The 8-bit RGBA pixels of an image probeImage accepted: JPEG through libjpeg-turbo, the rest
// (PNG) through stb_image.
bool decodeRgba8(std::span<const uint8_t> bytes, const std::string& name, int* w, int* h, std::vector<uint8_t>* rgba,
                 std::string* error) {
  std::string why;
  if (isJpeg(bytes)) {
    if (decodeJpeg(bytes, rgba, w, h, &why)) return true;
    *error = name + ": cannot decode image: " + why;
    return false;
  }
  int channels = 0;
  uint8_t* pixels = stbi_load_from_memory(bytes.data(), int(bytes.size()), w, h, &channels, 4);
  if (!pixels) {
    *error = name + ": cannot decode image: " + decodeFailure();
    return false;
  }
  rgba->assign(pixels, pixels + size_t(*w) * size_t(*h) * 4);
  stbi_image_free(pixels);
  return true;
}

}  // namespace

std::string decodeFailure() {
  const char* why = stbi_failure_reason();
  return why && *why ? why : "corrupt or truncated data";
}

bool probeImage(std::span<const uint8_t> bytes, const std::string& name, int* width, int* height, std::string* error) {
  std::string why = pngChunkError(bytes);
  if (why.empty()) why = radianceHdrError(bytes);
  if (!why.empty()) {
    *error = name + ": cannot read image: " + why;
    return false;
  }
  int channels = 0;
  if (isJpeg(bytes)) {
    if (!probeJpeg(bytes, width, height, &why)) {
      *error = name + ": cannot read image: " + why;
      return false;
    }
  } else if (bytes.size() > size_t(std::numeric_limits<int>::max()) ||
             !stbi_info_from_memory(bytes.data(), int(bytes.size()), width, height, &channels)) {
    *error = name + ": cannot read image: " + decodeFailure();
    return false;
  }
  if (*width <= 0 || *height <= 0 || *width > kMaxImageSide || *height > kMaxImageSide) {
    *error = name + ": image is " + std::to_string(*width) + "x" + std::to_string(*height) + "; the limit is " +
             std::to_string(kMaxImageSide) + " on each side";
    return false;
  }
  return true;
}

bool readImageFile(const std::string& path, std::vector<uint8_t>* bytes, std::string* error) {
  std::error_code ec;
  auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status) || !std::filesystem::is_regular_file(status)) {
    *error = path + ": cannot read image: " + (std::filesystem::exists(status) ? "not a regular file" : "no such file");
    return false;
  }
  uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxImageFileBytes) {
    *error = path + ": cannot read image: " +
             (ec ? ec.message() : std::to_string(size) + " bytes; the limit is " + std::to_string(kMaxImageFileBytes));
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  bytes->resize(size_t(size));
  if (!in.read(reinterpret_cast<char*>(bytes->data()), std::streamsize(size)) || in.peek() != EOF) {
    *error = path + ": cannot read image: the file could not be read whole";
    return false;
  }
  return true;
}

std::optional<Texture> decodeImageTexture(std::span<const uint8_t> bytes, bool srgb, const std::string& name,
                                          std::string* error) {
  // stb_image here also reads Radiance files (for environments); a texture is PNG or JPEG.
  if (!isPng(bytes) && !isJpeg(bytes)) {
    *error = name + ": cannot read image: textures are PNG, JPEG or KTX2 files (no PNG or JPEG signature)";
    return std::nullopt;
  }
  int w = 0, h = 0;
  if (!probeImage(bytes, name, &w, &h, error)) return std::nullopt;
  // Both decoders store the first row (the top of the picture) first; the texture convention puts
  // t = 0 first, so an image's top row is t = 0, as in glTF and most engines' UV conventions.
  Texture t;
  t.levels.emplace_back();
  if (!decodeRgba8(bytes, name, &w, &h, &t.levels[0], error)) return std::nullopt;
  t.width = uint32_t(w);
  t.height = uint32_t(h);
  t.format = srgb ? TextureFormat::Rgba8Srgb : TextureFormat::Rgba8Unorm;
  t.repeat = true;
  for (uint32_t lw = t.width, lh = t.height; lw > 1 || lh > 1; lw = std::max(1u, lw / 2), lh = std::max(1u, lh / 2))
    t.levels.push_back(halve(t.levels.back(), lw, lh, srgb));
  return t;
}

std::optional<Texture> loadImageTexture(const std::string& path, bool srgb, std::string* error) {
  std::vector<uint8_t> bytes;
  if (!readImageFile(path, &bytes, error)) return std::nullopt;
  return decodeImageTexture(bytes, srgb, path, error);
}

std::optional<ibl::EquirectImage> decodeEquirectImage(std::span<const uint8_t> bytes, const std::string& name,
                                                      std::string* error) {
  int w = 0, h = 0, channels = 0;
  if (!probeImage(bytes, name, &w, &h, error)) return std::nullopt;
  if (w != 2 * h) {
    *error = name + ": an equirect environment is twice as wide as high; this image is " + std::to_string(w) + "x" +
             std::to_string(h);
    return std::nullopt;
  }
  ibl::EquirectImage image(w, h);
  const int size = int(bytes.size());  // probeImage bounds it
  if (stbi_is_hdr_from_memory(bytes.data(), size)) {
    float* pixels = stbi_loadf_from_memory(bytes.data(), size, &w, &h, &channels, 3);
    if (!pixels) {
      *error = name + ": cannot decode image: " + decodeFailure();
      return std::nullopt;
    }
    std::memcpy(image.rgb.data(), pixels, image.rgb.size() * sizeof(float));
    stbi_image_free(pixels);
  } else {
    std::vector<uint8_t> rgba;
    if (!decodeRgba8(bytes, name, &w, &h, &rgba, error)) return std::nullopt;
    for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = float(decode(rgba[i / 3 * 4 + i % 3]));
  }
  for (float v : image.rgb) {
    if (!std::isfinite(v) || v < 0) {
      *error = name + ": the image holds a negative or non-finite value";
      return std::nullopt;
    }
  }
  return image;
}

Texture solidTexture(const std::array<double, 4>& rgba, bool srgb) {
  Texture t;
  t.width = t.height = 1;
  t.format = srgb ? TextureFormat::Rgba8Srgb : TextureFormat::Rgba8Unorm;
  std::vector<uint8_t> texel(4);
  for (size_t i = 0; i < 4; ++i) texel[i] = uint8_t(std::lround(std::clamp(rgba[i], 0.0, 1.0) * 255.0));
  t.levels.push_back(std::move(texel));
  return t;
}

}  // namespace facet::runtime
