#pragma once

#include <cstdint>
#include <span>

namespace facet::package::detail {

// XXH3_64bits of the whole file with the checksum field (bytes 24..31) read as zero, so the
// header, TOC and padding are covered too. `file` must be at least kHeaderSize bytes.
uint64_t fileChecksum(std::span<const uint8_t> file);

// XXH3_64bits of a blob's raw (decompressed) code: the deduplication key and integrity check.
uint64_t contentHash(std::span<const uint8_t> code);

}  // namespace facet::package::detail
