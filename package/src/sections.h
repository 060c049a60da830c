// Encoding and decoding of each section's payload. Each pair lives in one file so the two sides
// of the format are read side by side. Decoders report through the ByteReader's sticky error.
#pragma once

#include <string>
#include <vector>

#include "byte_io.h"
#include "format.h"

namespace facet::package::detail {

// A GLSL identifier of at most maxLength bytes: what shaders call a sampler or block, and what a
// GL or Metal runtime looks up.
bool isGlslIdentifier(const std::string& s, size_t maxLength);

// META: compiler version, then the material.
void encodeMetadata(ByteWriter& out, const std::string& compilerVersion, const MaterialInfo& material);
void decodeMetadata(ByteReader& in, std::string& compilerVersion, MaterialInfo& material);

// VARS: variant keys and, per shader, which blob holds its code.
void encodeVariantTable(ByteWriter& out, const std::vector<VariantInfo>& variants);
void decodeVariantTable(ByteReader& in, std::vector<VariantInfo>& variants);

// BTAB: one fixed-size entry per blob. `dataSize` is the size of BDAT, which the entries must
// tile exactly.
void encodeBlobTable(ByteWriter& out, const std::vector<BlobEntry>& blobs);
// `minor`: the file's format minor; codecs newer than it are rejected.
void decodeBlobTable(ByteReader& in, uint64_t dataSize, uint16_t minor, std::vector<BlobEntry>& blobs);

// TEXS: generated textures. Decoded after VARS and BTAB: every entry's variant indices and blob
// index are checked against them, and the blob's raw size against the texture's size.
void encodeTextureTable(ByteWriter& out, const std::vector<TextureInfo>& textures);
void decodeTextureTable(ByteReader& in, uint64_t variantCount, const std::vector<BlobEntry>& blobs,
                        std::vector<TextureInfo>& textures);

// MSLB: the Metal argument slots of the package's MSL (format 1.2). Each slot index within
// Metal's table for its kind; names GLSL identifiers like texture names.
void encodeMslBindings(ByteWriter& out, const std::vector<MslBinding>& bindings);
void decodeMslBindings(ByteReader& in, std::vector<MslBinding>& bindings);

// PRSH: the preshader (format 1.3). Decoded after VARS: variant indices are checked against the
// variant table; the block against the parameters and each op are meaning (semanticError).
void encodePreshader(ByteWriter& out, const Preshader& preshader);
void decodePreshader(ByteReader& in, uint64_t variantCount, Preshader& preshader);

}  // namespace facet::package::detail
