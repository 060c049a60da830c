// Textures from KTX2 files (ASTC LDR blocks or RGBA8, every mip level stored: the subset of
// docs/texture-format.md, written by `matc texture`), and their decoding to RGBA8 for a device that
// cannot sample ASTC.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// A KTX2 file held in memory (`name` is used in messages) as a Texture of its own format, with
// the levels it stores, repeating like a PNG texture. `srgb` is what the material expects
// (texture(srgb)); a file encoded the other way is refused with a message saying how to encode it,
// since sampling it would decode colours twice or not at all. The fuzz target fuzz_ktx2 drives it.
std::optional<Texture> decodeKtx2Texture(std::span<const uint8_t> bytes, bool srgb, const std::string& name,
                                         std::string* error);

// A texture image file: KTX2 when it starts with the KTX 2.0 identifier, else PNG
// (loadImageTexture). Read whole, within kMaxImageFileBytes (image_texture.h).
std::optional<Texture> loadTextureFile(const std::string& path, bool srgb, std::string* error);

// An ASTC texture decoded to RGBA8 (sRGB-encoded when it was sRGB: the sampler decodes), with the
// same levels, filter and wrap; what a backend uploads where the device cannot sample ASTC. An
// uncompressed texture is returned as it is.
std::optional<Texture> decodeCompressedTexture(const Texture& texture, std::string* error);

}  // namespace facet::runtime
