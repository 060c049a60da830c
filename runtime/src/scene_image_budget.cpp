#include "facet/runtime/scene_image_budget.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include <stb_image.h>  // implementation: stb_image_impl.cpp

#include "facet/runtime/image_texture.h"
#include "facet/texture/ktx2.h"
#include "jpeg.h"

namespace facet::runtime {
namespace {

// The first bytes of a regular file: enough for a PNG's IHDR (byte 16), a Radiance header and
// most JPEGs' frame headers.
std::vector<uint8_t> fileHead(const std::string& path) {
  constexpr size_t kHeadBytes = 64 * 1024;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return {};
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> head(kHeadBytes);
  in.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
  head.resize(size_t(in.gcount()));
  return head;
}

struct ImageCost {
  uint64_t bytes = 0;
  std::string description;  // "path (WxH)"
};

uint32_t little32(const std::vector<uint8_t>& b, size_t at) {
  return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
}

// A KTX2 texture takes the bytes its levels hold (ASTC blocks stay compressed on a GPU that
// samples them), from the header's format, size and level count.
std::optional<ImageCost> ktx2Cost(const std::string& path, const std::vector<uint8_t>& head) {
  if (head.size() < 44) return std::nullopt;
  const texture::Ktx2Format* format = texture::findKtx2Format(little32(head, 12));
  const uint32_t w = little32(head, 20), h = little32(head, 24), levels = little32(head, 40);
  if (!format || w == 0 || h == 0 || w > texture::kMaxKtx2Side || h > texture::kMaxKtx2Side) return std::nullopt;
  uint64_t bytes = 0;
  // At most the 14 levels of an 8192-texel side; a larger count is the reader's to refuse.
  for (uint32_t i = 0; i < std::clamp(levels, 1u, 14u); ++i)
    bytes += texture::ktx2LevelBytes(*format, std::max(1u, w >> i), std::max(1u, h >> i));
  return ImageCost{bytes, path + " (" + std::to_string(w) + "x" + std::to_string(h) + ", " + format->name + ")"};
}

std::optional<ImageCost> decodedCost(const std::string& path, uint64_t bytesPerPixel, bool mipChain) {
  const std::vector<uint8_t> head = fileHead(path);
  if (texture::isKtx2(head)) return ktx2Cost(path, head);
  int w = 0, h = 0, channels = 0;
  if (isJpeg(head)) {
    // A JPEG's frame header comes after its application segments (Exif, ICC profiles: up to 64 KiB
    // each), so it may lie past the head: then the whole file is read.
    std::string why;
    std::vector<uint8_t> whole;
    if (!probeJpeg(head, &w, &h, &why) && (!readImageFile(path, &whole, &why) || !probeJpeg(whole, &w, &h, &why)))
      return std::nullopt;
  } else if (head.empty() || !stbi_info_from_memory(head.data(), int(head.size()), &w, &h, &channels)) {
    return std::nullopt;
  }
  if (w <= 0 || h <= 0) return std::nullopt;
  uint64_t bytes = 0;
  for (uint64_t lw = uint64_t(w), lh = uint64_t(h);;
       lw = std::max<uint64_t>(1, lw / 2), lh = std::max<uint64_t>(1, lh / 2)) {
    bytes += lw * lh * bytesPerPixel;
    if (!mipChain || (lw == 1 && lh == 1)) break;
  }
  return ImageCost{bytes, path + " (" + std::to_string(w) + "x" + std::to_string(h) + ")"};
}

}  // namespace

bool checkSceneImageBudget(const Scene& scene, std::string* error) {
  std::set<std::string> textures;
  for (const SceneObject& o : scene.objects)
    for (const auto& [param, path] : o.textures) textures.insert(path);
  std::vector<ImageCost> costs;
  for (const std::string& path : textures)
    if (auto cost = decodedCost(path, 4, true)) costs.push_back(std::move(*cost));
  if (scene.environment && !scene.environment->image.empty())
    if (auto cost = decodedCost(scene.environment->image, 3 * sizeof(float), false)) costs.push_back(std::move(*cost));
  uint64_t total = 0;
  for (const ImageCost& c : costs) total += c.bytes;
  if (total <= kMaxSceneImageBytes) return true;
  std::sort(costs.begin(), costs.end(), [](const ImageCost& a, const ImageCost& b) { return a.bytes > b.bytes; });
  std::string largest;
  for (size_t i = 0; i < costs.size() && i < 3; ++i) largest += (i ? ", " : "") + costs[i].description;
  *error = "the scene's images decode to " + std::to_string((total + (1u << 20) - 1) >> 20) + " MiB (" +
           std::to_string(costs.size()) + " images; largest: " + largest + "); a scene may use at most " +
           std::to_string(kMaxSceneImageBytes >> 20) + " MiB of decoded images";
  return false;
}

}  // namespace facet::runtime
