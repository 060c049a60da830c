// Compression of one blob: zstd at a fixed level, or raw when zstd does not shrink it.
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

  // Returns the codec chosen; `stored` receives the bytes to write.
  Codec encode(std::span<const uint8_t> raw, std::vector<uint8_t>& stored);

private:
  // One context reused for every blob of a package: zstd's level-19 tables are large to set up.
  std::unique_ptr<ZSTD_CCtx, size_t (*)(ZSTD_CCtx*)> context_;
};

// Decodes a blob whose entry has passed the table checks (sizes within limits, stored bytes in
// bounds). `fileOffset` is where the stored bytes start, for messages. Checks the zstd frame
// header against raw_size before allocating, and the content hash after decoding.
bool decodeBlob(const BlobEntry& entry, uint32_t index, std::span<const uint8_t> stored,
                uint64_t fileOffset, std::vector<uint8_t>& raw, std::string& error);

}  // namespace facet::package::detail
