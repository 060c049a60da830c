// Checks and identities of textures that every backend needs in the same form: what a valid
// texture and binding list is (with the same messages on every API), and what identifies a
// texture's content for the backends' upload caches.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// Bindings 0..15: frame textures then material textures (shader_abi.h).
inline constexpr uint32_t kTextureSlots = abi::kMaterialTextureBase + abi::kMaxMaterialTextures;

// The 1×1 opaque black texture both backends bind in slots a draw leaves empty (GLES and Vulkan
// 1.1 both need every declared sampler to have a texture); with `cube`, six such faces, for the
// ABI's cube slots (a Vulkan view's type must match the shader's sampler, even for the dummy).
Texture emptySlotTexture(bool cube = false);

uint32_t bytesPerTexel(TextureFormat format);  // 0 for a compressed format or a value that is not an enumerator

// The blocks a format stores texels in: 1x1 of bytesPerTexel for uncompressed formats, 4x4..8x8
// of 16 bytes for ASTC; bytes 0 for a value that is not an enumerator.
struct TextureBlock {
  uint32_t width = 1;
  uint32_t height = 1;
  uint32_t bytes = 0;
};
TextureBlock textureBlock(TextureFormat format);
bool isCompressed(TextureFormat format);  // ASTC
bool isSrgb(TextureFormat format);        // sampled with sRGB decoding
// The same storage sampled without sRGB decoding (the gamma-hack tiers read colours encoded).
TextureFormat withoutSrgbDecode(TextureFormat format);
// Bytes of one width x height level (or face) in `format`: whole blocks at the edges.
uint64_t textureLevelBytes(TextureFormat format, uint32_t width, uint32_t height);
uint32_t mipExtent(uint32_t size, size_t level);

// Everything an uploaded copy depends on. The hash covers every byte of every level, so a
// texture edited in place, or a new one at a freed address, is uploaded again.
struct TextureIdentity {
  uint32_t width = 0;
  uint32_t height = 0;
  TextureFormat format = TextureFormat::Rgba8Unorm;
  bool linearFilter = false;
  bool repeat = false;
  bool clampT = false;
  bool cube = false;
  std::vector<size_t> levelSizes;
  uint64_t hash = 0;

  static TextureIdentity of(const Texture& texture);
  bool operator==(const TextureIdentity&) const = default;
};

// Every frame and draw texture binding (FrameDraws: the shadow casters' too, the shadow pass
// checked by shadowPassError first): binding in range and given once per draw, texture
// present, size within 1..maxImageSize, mip levels and their byte sizes consistent.
bool checkFrameTextures(const FrameDesc& frame, uint32_t maxImageSize, std::string* error);

}  // namespace facet::runtime
