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

}  // namespace

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
  const SourceTexture dummy = emptySlotTexture();
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
                 static_cast<GLsizei>(mipExtent(source.width, level)),
                 static_cast<GLsizei>(mipExtent(source.height, level)), 0, info.format, info.type,
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
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, source.clampT ? GL_CLAMP_TO_EDGE : wrap);
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
      TextureIdentity key = TextureIdentity::of(*source);
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
  evictUnusedEntries(textures_, frameNumber_, [](auto&) {});  // GL objects delete themselves
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
