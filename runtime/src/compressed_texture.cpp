#include "facet/runtime/compressed_texture.h"

#include "facet/runtime/image_texture.h"
#include "facet/runtime/texture_checks.h"
#include "facet/texture/astc.h"
#include "facet/texture/ktx2.h"

namespace facet::runtime {
namespace {

struct FormatPair {
  uint32_t vkFormat;
  TextureFormat format;
};

constexpr FormatPair kFormats[] = {
    {37, TextureFormat::Rgba8Unorm},    {43, TextureFormat::Rgba8Srgb},     {157, TextureFormat::Astc4x4Unorm},
    {158, TextureFormat::Astc4x4Srgb},  {161, TextureFormat::Astc5x5Unorm}, {162, TextureFormat::Astc5x5Srgb},
    {165, TextureFormat::Astc6x6Unorm}, {166, TextureFormat::Astc6x6Srgb},  {171, TextureFormat::Astc8x8Unorm},
    {172, TextureFormat::Astc8x8Srgb},
};

}  // namespace

std::optional<Texture> decodeKtx2Texture(std::span<const uint8_t> bytes, bool srgb, const std::string& name,
                                         std::string* error) {
  std::optional<texture::Ktx2Image> image = texture::readKtx2(bytes, name, error);
  if (!image) return std::nullopt;
  const texture::Ktx2Format& file = *texture::findKtx2Format(image->vkFormat);  // readKtx2 checked it
  if (file.srgb != srgb) {
    *error = name + ": the texture is " + file.name + (file.srgb ? " (sRGB colour)" : " (linear)") +
             " but the material samples it as " +
             (srgb ? "sRGB colour (texture(srgb)): encode it with --usage color"
                   : "linear data (texture(linear) or texture(normal)): encode it with --usage data or normal");
    return std::nullopt;
  }
  Texture t;
  for (const FormatPair& pair : kFormats)
    if (pair.vkFormat == image->vkFormat) t.format = pair.format;
  t.width = image->width;
  t.height = image->height;
  t.repeat = true;
  t.levels = std::move(image->levels);
  return t;
}

std::optional<Texture> loadTextureFile(const std::string& path, bool srgb, std::string* error) {
  std::vector<uint8_t> bytes;
  if (!readImageFile(path, &bytes, error)) return std::nullopt;
  if (texture::isKtx2(bytes)) return decodeKtx2Texture(bytes, srgb, path, error);
  return decodeImageTexture(bytes, srgb, path, error);
}

std::optional<Texture> decodeCompressedTexture(const Texture& source, std::string* error) {
  if (!isCompressed(source.format)) return source;
  const TextureBlock block = textureBlock(source.format);
  const bool srgb = isSrgb(source.format);
  Texture t = source;
  t.format = srgb ? TextureFormat::Rgba8Srgb : TextureFormat::Rgba8Unorm;
  for (size_t i = 0; i < source.levels.size(); ++i) {
    auto rgba = texture::decodeAstc(source.levels[i], mipExtent(source.width, i), mipExtent(source.height, i),
                                    block.width, block.height, srgb, error);
    if (!rgba) {
      *error = "ASTC level " + std::to_string(i) + ": " + *error;
      return std::nullopt;
    }
    t.levels[i] = std::move(*rgba);
  }
  return t;
}

}  // namespace facet::runtime
