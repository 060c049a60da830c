#include "facet/runtime/texture_checks.h"

#include "facet/runtime/content_hash.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace facet::runtime {
namespace {

// 1 + floor(log2(max(width, height))): the levels down to 1x1.
size_t fullChainLength(uint32_t width, uint32_t height) {
  size_t levels = 1;
  for (uint32_t size = std::max(width, height); size > 1; size >>= 1) ++levels;
  return levels;
}

// Every level through hashBytes (which mixes in the length, so moving bytes between levels
// changes the hash).
uint64_t hashLevels(const std::vector<std::vector<uint8_t>>& levels) {
  uint64_t hash = kContentHashSeed;
  for (const std::vector<uint8_t>& level : levels) hash = hashBytes(level.data(), level.size(), hash);
  return hash;
}

bool checkTexture(const Texture& texture, uint32_t maxImageSize, const std::string& which, std::string* error) {
  if (texture.width == 0 || texture.height == 0 || texture.width > maxImageSize || texture.height > maxImageSize) {
    *error = which + ": size " + std::to_string(texture.width) + "x" + std::to_string(texture.height) +
             " is outside 1.." + std::to_string(maxImageSize);
    return false;
  }
  const TextureBlock block = textureBlock(texture.format);
  if (block.bytes == 0) {
    *error = which + ": unknown TextureFormat " + std::to_string(static_cast<int>(texture.format));
    return false;
  }
  if (texture.cube && texture.width != texture.height) {
    *error = which + ": a cube map's faces must be square, not " + std::to_string(texture.width) + "x" +
             std::to_string(texture.height);
    return false;
  }
  if (texture.cube && isCompressed(texture.format)) {
    *error = which + ": a cube map cannot be ASTC-compressed (compressed textures are 2D)";
    return false;
  }
  const size_t fullChain = fullChainLength(texture.width, texture.height);
  if (texture.levels.empty() || texture.levels.size() > fullChain) {
    *error = which + ": " + std::to_string(texture.levels.size()) + " mip levels given, a " +
             std::to_string(texture.width) + "x" + std::to_string(texture.height) + " texture has 1.." +
             std::to_string(fullChain);
    return false;
  }
  for (size_t i = 0; i < texture.levels.size(); ++i) {
    const uint32_t w = mipExtent(texture.width, i);
    const uint32_t h = mipExtent(texture.height, i);
    const size_t faces = texture.cube ? 6 : 1;
    const uint64_t expected = faces * textureLevelBytes(texture.format, w, h);
    if (texture.levels[i].size() != expected) {
      *error = which + ": level " + std::to_string(i) + " has " + std::to_string(texture.levels[i].size()) +
               " bytes, " + (texture.cube ? "6 faces of " : "") + std::to_string(w) + "x" + std::to_string(h) +
               " texels " +
               (block.width > 1 ? "in " + std::to_string(block.width) + "x" + std::to_string(block.height) + " blocks "
                                : std::string()) +
               "of " + std::to_string(block.bytes) + " bytes need " + std::to_string(expected);
      return false;
    }
  }
  return true;
}

// Checks one list of bindings; `taken` marks the bindings already given to the same draw.
bool checkBindings(const std::vector<TextureBinding>& bindings, const std::string& owner, uint32_t maxImageSize,
                   std::array<const char*, kTextureSlots>* taken, const char* kind, std::string* error) {
  for (size_t i = 0; i < bindings.size(); ++i) {
    const TextureBinding& binding = bindings[i];
    const std::string which = owner + std::string(kind) + " " + std::to_string(i) + " ('" + binding.glslName +
                              "', binding " + std::to_string(binding.binding) + ")";
    if (binding.binding >= kTextureSlots) {
      *error = which + ": binding is outside 0.." + std::to_string(kTextureSlots - 1);
      return false;
    }
    if ((*taken)[binding.binding]) {
      *error = which + ": binding " + std::to_string(binding.binding) + " is already given by a " +
               (*taken)[binding.binding];
      return false;
    }
    (*taken)[binding.binding] = kind;
    if (!binding.texture) {
      *error = which + ": texture is null";
      return false;
    }
    if (!checkTexture(*binding.texture, maxImageSize, which, error)) return false;
    if (binding.sampler && binding.texture->cube) {
      *error = which + ": a sampler is for 2D textures (a cube map is filtered across its faces)";
      return false;
    }
    const auto wrapKnown = [](TextureWrap w) { return uint8_t(w) <= uint8_t(TextureWrap::MirroredRepeat); };
    if (binding.sampler && !(wrapKnown(binding.sampler->wrapS) && wrapKnown(binding.sampler->wrapT))) {
      *error = which + ": sampler wrap mode is not a TextureWrap";
      return false;
    }
  }
  return true;
}

}  // namespace

