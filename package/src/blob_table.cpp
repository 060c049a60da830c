// BTAB section: where each blob's bytes are in BDAT, how they are encoded, and their hash.
#include "sections.h"

namespace facet::package::detail {

void encodeBlobTable(ByteWriter& out, const std::vector<BlobEntry>& blobs) {
  out.u32(uint32_t(blobs.size()));
  for (const BlobEntry& b : blobs) {
    out.u64(b.contentHash);
    out.u64(b.offset);
    out.u64(b.storedSize);
    out.u64(b.rawSize);
    out.u32(uint32_t(b.codec));
    out.u32(b.dictionary);
  }
}

void decodeBlobTable(ByteReader& in, uint64_t dataSize, uint16_t minor, std::vector<BlobEntry>& blobs) {
  uint32_t count = in.count(kBlobEntrySize, "blob count");
  blobs.reserve(count);
  // Blobs must tile BDAT in order with no gap or overlap: then every stored byte belongs to
  // exactly one blob, and the work of decoding is bounded by the file size.
  uint64_t expectedOffset = 0;
  uint64_t totalRaw = 0;
  for (uint32_t i = 0; i < count && in.ok(); ++i) {
    uint64_t at = in.position();
    BlobEntry b;
    b.contentHash = in.u64();
    b.offset = in.u64();
    b.storedSize = in.u64();
    b.rawSize = in.u64();
    uint32_t codec = in.u32();
    b.dictionary = in.u32();
    if (!in.ok()) return;
    const std::string what = "blob " + std::to_string(i) + " (table entry at byte " + std::to_string(at) + ")";
    if (codec > uint32_t(Codec::ZstdDictionary)) return in.fail(what + " has unknown codec " + std::to_string(codec));
    b.codec = Codec(codec);
    if (b.codec == Codec::ZstdDictionary && minor < kFirstMinorWithDictionary)
      return in.fail(what + " is compressed against a dictionary, which format 1." + std::to_string(minor) +
                     " does not have");
    if (b.codec != Codec::ZstdDictionary && b.dictionary != 0)
      return in.fail(what + " names a dictionary but its codec does not use one");
    if (b.offset != expectedOffset)
      return in.fail(what + " starts at data offset " + std::to_string(b.offset) + ", expected " +
                     std::to_string(expectedOffset));
    if (b.storedSize > dataSize - b.offset)
      return in.fail(what + " has " + std::to_string(b.storedSize) + " stored bytes at data offset " +
                     std::to_string(b.offset) + " but the blob data section has " + std::to_string(dataSize) +
                     " bytes");
    if (b.rawSize > kMaxBlobRawSize)
      return in.fail(what + " claims a raw size of " + std::to_string(b.rawSize) + " bytes, more than the limit of " +
                     std::to_string(kMaxBlobRawSize));
    if (b.codec == Codec::Raw && b.storedSize != b.rawSize)
      return in.fail(what + " is stored raw but its stored size " + std::to_string(b.storedSize) +
                     " differs from its raw size " + std::to_string(b.rawSize));
    // The writer stores raw whenever zstd does not shrink the code.
    if (b.codec != Codec::Raw && b.storedSize >= b.rawSize)
      return in.fail(what + " is zstd-compressed but not smaller than its raw size");
    totalRaw += b.rawSize;
    if (totalRaw > kMaxTotalCodeSize)
      return in.fail("blobs up to " + what + " hold more than " + std::to_string(kMaxTotalCodeSize) +
                     " bytes of code in total");
    expectedOffset = b.offset + b.storedSize;
    blobs.push_back(b);
  }
  // A dictionary is itself decodable alone: no chains, no cycles.
  for (uint32_t i = 0; i < blobs.size() && in.ok(); ++i) {
    if (blobs[i].codec != Codec::ZstdDictionary) continue;
    const uint32_t d = blobs[i].dictionary;
    if (d >= blobs.size())
      return in.fail("blob " + std::to_string(i) + " names dictionary blob " + std::to_string(d) +
                     " but the package has " + std::to_string(blobs.size()) + " blobs");
    if (blobs[d].codec == Codec::ZstdDictionary)
      return in.fail("blob " + std::to_string(i) + " names dictionary blob " + std::to_string(d) +
                     ", which is itself compressed against a dictionary");
  }
  in.expectEnd();
  if (in.ok() && expectedOffset != dataSize)
    in.fail("blob data section has " + std::to_string(dataSize - expectedOffset) + " bytes not covered by any blob");
}

}  // namespace facet::package::detail
