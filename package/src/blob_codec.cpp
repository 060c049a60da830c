#include "blob_codec.h"

#include <cstdio>
#include <memory>
#include <new>

#include "checksum.h"

namespace facet::package::detail {

namespace {

std::string hex(uint64_t v) {
  char buf[19];
  std::snprintf(buf, sizeof buf, "0x%016llx", static_cast<unsigned long long>(v));
  return buf;
}

}  // namespace

BlobEncoder::BlobEncoder()
    : context_(ZSTD_createCCtx(), &ZSTD_freeCCtx), dictionaryContext_(ZSTD_createCCtx(), &ZSTD_freeCCtx) {
  if (!context_ || !dictionaryContext_) throw std::bad_alloc();
}

void BlobEncoder::setDictionary(std::span<const uint8_t> dictionary) {
  ZSTD_CCtx* c = dictionaryContext_.get();
  ZSTD_CCtx_reset(c, ZSTD_reset_session_and_parameters);
  ZSTD_CCtx_setParameter(c, ZSTD_c_compressionLevel, kZstdLevel);
  // Content size in the frame header (the reader checks it), no zstd checksum (the content hash
  // covers the code), no dictionary ID (a raw-content dictionary has none).
  ZSTD_CCtx_setParameter(c, ZSTD_c_contentSizeFlag, 1);
  ZSTD_CCtx_setParameter(c, ZSTD_c_checksumFlag, 0);
  // Sticky: zstd builds the dictionary's tables once and reuses them for every frame. Loaded as
  // raw content because it does not start with kZstdDictionaryMagic (the writer makes sure).
  ZSTD_CCtx_loadDictionary(c, dictionary.data(), dictionary.size());
}

Codec BlobEncoder::encodeWithDictionary(std::span<const uint8_t> raw, std::vector<uint8_t>& stored) {
  stored.resize(ZSTD_compressBound(raw.size()));
  size_t n = ZSTD_compress2(dictionaryContext_.get(), stored.data(), stored.size(), raw.data(), raw.size());
  if (!ZSTD_isError(n) && n < raw.size()) {
    stored.resize(n);
    return Codec::ZstdDictionary;
  }
  stored.assign(raw.begin(), raw.end());
  return Codec::Raw;
}

Codec BlobEncoder::encode(std::span<const uint8_t> raw, std::vector<uint8_t>& stored) {
  stored.resize(ZSTD_compressBound(raw.size()));
  // ZSTD_compressCCtx writes the content size into the frame header (the reader checks it
  // against raw_size) and no zstd checksum (the content hash already covers the code).
  size_t n = ZSTD_compressCCtx(context_.get(), stored.data(), stored.size(), raw.data(), raw.size(), kZstdLevel);
  if (!ZSTD_isError(n) && n < raw.size()) {
    stored.resize(n);
    return Codec::Zstd;
  }
  stored.assign(raw.begin(), raw.end());
  return Codec::Raw;
}

bool decodeBlob(const BlobEntry& entry, uint32_t index, std::span<const uint8_t> stored, uint64_t fileOffset,
                std::span<const uint8_t> dictionary, std::vector<uint8_t>& raw, std::string& error) {
  const std::string where = "blob " + std::to_string(index) + " at byte " + std::to_string(fileOffset);
  if (entry.codec == Codec::Raw) {
    raw.assign(stored.begin(), stored.end());
  } else {
    // Exactly one frame, declaring exactly raw_size bytes: the declared size is what we allocate,
    // and it has already been checked against the limits.
    size_t frameSize = ZSTD_findFrameCompressedSize(stored.data(), stored.size());
    if (ZSTD_isError(frameSize) || frameSize != stored.size()) {
      error = where + " is not a single complete zstd frame";
      return false;
    }
    unsigned long long declared = ZSTD_getFrameContentSize(stored.data(), stored.size());
    if (declared == ZSTD_CONTENTSIZE_UNKNOWN || declared == ZSTD_CONTENTSIZE_ERROR) {
      error = where + " has a zstd frame without a content size";
      return false;
    }
    if (declared != entry.rawSize) {
      error = where + " has a zstd frame of " + std::to_string(declared) + " bytes but the blob table says " +
              std::to_string(entry.rawSize);
      return false;
    }
    raw.resize(entry.rawSize);
    size_t n = 0;
    if (entry.codec == Codec::ZstdDictionary) {
      std::unique_ptr<ZSTD_DCtx, size_t (*)(ZSTD_DCtx*)> context(ZSTD_createDCtx(), &ZSTD_freeDCtx);
      if (!context) throw std::bad_alloc();
      n = ZSTD_decompress_usingDict(context.get(), raw.data(), raw.size(), stored.data(), stored.size(),
                                    dictionary.data(), dictionary.size());
    } else {
      n = ZSTD_decompress(raw.data(), raw.size(), stored.data(), stored.size());
    }
    if (ZSTD_isError(n) || n != entry.rawSize) {
      error = where + " does not decompress: " + (ZSTD_isError(n) ? ZSTD_getErrorName(n) : "wrong decompressed size");
      return false;
    }
  }
  return checkContentHash(entry, index, raw, fileOffset, error);
}

bool checkContentHash(const BlobEntry& entry, uint32_t index, std::span<const uint8_t> raw, uint64_t fileOffset,
                      std::string& error) {
  uint64_t computed = contentHash(raw);
  if (computed != entry.contentHash) {
    error = "blob " + std::to_string(index) + " at byte " + std::to_string(fileOffset) +
            " content hash mismatch (expected " + hex(entry.contentHash) + ", computed " + hex(computed) + ")";
    return false;
  }
  return true;
}

}  // namespace facet::package::detail
