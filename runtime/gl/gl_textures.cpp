#include "gl_textures.h"

#include <algorithm>
#include <cstring>
#include <unordered_set>

namespace facet::runtime::gl {
namespace {

using SourceTexture = facet::runtime::Texture;

struct FormatInfo {
  GLenum internalFormat;
  GLenum format;
  GLenum type;
  uint32_t bytesPerTexel;  // 0: not a TextureFormat enumerator
};

FormatInfo formatInfo(TextureFormat format) {
  switch (format) {
    case TextureFormat::Rgba8Unorm: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4};
    case TextureFormat::Rgba8Srgb: return {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, 4};
    case TextureFormat::R8Unorm: return {GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1};
    case TextureFormat::Rg16Float: return {GL_RG16F, GL_RG, GL_HALF_FLOAT, 4};
    case TextureFormat::Rgba16Float: return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, 8};
  }
  return {GL_NONE, GL_NONE, GL_NONE, 0};
}

uint32_t levelExtent(uint32_t size, size_t level) { return std::max(1u, size >> level); }

// 1 + floor(log2(max(width, height))): the levels down to 1x1.
size_t fullChainLength(uint32_t width, uint32_t height) {
  size_t levels = 1;
  for (uint32_t size = std::max(width, height); size > 1; size >>= 1) ++levels;
  return levels;
}

// Word-at-a-time multiply-xor hash of every level (length included, so moving bytes between
// levels changes it). Not cryptographic: it detects edits, it does not resist adversaries.
uint64_t hashLevels(const std::vector<std::vector<uint8_t>>& levels) {
  constexpr uint64_t kMultiplier = 0x9E3779B97F4A7C15ull;
  uint64_t hash = 0xCBF29CE484222325ull;
  const auto mix = [&](uint64_t word) {
    hash = (hash ^ word) * kMultiplier;
    hash ^= hash >> 29;
  };
  for (const std::vector<uint8_t>& level : levels) {
    mix(level.size());
    const uint8_t* bytes = level.data();
    size_t i = 0;
    for (; i + 8 <= level.size(); i += 8) {
      uint64_t word = 0;
      std::memcpy(&word, bytes + i, 8);
      mix(word);
    }
    if (i < level.size()) {
      uint64_t word = 0;
      std::memcpy(&word, bytes + i, level.size() - i);
      mix(word);
    }
  }
  return hash;
}

bool checkTexture(const SourceTexture& texture, uint32_t maxSize, const std::string& which, std::string* error) {
  if (texture.width == 0 || texture.height == 0 || texture.width > maxSize || texture.height > maxSize) {
    *error = which + ": size " + std::to_string(texture.width) + "x" + std::to_string(texture.height) +
             " is outside 1.." + std::to_string(maxSize);
    return false;
  }
  const uint32_t texelBytes = formatInfo(texture.format).bytesPerTexel;
  if (texelBytes == 0) {
    *error = which + ": unknown TextureFormat " + std::to_string(static_cast<int>(texture.format));
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
    const uint32_t w = levelExtent(texture.width, i);
    const uint32_t h = levelExtent(texture.height, i);
    const size_t expected = size_t{w} * h * texelBytes;
    if (texture.levels[i].size() != expected) {
      *error = which + ": level " + std::to_string(i) + " has " + std::to_string(texture.levels[i].size()) +
               " bytes, " + std::to_string(w) + "x" + std::to_string(h) + " texels of " +
               std::to_string(texelBytes) + " bytes need " + std::to_string(expected);
      return false;
    }
  }
  return true;
}

// Checks one list of bindings; `taken` marks the bindings already given to the same draw.
bool checkBindings(const std::vector<TextureBinding>& bindings, const std::string& owner, uint32_t maxSize,
                   std::array<const char*, kTextureUnits>* taken, const char* kind, std::string* error) {
  for (size_t i = 0; i < bindings.size(); ++i) {
    const TextureBinding& binding = bindings[i];
    const std::string which = owner + std::string(kind) + " " + std::to_string(i) + " ('" + binding.glslName +
                              "', binding " + std::to_string(binding.binding) + ")";
    if (binding.binding >= kTextureUnits) {
      *error = which + ": binding is outside 0.." + std::to_string(kTextureUnits - 1);
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
    if (!checkTexture(*binding.texture, maxSize, which, error)) return false;
  }
  return true;
}

}  // namespace

bool checkFrameTextures(const FrameDesc& frame, uint32_t maxTextureSize, std::string* error) {
  std::array<const char*, kTextureUnits> frameTaken{};
  if (!checkBindings(frame.frameTextures, "", maxTextureSize, &frameTaken, "frame texture", error)) return false;
  for (size_t d = 0; d < frame.draws.size(); ++d) {
    std::array<const char*, kTextureUnits> taken = frameTaken;
    if (!checkBindings(frame.draws[d].textures, "draw " + std::to_string(d) + ": ", maxTextureSize, &taken,
                       "draw texture", error)) {
      return false;
    }
  }
  return true;
}

