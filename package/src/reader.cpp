// bytes -> Package. Checks run from the outside in: header, checksum, table of contents, section
// payloads, cross-references and totals, and only then are blobs decompressed. Nothing is
// allocated on the strength of a number in the file until that number has been checked against
// the bytes that back it or against a fixed limit.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <map>
#include <new>
#include <optional>

#include "blob_codec.h"
#include "byte_io.h"
#include "checksum.h"
#include "format.h"
#include "sections.h"

namespace facet::package {

using namespace detail;

namespace {

struct TocEntry {
  uint32_t tag = 0;
  uint64_t offset = 0;
  uint64_t size = 0;
};

std::string tagName(uint32_t tag) {
  std::string s;
  for (int i = 0; i < 4; ++i) {
    char c = char(tag >> (8 * i));
    s += (c >= 0x20 && c < 0x7f) ? c : '?';
  }
  return s;
}

std::string hex(uint64_t v) {
  char buf[19];
  std::snprintf(buf, sizeof buf, "0x%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// Magic, version, declared size and checksum. After this the bytes are known to be what some
// writer produced, so later errors mean a buggy or hostile writer rather than transfer damage.
bool checkHeader(std::span<const uint8_t> file, std::string& error) {
  const uint64_t size = file.size();
  const uint64_t magicBytes = std::min<uint64_t>(size, kMagic.size());
  if (!std::equal(file.begin(), file.begin() + magicBytes, kMagic.begin())) {
    error = "not a Facet package: bad magic bytes at byte 0";
    return false;
  }
  if (size < kHeaderSize) {
    error = "package is truncated: the header needs " + std::to_string(kHeaderSize) +
            " bytes but the file has " + std::to_string(size) + " bytes";
    return false;
  }
  // The version is checked before anything else it might change the meaning of.
  const uint16_t major = uint16_t(loadLE(file.data() + kVersionOffset, 2));
  const uint16_t minor = uint16_t(loadLE(file.data() + kMinorOffset, 2));
  if (major == 0) {
    error = "package format version 0." + std::to_string(minor) + " at byte " + std::to_string(kVersionOffset) +
            " is not valid";
    return false;
  }
  if (major != kFormatMajor || minor > kFormatMinor) {
    const std::string theirs = std::to_string(major) + "." + std::to_string(minor);
    const std::string ours = std::to_string(kFormatMajor) + "." + std::to_string(kFormatMinor);
    error = "package format " + theirs + " is not supported: this reader reads formats " + std::to_string(kFormatMajor) +
            ".0 to " + ours + " (" + (major > kFormatMajor || (major == kFormatMajor && minor > kFormatMinor)
                                          ? "the package was built by a newer compiler"
                                          : "the package was built by an older, incompatible compiler") +
            "); rebuild it with this release's compiler: matc compile MATERIAL.mat -o PACKAGE.matpkg";
    return false;
  }
  uint64_t declared = loadLE(file.data() + kFileSizeOffset, 8);
  if (declared > size) {
    error = "package is truncated: the header declares " + std::to_string(declared) +
            " bytes but the file has " + std::to_string(size) + " bytes";
    return false;
  }
  if (declared < size) {
    error = "package has " + std::to_string(size - declared) + " unexpected bytes after its end at byte " +
            std::to_string(declared);
    return false;
  }
  uint64_t expected = loadLE(file.data() + kChecksumOffset, 8);
  uint64_t computed = fileChecksum(file);
  if (expected != computed) {
    error = "checksum mismatch: file is corrupt (expected " + hex(expected) + ", computed " +
            hex(computed) + ")";
    return false;
  }
  return true;
}

// Reads the table of contents and returns the four required sections in the order
// META, VARS, BTAB, BDAT, and the optional TEXS. Unknown tags are skipped so later writers can
// add sections.
bool readToc(std::span<const uint8_t> file, TocEntry (&required)[4], std::optional<TocEntry>& textures,
             std::string& error) {
  const uint64_t size = file.size();
  uint32_t count = uint32_t(loadLE(file.data() + kSectionCountOffset, 4));
  if (count > kMaxSections) {
    error = "package declares " + std::to_string(count) + " sections at byte " +
            std::to_string(kSectionCountOffset) + "; at most " + std::to_string(kMaxSections) +
            " are allowed";
    return false;
  }
  const uint64_t tocEnd = kHeaderSize + uint64_t(count) * kTocEntrySize;
  if (tocEnd > size) {
    error = "package is truncated: table of contents ends at byte " + std::to_string(tocEnd) +
            " but the file has " + std::to_string(size) + " bytes";
    return false;
  }

  std::vector<TocEntry> entries;
  entries.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    const uint64_t at = kHeaderSize + uint64_t(i) * kTocEntrySize;
    TocEntry e;
    e.tag = uint32_t(loadLE(file.data() + at, 4));
    uint32_t flags = uint32_t(loadLE(file.data() + at + 4, 4));
    e.offset = loadLE(file.data() + at + 8, 8);
    e.size = loadLE(file.data() + at + 16, 8);
    const std::string what = "section '" + tagName(e.tag) + "' (table of contents entry at byte " +
                             std::to_string(at) + ")";
    if (flags != 0) {
      error = what + " has reserved flags set";
      return false;
    }
    if (e.offset < tocEnd) {
      error = what + " starts at byte " + std::to_string(e.offset) +
              ", inside the header and table of contents which end at byte " + std::to_string(tocEnd);
      return false;
    }
    // Written as a subtraction so a huge size cannot wrap offset + size around.
    if (e.offset > size || e.size > size - e.offset) {
      error = what + " spans bytes " + std::to_string(e.offset) + " + " + std::to_string(e.size) +
              ", past the end of the file at byte " + std::to_string(size);
      return false;
    }
    entries.push_back(e);
  }

  std::vector<TocEntry> byOffset = entries;
  std::sort(byOffset.begin(), byOffset.end(),
            [](const TocEntry& a, const TocEntry& b) { return a.offset < b.offset; });
  for (size_t i = 1; i < byOffset.size(); ++i) {
    const TocEntry& prev = byOffset[i - 1];
    if (byOffset[i].offset < prev.offset + prev.size) {
      error = "section '" + tagName(byOffset[i].tag) + "' at byte " + std::to_string(byOffset[i].offset) +
              " overlaps section '" + tagName(prev.tag) + "' which ends at byte " +
              std::to_string(prev.offset + prev.size);
      return false;
    }
  }

  const uint32_t tags[4] = {kTagMeta, kTagVariants, kTagBlobTable, kTagBlobData};
  for (int t = 0; t < 4; ++t) {
    int found = 0;
    for (const TocEntry& e : entries) {
      if (e.tag == tags[t]) {
        required[t] = e;
        ++found;
      }
    }
    if (found != 1) {
      error = "package has " + std::to_string(found) + " '" + tagName(tags[t]) +
              "' sections; exactly one is required";
      return false;
    }
  }
  for (const TocEntry& e : entries) {
    if (e.tag != kTagTextures) continue;
    if (textures) {
      error = "package has more than one '" + tagName(kTagTextures) + "' section; at most one is allowed";
      return false;
    }
    textures = e;
  }
  return true;
}

bool decodeSection(std::span<const uint8_t> file, const TocEntry& e, std::string& error,
                   const auto& decode) {
  ByteReader in(file, e.offset, e.offset + e.size, tagName(e.tag));
  decode(in);
  if (!in.ok()) {
    error = in.error();
    return false;
  }
  return true;
}

ReadResult failure(std::string error) {
  ReadResult r;
  r.error = std::move(error);
  return r;
}

ReadResult readChecked(std::span<const uint8_t> file) {
  std::string error;
  if (!checkHeader(file, error)) return failure(error);
  TocEntry toc[4];
  std::optional<TocEntry> texs;
  if (!readToc(file, toc, texs, error)) return failure(error);
  const TocEntry& meta = toc[0];
  const TocEntry& vars = toc[1];
  const TocEntry& table = toc[2];
  const TocEntry& data = toc[3];

  const uint16_t minor = uint16_t(loadLE(file.data() + kMinorOffset, 2));
  Package pkg;
  std::vector<VariantEntry> variants;
  std::vector<BlobEntry> blobs;
  if (!decodeSection(file, meta, error,
                     [&](ByteReader& in) { decodeMetadata(in, pkg.compilerVersion, pkg.material); }) ||
      !decodeSection(file, vars, error, [&](ByteReader& in) { decodeVariantTable(in, variants); }) ||
      !decodeSection(file, table, error, [&](ByteReader& in) { decodeBlobTable(in, data.size, minor, blobs); }))
    return failure(error);
  std::vector<TextureEntry> textures;
  if (texs && !decodeSection(file, *texs, error, [&](ByteReader& in) {
        decodeTextureTable(in, variants.size(), blobs, textures);
      }))
    return failure(error);

  // Shared blobs are copied into every shader that uses them, so the copies are what must stay
  // bounded, not just the stored bytes.
  std::vector<std::vector<std::pair<uint32_t, uint32_t>>> users(blobs.size());
  uint64_t totalCode = 0;
  for (uint32_t v = 0; v < variants.size(); ++v) {
    for (uint32_t s = 0; s < variants[v].shaders.size(); ++s) {
      uint32_t blob = variants[v].shaders[s].blob;
      if (blob >= blobs.size())
        return failure("shader " + std::to_string(s) + " of variant '" + variants[v].key +
                       "' refers to blob " + std::to_string(blob) + " but the package has " +
                       std::to_string(blobs.size()) + " blobs");
      totalCode += blobs[blob].rawSize;
      if (totalCode > kMaxTotalCodeSize)
        return failure("variants up to '" + variants[v].key + "' hold more than " +
                       std::to_string(kMaxTotalCodeSize) + " bytes of shader code in total");
      users[blob].push_back({v, s});
    }
  }
  // Texels are copied out of their blobs like code, and count towards the same bound.
  std::vector<std::vector<uint32_t>> textureUsers(blobs.size());
  for (uint32_t t = 0; t < textures.size(); ++t) {
    totalCode += blobs[textures[t].blob].rawSize;
    if (totalCode > kMaxTotalCodeSize)
      return failure("shaders and textures up to texture '" + textures[t].name + "' hold more than " +
                     std::to_string(kMaxTotalCodeSize) + " bytes in total");
    textureUsers[textures[t].blob].push_back(t);
  }

  ReadResult result;
  pkg.variants.resize(variants.size());
  result.stats.resize(variants.size());
  for (size_t v = 0; v < variants.size(); ++v) {
    pkg.variants[v].key = std::move(variants[v].key);
    pkg.variants[v].shaders.resize(variants[v].shaders.size());
    result.stats[v].resize(variants[v].shaders.size());
    for (size_t s = 0; s < variants[v].shaders.size(); ++s) {
      const ShaderRef& ref = variants[v].shaders[s];
      pkg.variants[v].shaders[s].stage = ref.stage;
      pkg.variants[v].shaders[s].target = ref.target;
      result.stats[v][s].rawSize = blobs[ref.blob].rawSize;
    }
  }
  pkg.textures.resize(textures.size());
  result.textureStats.resize(textures.size());
  for (size_t t = 0; t < textures.size(); ++t) {
    Texture& out = pkg.textures[t];
    out.name = std::move(textures[t].name);
    out.width = textures[t].width;
    out.height = textures[t].height;
    out.format = textures[t].format;
    out.variants = std::move(textures[t].variants);
    result.textureStats[t].rawSize = blobs[textures[t].blob].rawSize;
  }

  // Dictionaries first (a dictionary is never itself dictionary-coded: decodeBlobTable), kept
  // for the blobs that name them.
  std::map<uint32_t, std::vector<uint8_t>> dictionaries;
  for (const BlobEntry& entry : blobs)
    if (entry.codec == Codec::ZstdDictionary) dictionaries.try_emplace(entry.dictionary);
  auto decode = [&](uint32_t b, std::vector<uint8_t>& raw) {
    const BlobEntry& entry = blobs[b];
    const uint64_t at = data.offset + entry.offset;
    std::span<const uint8_t> dictionary;
    if (entry.codec == Codec::ZstdDictionary) dictionary = dictionaries.at(entry.dictionary);
    return decodeBlob(entry, b, file.subspan(at, entry.storedSize), at, dictionary, raw, error);
  };
  for (auto& [d, bytes] : dictionaries) {
    if (!decode(d, bytes)) return failure(error);
    if (bytes.size() >= 4 && loadLE(bytes.data(), 4) == kZstdDictionaryMagic)
      return failure("dictionary blob " + std::to_string(d) +
                     " starts with the zstd dictionary magic; package dictionaries are raw content");
  }
  std::vector<uint8_t> raw;
  for (uint32_t b = 0; b < blobs.size(); ++b) {
    const BlobEntry& entry = blobs[b];
    if (auto it = dictionaries.find(b); it != dictionaries.end()) {
      raw = it->second;
    } else if (!decode(b, raw)) {
      return failure(error);
    }
    if (users[b].empty() && textureUsers[b].empty()) result.dictionaryStoredSize += entry.storedSize;
    // The first user is charged the stored bytes, later users share them for free, so summing
    // storedSize over all shaders gives the blob bytes actually in the file.
    for (size_t u = 0; u < users[b].size(); ++u) {
      auto [v, s] = users[b][u];
      if (u == 0) result.stats[v][s].storedSize = entry.storedSize;
      pkg.variants[v].shaders[s].code = raw;
    }
    for (size_t u = 0; u < textureUsers[b].size(); ++u) {
      uint32_t t = textureUsers[b][u];
      if (u == 0 && users[b].empty()) result.textureStats[t].storedSize = entry.storedSize;
      pkg.textures[t].texels = raw;
    }
  }

  result.formatMajor = kFormatMajor;
  result.formatMinor = minor;
  result.package = std::move(pkg);
  return result;
}

}  // namespace

ReadResult read(std::span<const uint8_t> bytes) {
  // Every size is checked before allocation, so this only fires on genuine memory exhaustion
  // within the documented limits; the contract is that no exception leaves read().
  try {
    return readChecked(bytes);
  } catch (const std::bad_alloc&) {
    return failure("out of memory while reading package (" + std::to_string(bytes.size()) + " bytes)");
  } catch (const std::exception& e) {
    return failure(std::string("internal error while reading package: ") + e.what());
  }
}

}  // namespace facet::package