Texture emptySlotTexture(bool cube) {
  Texture t;
  t.width = 1;
  t.height = 1;
  t.format = TextureFormat::Rgba8Unorm;
  t.cube = cube;
  t.levels = {{}};
  for (int face = 0; face < (cube ? 6 : 1); ++face) t.levels[0].insert(t.levels[0].end(), {0, 0, 0, 255});
  t.linearFilter = false;
  return t;
}

uint32_t bytesPerTexel(TextureFormat format) {
  switch (format) {
    case TextureFormat::R8Unorm: return 1;
    case TextureFormat::Rgba16Float: return 8;
    case TextureFormat::Rgba8Unorm:
    case TextureFormat::Rgba8Srgb:
    case TextureFormat::Rg16Float: return 4;
    default: return 0;  // compressed, or not an enumerator (rejected by checkTexture)
  }
}

TextureBlock textureBlock(TextureFormat format) {
  switch (format) {
    case TextureFormat::Astc4x4Unorm:
    case TextureFormat::Astc4x4Srgb: return {4, 4, 16};
    case TextureFormat::Astc5x5Unorm:
    case TextureFormat::Astc5x5Srgb: return {5, 5, 16};
    case TextureFormat::Astc6x6Unorm:
    case TextureFormat::Astc6x6Srgb: return {6, 6, 16};
    case TextureFormat::Astc8x8Unorm:
    case TextureFormat::Astc8x8Srgb: return {8, 8, 16};
    default: return {1, 1, bytesPerTexel(format)};
  }
}

bool isCompressed(TextureFormat format) { return textureBlock(format).width > 1; }

bool isSrgb(TextureFormat format) {
  switch (format) {
    case TextureFormat::Rgba8Srgb:
    case TextureFormat::Astc4x4Srgb:
    case TextureFormat::Astc5x5Srgb:
    case TextureFormat::Astc6x6Srgb:
    case TextureFormat::Astc8x8Srgb: return true;
    default: return false;
  }
}

TextureFormat withoutSrgbDecode(TextureFormat format) {
  switch (format) {
    case TextureFormat::Rgba8Srgb: return TextureFormat::Rgba8Unorm;
    case TextureFormat::Astc4x4Srgb: return TextureFormat::Astc4x4Unorm;
    case TextureFormat::Astc5x5Srgb: return TextureFormat::Astc5x5Unorm;
    case TextureFormat::Astc6x6Srgb: return TextureFormat::Astc6x6Unorm;
    case TextureFormat::Astc8x8Srgb: return TextureFormat::Astc8x8Unorm;
    default: return format;
  }
}

uint64_t textureLevelBytes(TextureFormat format, uint32_t width, uint32_t height) {
  const TextureBlock block = textureBlock(format);
  return uint64_t((width + block.width - 1) / block.width) * ((height + block.height - 1) / block.height) * block.bytes;
}

uint32_t mipExtent(uint32_t size, size_t level) { return std::max(1u, size >> level); }

TextureIdentity TextureIdentity::of(const Texture& texture) {
  TextureIdentity id;
  id.width = texture.width;
  id.height = texture.height;
  id.format = texture.format;
  id.linearFilter = texture.linearFilter;
  id.repeat = texture.repeat;
  id.clampT = texture.clampT;
  id.cube = texture.cube;
  for (const std::vector<uint8_t>& level : texture.levels) id.levelSizes.push_back(level.size());
  id.hash = hashLevels(texture.levels);
  return id;
}

bool checkFrameTextures(const FrameDesc& frame, uint32_t maxImageSize, std::string* error) {
  std::array<const char*, kTextureSlots> frameTaken{};
  if (!checkBindings(frame.frameTextures, "", maxImageSize, &frameTaken, "frame texture", error)) {
    return false;
  }
  const FrameDraws draws(frame);
  for (size_t d = 0; d < draws.size(); ++d) {
    std::array<const char*, kTextureSlots> taken = frameTaken;
    if (!checkBindings(draws[d].textures, "draw " + std::to_string(d) + ": ", maxImageSize, &taken, "draw texture",
                       error)) {
      return false;
    }
  }
  return true;
}

}  // namespace facet::runtime
