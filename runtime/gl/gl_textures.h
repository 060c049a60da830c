// Sampled textures of the forward pass: checking the frame's TextureBindings, uploading Texture
// data with all its given mip levels, a cache so that a texture seen in an earlier frame is not
// uploaded again, binding them to texture units (unit = ABI binding), and pointing each
// program's sampler uniforms, found by name, at their units.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/texture_checks.h"
#include "gl_objects.h"

namespace facet::runtime::gl {

// Units 0..15: frame textures 0..7, material textures 8..15.
inline constexpr uint32_t kTextureUnits = kTextureSlots;  // texture unit = binding

// Sampler uniform name → the unit glUniform1i last gave it in one program (-1: the program has
// no such active uniform). GLSL ES 3.00 has no layout(binding) for samplers, so this is how a
// sampler reaches its unit; the map makes that once per program and name, not once per draw.
using SamplerUnits = std::unordered_map<std::string, GLint>;

// Sets the sampler uniforms that `bindings` name to their units. `program` must be in use.
void assignSamplerUnits(GLuint program, const std::vector<TextureBinding>& bindings, SamplerUnits* assigned);

// GL textures made from the Textures a backend has drawn with, keyed by the Texture's address.
//
// Cache rule: an entry is reused when the Texture at the same address has the same size, format,
// level sizes, filter and wrap, and the same 64-bit hash of all its level bytes. The hash is one
// pass over the data per frame; it is what makes a texture edited in place, or a new one
// allocated at a freed one's address, upload again instead of sampling stale data. An entry
// unused for kEvictAfterFrames frames is deleted.
class TextureCache {
 public:
  // Creates the 1x1 dummy texture bound to every unit a draw leaves empty. `uploadAstc`: the
  // context samples ASTC (GL_KHR_texture_compression_astc_ldr); otherwise ASTC textures are
  // decoded to RGBA8 on the CPU before upload.
  bool init(bool uploadAstc, std::string* error);

  // Uploads every texture of the (already checked) frame that is new or changed, then deletes
  // the entries that went unused for too long. Changes the current unit's 2D and cube bindings.
  bool prepare(const FrameDesc& frame, std::string* error);

  // Binds units 0..15 for one draw: the frame's textures, the draw's, the dummy elsewhere, so a
  // texture of an earlier draw never leaks into this one. Skips units already bound right.
  void bind(const FrameDesc& frame, const DrawItem& draw);
  // The shadow atlas and its compare sampler, bound on unit abi::kShadowAtlasBinding by the
  // bind() calls that follow (the forward pass's receivers); texture 0: the dummy there again
  // (the shadow pass's casters, which draw into it).
  void setShadowAtlas(GLuint texture, GLuint sampler) {
    shadowAtlas_ = texture;
    shadowSampler_ = sampler;
  }
  // Binds sampler object 0 on every unit that may hold another (bind()'s, or an app's), so that
  // a pass binding textures itself samples with their own parameters.
  void clearSamplers();
  // Forgets what bind() left on the units (call when something else rebinds them).
  void forgetBindings() {
    bound2D_.fill(~0u);
    boundCube_.fill(~0u);
    boundSamplers_.fill(~0u);
  }
  // ASTC textures uploaded as blocks, and decoded to RGBA8 first, since creation.
  uint64_t compressedUploads() const { return compressedUploads_; }
  uint64_t decodedUploads() const { return decodedUploads_; }

 private:
  struct Entry {
    TextureIdentity key;
    Texture texture;
    uint64_t lastUsedFrame = 0;
  };

  bool upload(const facet::runtime::Texture& source, Texture* out, std::string* error);

  Texture dummy_;  // 1x1 RGBA8 (0, 0, 0, 1): what GL returns for an incomplete texture too
  std::unordered_map<const facet::runtime::Texture*, Entry> textures_;
  std::array<GLuint, kTextureUnits> bound2D_{};
  std::array<GLuint, kTextureUnits> boundCube_{};
  // Sampler objects for the bindings that carry a TextureSampler, by TextureSampler::key() (at
  // most 144, kept); a unit without one has sampler 0 bound, so the texture's own parameters
  // apply and a sampler an app left bound does not.
  std::unordered_map<uint32_t, Sampler> samplers_;
  std::array<GLuint, kTextureUnits> boundSamplers_{};
  GLuint samplerFor(const TextureSampler& sampler);
  GLuint shadowAtlas_ = 0;
  GLuint shadowSampler_ = 0;
  uint64_t frameNumber_ = 0;
  bool uploadAstc_ = false;
  uint64_t compressedUploads_ = 0;
  uint64_t decodedUploads_ = 0;
};

}  // namespace facet::runtime::gl