void assignSamplerUnits(GLuint program, const std::vector<TextureBinding>& bindings, SamplerUnits* assigned) {
  for (const TextureBinding& binding : bindings) {
    const auto unit = static_cast<GLint>(binding.binding);
    auto found = assigned->find(binding.glslName);
    if (found != assigned->end() && (found->second == unit || found->second < 0)) continue;
    // A name the program does not use (location -1) is skipped, and remembered as such.
    const GLint location = glGetUniformLocation(program, binding.glslName.c_str());
    if (location >= 0) glUniform1i(location, unit);
    (*assigned)[binding.glslName] = location >= 0 ? unit : -1;
  }
}

bool TextureCache::init(std::string* error) {
  SourceTexture dummy;
  dummy.width = 1;
  dummy.height = 1;
  dummy.format = TextureFormat::Rgba8Unorm;
  dummy.levels = {{0, 0, 0, 255}};
  dummy.linearFilter = false;
  forgetBindings();
  return upload(dummy, &dummy_, error);
}

bool TextureCache::upload(const SourceTexture& source, Texture* out, std::string* error) {
  const FormatInfo info = formatInfo(source.format);
  Texture texture = Texture::generate();
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows tightly packed, whatever the width and format
  for (size_t level = 0; level < source.levels.size(); ++level) {
    // Row 0 of the data is t = 0 in GL as in the contract: no flip.
    glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(level), static_cast<GLint>(info.internalFormat),
                 static_cast<GLsizei>(levelExtent(source.width, level)),
                 static_cast<GLsizei>(levelExtent(source.height, level)), 0, info.format, info.type,
                 source.levels[level].data());
  }
  // The given levels are the whole chain GL may use: a shorter chain is still complete.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(source.levels.size() - 1));
  // Nearest still selects a mip level (like Vulkan's NEAREST mipmap mode), so textureLod works.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                  source.linearFilter ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, source.linearFilter ? GL_LINEAR : GL_NEAREST);
  const GLint wrap = source.repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  glBindTexture(GL_TEXTURE_2D, 0);
  if (!checkGlError("texture upload", error)) return false;
  *out = std::move(texture);
  return true;
}

bool TextureCache::prepare(const FrameDesc& frame, std::string* error) {
  ++frameNumber_;
  forgetBindings();  // upload() rebinds the current unit
  std::unordered_set<const SourceTexture*> seen;
  const auto refresh = [&](const std::vector<TextureBinding>& bindings) {
    for (const TextureBinding& binding : bindings) {
      const SourceTexture* source = binding.texture;
      if (!seen.insert(source).second) continue;
      Key key;
      key.width = source->width;
      key.height = source->height;
      key.format = source->format;
      key.linearFilter = source->linearFilter;
      key.repeat = source->repeat;
      for (const std::vector<uint8_t>& level : source->levels) key.levelSizes.push_back(level.size());
      key.hash = hashLevels(source->levels);
      auto found = textures_.find(source);
      if (found != textures_.end() && found->second.key == key) {
        found->second.lastUsedFrame = frameNumber_;
        continue;
      }
      Entry entry;
      entry.key = std::move(key);
      entry.lastUsedFrame = frameNumber_;
      if (!upload(*source, &entry.texture, error)) return false;
      textures_[source] = std::move(entry);  // a changed texture's old name is deleted here
    }
    return true;
  };
  if (!refresh(frame.frameTextures)) return false;
  for (const DrawItem& draw : frame.draws) {
    if (!refresh(draw.textures)) return false;
  }
  // Eviction: a texture gone from the scene must not hold memory forever.
  for (auto it = textures_.begin(); it != textures_.end();) {
    it = frameNumber_ - it->second.lastUsedFrame >= kEvictAfterFrames ? textures_.erase(it) : std::next(it);
  }
  return true;
}

void TextureCache::bind(const FrameDesc& frame, const DrawItem& draw) {
  std::array<GLuint, kTextureUnits> wanted;
  wanted.fill(dummy_.id());
  const auto assign = [&](const std::vector<TextureBinding>& bindings) {
    for (const TextureBinding& binding : bindings) {
      auto found = textures_.find(binding.texture);
      if (found != textures_.end() && binding.binding < kTextureUnits) {
        wanted[binding.binding] = found->second.texture.id();
      }
    }
  };
  assign(frame.frameTextures);
  assign(draw.textures);
  for (uint32_t unit = 0; unit < kTextureUnits; ++unit) {
    if (bound_[unit] == wanted[unit]) continue;
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, wanted[unit]);
    bound_[unit] = wanted[unit];
  }
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace facet::runtime::gl
