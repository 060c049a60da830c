#include "gl_textures.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <unordered_set>

#include "facet/runtime/compressed_texture.h"

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
    // ASTC: glCompressedTexImage2D's internal format (KHR_texture_compression_astc_ldr).
    case TextureFormat::Astc4x4Unorm: return {GL_COMPRESSED_RGBA_ASTC_4x4_KHR, GL_NONE, GL_NONE, 0};
    case TextureFormat::Astc4x4Srgb: return {GL_COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR, GL_NONE, GL_NONE, 0};
    case TextureFormat::Astc5x5Unorm: return {GL_COMPRESSED_RGBA_ASTC_5x5_KHR, GL_NONE, GL_NONE, 0};
    case TextureFormat::Astc5x5Srgb: return {GL_COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR, GL_NONE, GL_NONE, 0};
    case TextureFormat::Astc6x6Unorm: return {GL_COMPRESSED_RGBA_ASTC_6x6_KHR, GL_NONE, GL_NONE, 0};
    case TextureFormat::Astc6x6Srgb: return {GL_COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR, GL_NONE, GL_NONE, 0};
    case TextureFormat::Astc8x8Unorm: return {GL_COMPRESSED_RGBA_ASTC_8x8_KHR, GL_NONE, GL_NONE, 0};
    case TextureFormat::Astc8x8Srgb: return {GL_COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR, GL_NONE, GL_NONE, 0};
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

bool TextureCache::init(bool uploadAstc, std::string* error) {
  uploadAstc_ = uploadAstc;
  const SourceTexture dummy = emptySlotTexture();
  forgetBindings();
  return upload(dummy, &dummy_, error);
}

