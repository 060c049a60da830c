// On-disk constants and layout of a .matpkg file. docs/package-format.md is the byte-by-byte
// description; keep the two in step. The rows of the variant and texture tables are
// package_reader.h's VariantInfo, ShaderInfo and TextureInfo (code and texels by blob index),
// as the sections store them; rows.h converts them to and from the package model.
#pragma once

#include <array>
#include <cstdint>

#include "facet/package/package.h"
#include "facet/package/package_reader.h"

namespace facet::package::detail {

// PNG-style: the high byte catches 7-bit transfers, CR LF catches newline conversion in either
// direction, and 0x1A stops `type` on Windows from dumping binary to the console.
inline constexpr std::array<uint8_t, 8> kMagic = {0x89, 'F', 'P', 'K', 'G', '\r', '\n', 0x1A};

// Header: magic[8], u16 format major, u16 format minor, u32 section count, u64 file size,
// u64 checksum. (Format 1.0 described bytes 8..11 as one u32 version 1: the same bytes.)
inline constexpr uint64_t kHeaderSize = 32;
inline constexpr uint64_t kVersionOffset = 8;
inline constexpr uint64_t kMinorOffset = 10;
inline constexpr uint64_t kSectionCountOffset = 12;
inline constexpr uint64_t kFileSizeOffset = 16;
inline constexpr uint64_t kChecksumOffset = 24;

// TOC entry: u8[4] tag, u32 flags (0), u64 offset, u64 size.
inline constexpr uint64_t kTocEntrySize = 24;
inline constexpr uint64_t kSectionAlignment = 8;

constexpr uint32_t fourcc(char a, char b, char c, char d) {
  return uint32_t(uint8_t(a)) | uint32_t(uint8_t(b)) << 8 | uint32_t(uint8_t(c)) << 16 | uint32_t(uint8_t(d)) << 24;
}

inline constexpr uint32_t kTagMeta = fourcc('M', 'E', 'T', 'A');         // compiler version + material
inline constexpr uint32_t kTagVariants = fourcc('V', 'A', 'R', 'S');     // variant table
inline constexpr uint32_t kTagBlobTable = fourcc('B', 'T', 'A', 'B');    // one entry per blob
inline constexpr uint32_t kTagBlobData = fourcc('B', 'D', 'A', 'T');     // blob bytes, back to back
inline constexpr uint32_t kTagTextures = fourcc('T', 'E', 'X', 'S');     // generated textures (optional)
inline constexpr uint32_t kTagMslBindings = fourcc('M', 'S', 'L', 'B');  // Metal argument slots (optional, 1.2)
inline constexpr uint16_t kFirstMinorWithMslBindings = 2;
inline constexpr uint32_t kTagPreshader = fourcc('P', 'R', 'S', 'H');  // preshader programs (optional, 1.3)
inline constexpr uint16_t kFirstMinorWithPreshader = 3;

// Limits the reader enforces so that a hostile file cannot make it allocate or work without
// bound. A real package has 4 sections and a few MiB of code.
inline constexpr uint32_t kMaxSections = 64;
inline constexpr uint64_t kMaxBlobRawSize = 256ull << 20;
// Caps both the sum of all blobs' raw sizes and the code materialised into Package::variants,
// where a shared blob is copied once per shader that uses it.
inline constexpr uint64_t kMaxTotalCodeSize = 1ull << 30;
inline constexpr uint64_t kMaxFileSize = 1ull << 30;
// Package textures: a side at most this long (the largest 2D image GLES 3 / Vulkan devices must
// support is smaller; a lookup table needs far less), a name a GLSL identifier of at most 64 bytes.
inline constexpr uint32_t kMaxTextureSide = 16384;
inline constexpr uint32_t kMaxTextureNameLength = 64;
// An MSLB name: a block name or a sampler's, "facet_material_" + a parameter name (≤ kMaxNameBytes).
inline constexpr uint32_t kMaxMslNameLength = 192;

// Fixed so output is deterministic. With the package dictionary most of a blob is one long match,
// and level 9 compresses ten times faster than 19 for 13 % more bytes (docs/package-format.md,
// "The dictionary"); at 19 compression was 14 % of a compile.
inline constexpr int kZstdLevel = 9;

// ZstdDictionary (format 1.1): one zstd frame compressed against the raw bytes of another blob
// (BlobEntry::dictionary), as a zstd raw-content dictionary.
enum class Codec : uint32_t { Raw = 0, Zstd = 1, ZstdDictionary = 2 };
inline constexpr uint16_t kFirstMinorWithDictionary = 1;

// Encoded sizes of fixed-size records, used to check counts against the bytes available.
inline constexpr uint64_t kShaderInfoSize = 8;  // u8 stage, u8 target, u16 reserved, u32 blob
inline constexpr uint64_t kMinVariantSize = 8;  // u32 key length, u32 shader count
inline constexpr uint64_t kMinParamSize = 16;   // u32 name length, 4 x u8, u32 offset, u32 size
inline constexpr uint64_t kBlobEntrySize = 40;  // 4 x u64, u32 codec, u32 dictionary blob
// u32 name length, u32 width, u32 height, u8 format, u8 + u16 reserved, u32 blob, u32 variant count
inline constexpr uint64_t kMinTextureSize = 24;
inline constexpr uint64_t kVariantIndexSize = 4;
// u32 name length, u8 kind, u8 + u16 reserved, u32 set, u32 binding, u32 index
inline constexpr uint64_t kMinMslBindingSize = 20;
inline constexpr uint8_t kLastMslResource = uint8_t(MslResource::Texture);
// PRSH: u32 variant count (then the indices), u32 op count; an op is u8 code, dst, a, b, u32
// offset, u32 count, 4 x f32.
inline constexpr uint64_t kMinPreshaderProgramSize = 8;
inline constexpr uint64_t kPreshaderOpSize = 28;

struct BlobEntry {
  uint64_t contentHash = 0;  // XXH3_64bits of the raw code
  uint64_t offset = 0;       // from the start of the BDAT section
  uint64_t storedSize = 0;
  uint64_t rawSize = 0;
  Codec codec = Codec::Raw;
  uint32_t dictionary = 0;  // ZstdDictionary: the blob whose raw bytes are the dictionary; else 0
};

// Number of default-value components a parameter of this type carries. Color accepts both RGB
// and RGBA (the contract says "component count of the type" without fixing it for colours).
inline bool defaultCountMatches(ParamType type, uint64_t count) {
  switch (type) {
    case ParamType::Float:
    case ParamType::Int:
    case ParamType::Bool: return count == 1;
    case ParamType::Vec2: return count == 2;
    case ParamType::Vec3: return count == 3;
    case ParamType::Vec4: return count == 4;
    case ParamType::Color: return count == 3 || count == 4;
    case ParamType::TextureSrgb:
    case ParamType::TextureLinear:
    case ParamType::TextureNormal: return count == 4;
  }
  return false;
}

inline constexpr uint8_t kLastParamType = uint8_t(ParamType::TextureNormal);
inline constexpr uint8_t kLastStage = uint8_t(Stage::Fragment);
inline constexpr uint8_t kLastTarget = uint8_t(Target::Msl);
inline constexpr uint8_t kLastTexelFormat = uint8_t(TexelFormat::R8Unorm);

}  // namespace facet::package::detail
