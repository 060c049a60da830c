// Compression of one blob: zstd at a fixed level, alone or against the package's dictionary
// (format 1.1), or raw when zstd does not shrink it.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <zstd.h>

#include "format.h"

namespace facet::package::detail {

class BlobEncoder {
 public:
  BlobEncoder();

  // Returns the codec chosen (Zstd or Raw); `stored` receives the bytes to write.
  Codec encode(std::span<const uint8_t> raw, std::vector<uint8_t>& stored);

  // Loads the raw bytes every later encodeWithDictionary call compresses against; they must not
  // start with kZstdDictionaryMagic.
  void setDictionary(std::span<const uint8_t> dictionary);
  // Returns ZstdDictionary or Raw.
  Codec encodeWithDictionary(std::span<const uint8_t> raw, std::vector<uint8_t>& stored);

 private:
  // One context per mode, reused for every blob of a package: zstd's level-19 tables, and the
  // dictionary's, are large to set up.
  std::unique_ptr<ZSTD_CCtx, size_t (*)(ZSTD_CCtx*)> context_;
  std::unique_ptr<ZSTD_CCtx, size_t (*)(ZSTD_CCtx*)> dictionaryContext_;
};

// The first four bytes of a zstd-format dictionary. A package dictionary is raw content, and one
// starting with these bytes would be parsed as the other kind, so the reader refuses it.
inline constexpr uint32_t kZstdDictionaryMagic = 0xEC30A437;

// Decodes a blob whose entry has passed the table checks (sizes within limits, stored bytes in
// bounds). `fileOffset` is where the stored bytes start, for messages. `dictionary` is the raw
// bytes of entry.dictionary for a ZstdDictionary blob, ignored otherwise. Checks the zstd frame
// header against raw_size before allocating, and the content hash after decoding.
bool decodeBlob(const BlobEntry& entry, uint32_t index, std::span<const uint8_t> stored, uint64_t fileOffset,
                std::span<const uint8_t> dictionary, std::vector<uint8_t>& raw, std::string& error);

// The content hash of a blob's raw bytes against its table entry; what decodeBlob checks last,
// and all the lazy reader checks for a blob stored raw (served without a copy).
bool checkContentHash(const BlobEntry& entry, uint32_t index, std::span<const uint8_t> raw, uint64_t fileOffset,
                      std::string& error);

}  // namespace facet::package::detail