bool TextureCache::upload(const SourceTexture& given, Texture* out, std::string* error) {
  std::optional<SourceTexture> decoded;
  if (isCompressed(given.format)) {
    if (!uploadAstc_) {
      decoded = decodeCompressedTexture(given, error);
      if (!decoded) return false;
      ++decodedUploads_;
    } else {
      ++compressedUploads_;
    }
  }
  const SourceTexture& source = decoded ? *decoded : given;
  const FormatInfo info = formatInfo(source.format);
  const GLenum target = source.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
  const int faces = source.cube ? 6 : 1;
  Texture texture = Texture::generate();
  glBindTexture(target, texture.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows tightly packed, whatever the width and format
  for (size_t level = 0; level < source.levels.size(); ++level) {
    const uint32_t width = mipExtent(source.width, level), height = mipExtent(source.height, level);
    const auto faceBytes = size_t(textureLevelBytes(source.format, width, height));
    for (int face = 0; face < faces; ++face) {
      // Row 0 of the data is t = 0 in GL as in the contract: no flip. A cube map's faces follow
      // each other in the level's bytes, in GL's order (POSITIVE_X + face).
      const GLenum image = source.cube ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face) : GL_TEXTURE_2D;
      const uint8_t* data = source.levels[level].data() + size_t(face) * faceBytes;
      if (isCompressed(source.format)) {
        glCompressedTexImage2D(image, static_cast<GLint>(level), info.internalFormat, static_cast<GLsizei>(width),
                               static_cast<GLsizei>(height), 0, static_cast<GLsizei>(faceBytes), data);
      } else {
        glTexImage2D(image, static_cast<GLint>(level), static_cast<GLint>(info.internalFormat),
                     static_cast<GLsizei>(width), static_cast<GLsizei>(height), 0, info.format, info.type, data);
      }
    }
  }
  // The given levels are the whole chain GL may use: a shorter chain is still complete.
  glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(source.levels.size() - 1));
  // Nearest still selects a mip level (like Vulkan's NEAREST mipmap mode), so textureLod works.
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER,
                  source.linearFilter ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, source.linearFilter ? GL_LINEAR : GL_NEAREST);
  const GLint wrap = source.repeat && !source.cube ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, source.clampT ? GL_CLAMP_TO_EDGE : wrap);
  glBindTexture(target, 0);
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
  // Each unit has a 2D and a cube binding; a unit's sampler reads the one its type names. The
  // dummy fills every 2D binding left empty; an empty cube binding reads as incomplete, (0, 0, 0, 1)
  // too, which no lit draw meets (the environment is a frame texture).
  std::array<GLuint, kTextureUnits> wanted2D, wantedCube;
  wanted2D.fill(dummy_.id());
  wantedCube.fill(0);
  std::array<GLuint, kTextureUnits> wantedSamplers{};
  const auto assign = [&](const std::vector<TextureBinding>& bindings) {
    for (const TextureBinding& binding : bindings) {
      auto found = textures_.find(binding.texture);
      if (found != textures_.end() && binding.binding < kTextureUnits) {
        (found->second.key.cube ? wantedCube : wanted2D)[binding.binding] = found->second.texture.id();
        if (binding.sampler) wantedSamplers[binding.binding] = samplerFor(*binding.sampler);
      }
    }
  };
  assign(frame.frameTextures);
  assign(draw.textures);
  if (shadowAtlas_ != 0) {
    wanted2D[abi::kShadowAtlasBinding] = shadowAtlas_;
    wantedSamplers[abi::kShadowAtlasBinding] = shadowSampler_;
  }
  for (uint32_t unit = 0; unit < kTextureUnits; ++unit) {
    if (boundSamplers_[unit] != wantedSamplers[unit]) glBindSampler(unit, wantedSamplers[unit]);
    boundSamplers_[unit] = wantedSamplers[unit];
  }
  for (uint32_t unit = 0; unit < kTextureUnits; ++unit) {
    if (bound2D_[unit] == wanted2D[unit] && boundCube_[unit] == wantedCube[unit]) continue;
    glActiveTexture(GL_TEXTURE0 + unit);
    if (bound2D_[unit] != wanted2D[unit]) glBindTexture(GL_TEXTURE_2D, wanted2D[unit]);
    if (boundCube_[unit] != wantedCube[unit]) glBindTexture(GL_TEXTURE_CUBE_MAP, wantedCube[unit]);
    bound2D_[unit] = wanted2D[unit];
    boundCube_[unit] = wantedCube[unit];
  }
  glActiveTexture(GL_TEXTURE0);
}

void TextureCache::clearSamplers() {
  for (uint32_t unit = 0; unit < kTextureUnits; ++unit) {
    if (boundSamplers_[unit] != 0) glBindSampler(unit, 0);
    boundSamplers_[unit] = 0;
  }
}

GLuint TextureCache::samplerFor(const TextureSampler& sampler) {
  auto found = samplers_.find(sampler.key());
  if (found != samplers_.end()) return found->second.id();
  Sampler made = Sampler::generate();
  const auto wrap = [](TextureWrap w) {
    switch (w) {
      case TextureWrap::Repeat: return GL_REPEAT;
      case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
      case TextureWrap::ClampToEdge: break;
    }
    return GL_CLAMP_TO_EDGE;
  };
  GLint min = sampler.minLinear ? GL_LINEAR : GL_NEAREST;
  if (sampler.mipmaps) {
    min = sampler.minLinear ? (sampler.mipLinear ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST)
                            : (sampler.mipLinear ? GL_NEAREST_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST);
  }
  glSamplerParameteri(made.id(), GL_TEXTURE_MIN_FILTER, min);
  glSamplerParameteri(made.id(), GL_TEXTURE_MAG_FILTER, sampler.magLinear ? GL_LINEAR : GL_NEAREST);
  glSamplerParameteri(made.id(), GL_TEXTURE_WRAP_S, wrap(sampler.wrapS));
  glSamplerParameteri(made.id(), GL_TEXTURE_WRAP_T, wrap(sampler.wrapT));
  const GLuint id = made.id();
  samplers_.emplace(sampler.key(), std::move(made));
  return id;
}

}  // namespace facet::runtime::gl
