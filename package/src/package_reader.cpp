// bytes -> PackageReader. Checks run from the outside in: header, checksum, table of contents,
// section payloads, cross-references; blobs are decoded only when first asked for. Nothing is
// allocated on the strength of a number in the file until that number has been checked against
// the bytes that back it or against a fixed limit.
#include "facet/package/package_reader.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <map>
#include <mutex>
#include <new>

#include "blob_codec.h"
#include "byte_io.h"
#include "checksum.h"
#include "file_io.h"
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
    error = "package is truncated: the header needs " + std::to_string(kHeaderSize) + " bytes but the file has " +
            std::to_string(size) + " bytes";
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
    error = "package format " + theirs + " is not supported: this reader reads formats " +
            std::to_string(kFormatMajor) + ".0 to " + ours + " (" +
            (major > kFormatMajor || (major == kFormatMajor && minor > kFormatMinor)
                 ? "the package was built by a newer compiler"
                 : "the package was built by an older, incompatible compiler") +
            "); rebuild it with this release's compiler: matc compile MATERIAL.mat -o PACKAGE.matpkg";
    return false;
  }
  uint64_t declared = loadLE(file.data() + kFileSizeOffset, 8);
  if (declared > size) {
    error = "package is truncated: the header declares " + std::to_string(declared) + " bytes but the file has " +
            std::to_string(size) + " bytes";
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
    error = "checksum mismatch: file is corrupt (expected " + hex(expected) + ", computed " + hex(computed) + ")";
    return false;
  }
  return true;
}

// Sections (sorted by offset, not overlapping) follow the table of contents as the writer lays
// them out: each at the first 8-byte boundary after the one before, the gap zero, the last one
// ending the file. The checksum only proves that some writer made the bytes; without this a
// hostile one could carry data in padding or after the last section that every check skips.
bool checkSectionTiling(std::span<const uint8_t> file, uint64_t tocEnd, const std::vector<TocEntry>& byOffset,
                        std::string& error) {
  uint64_t end = tocEnd;
  std::string before = "the table of contents";
  for (const TocEntry& e : byOffset) {
    const uint64_t expected = (end + kSectionAlignment - 1) / kSectionAlignment * kSectionAlignment;
    if (e.offset != expected) {
      error = "section '" + tagName(e.tag) + "' starts at byte " + std::to_string(e.offset) + ", but " + before +
              " ends at byte " + std::to_string(end) + ": the next section starts at byte " + std::to_string(expected) +
              " (the next " + std::to_string(kSectionAlignment) + "-byte boundary)";
      return false;
    }
    for (uint64_t at = end; at < e.offset; ++at) {
      if (file[at] != 0) {
        error = "padding byte " + std::to_string(at) + " before section '" + tagName(e.tag) + "' is " +
                std::to_string(file[at]) + ", not zero";
        return false;
      }
    }
    end = e.offset + e.size;
    before = "section '" + tagName(e.tag) + "'";
  }
  if (end != file.size()) {
    error = "package has " + std::to_string(file.size() - end) + " bytes after its last section, which ends at byte " +
            std::to_string(end);
    return false;
  }
  return true;
}

// Reads the table of contents and returns the four required sections in the order
// META, VARS, BTAB, BDAT, and the optional TEXS. Unknown tags are skipped so later writers can
// add sections.
bool readToc(std::span<const uint8_t> file, TocEntry (&required)[4], std::optional<TocEntry>& textures,
             std::optional<TocEntry>& mslBindings, std::optional<TocEntry>& preshader, std::string& error) {
  const uint64_t size = file.size();
  uint32_t count = uint32_t(loadLE(file.data() + kSectionCountOffset, 4));
  if (count > kMaxSections) {
    error = "package declares " + std::to_string(count) + " sections at byte " + std::to_string(kSectionCountOffset) +
            "; at most " + std::to_string(kMaxSections) + " are allowed";
    return false;
  }
  const uint64_t tocEnd = kHeaderSize + uint64_t(count) * kTocEntrySize;
  if (tocEnd > size) {
    error = "package is truncated: table of contents ends at byte " + std::to_string(tocEnd) + " but the file has " +
            std::to_string(size) + " bytes";
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
    const std::string what =
        "section '" + tagName(e.tag) + "' (table of contents entry at byte " + std::to_string(at) + ")";
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
  std::sort(byOffset.begin(), byOffset.end(), [](const TocEntry& a, const TocEntry& b) { return a.offset < b.offset; });
  for (size_t i = 1; i < byOffset.size(); ++i) {
    const TocEntry& prev = byOffset[i - 1];
    if (byOffset[i].offset < prev.offset + prev.size) {
      error = "section '" + tagName(byOffset[i].tag) + "' at byte " + std::to_string(byOffset[i].offset) +
              " overlaps section '" + tagName(prev.tag) + "' which ends at byte " +
              std::to_string(prev.offset + prev.size);
      return false;
    }
  }
  if (!checkSectionTiling(file, tocEnd, byOffset, error)) return false;

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
      error = "package has " + std::to_string(found) + " '" + tagName(tags[t]) + "' sections; exactly one is required";
      return false;
    }
  }
  for (const TocEntry& e : entries) {
    std::optional<TocEntry>* optional = e.tag == kTagTextures      ? &textures
                                        : e.tag == kTagMslBindings ? &mslBindings
                                        : e.tag == kTagPreshader   ? &preshader
                                                                   : nullptr;
    if (!optional) continue;
    if (*optional) {
      error = "package has more than one '" + tagName(e.tag) + "' section; at most one is allowed";
      return false;
    }
    *optional = e;
  }
  return true;
}

bool decodeSection(std::span<const uint8_t> file, const TocEntry& e, std::string& error, const auto& decode) {
  ByteReader in(file, e.offset, e.offset + e.size, tagName(e.tag));
  decode(in);
  if (!in.ok()) {
    error = in.error();
    return false;
  }
  return true;
}

}  // namespace

struct PackageReader::State {
  std::vector<uint8_t> owned;  // openFile's copy of the file; empty for open()
  std::span<const uint8_t> file;
  uint16_t minor = 0;
  std::string compilerVersion;
  MaterialInfo material;
  std::vector<VariantInfo> variants;
  std::vector<TextureInfo> textures;
  std::vector<MslBinding> mslBindings;
  Preshader preshader;
  std::vector<BlobEntry> entries;
  std::vector<BlobInfo> blobs;
  uint64_t dataOffset = 0;  // BDAT's offset in the file

  // Decoded on demand, under the mutex: compressed blobs' raw bytes, raw blobs whose content
  // hash has been checked (their bytes are the input's).
  mutable std::mutex mutex;
  mutable std::map<uint32_t, std::vector<uint8_t>> decoded;
  mutable std::vector<bool> hashChecked;
  mutable uint64_t bytesDecompressed = 0;

  bool parse(std::string& error);
  std::optional<std::span<const uint8_t>> blobLocked(uint32_t b, std::string& error) const;
};

bool PackageReader::State::parse(std::string& error) {
  if (!checkHeader(file, error)) return false;
  TocEntry toc[4];
  std::optional<TocEntry> texs, mslb, prsh;
  if (!readToc(file, toc, texs, mslb, prsh, error)) return false;
  const TocEntry& meta = toc[0];
  const TocEntry& vars = toc[1];
  const TocEntry& table = toc[2];
  const TocEntry& data = toc[3];
  minor = uint16_t(loadLE(file.data() + kMinorOffset, 2));
  dataOffset = data.offset;

  if (!decodeSection(file, meta, error, [&](ByteReader& in) { decodeMetadata(in, compilerVersion, material); }) ||
      !decodeSection(file, vars, error, [&](ByteReader& in) { decodeVariantTable(in, variants); }) ||
      !decodeSection(file, table, error, [&](ByteReader& in) { decodeBlobTable(in, data.size, minor, entries); }))
    return false;
  // A depth-only program (format 1.7) in an older package: no writer of that version made it.
  if (minor < kFirstMinorWithDepthPrograms)
    for (const VariantInfo& v : variants)
      if (isDepthProgramKey(v.key)) {
        error = "package format 1." + std::to_string(minor) + " has variant '" + v.key +
                "', a depth-only program, which only format 1." + std::to_string(kFirstMinorWithDepthPrograms) +
                " and later have";
        return false;
      }
  if (texs && !decodeSection(file, *texs, error,
                             [&](ByteReader& in) { decodeTextureTable(in, variants.size(), entries, textures); }))
    return false;
  if (mslb) {
    if (minor < kFirstMinorWithMslBindings) {
      error = "package format 1." + std::to_string(minor) + " has a '" + tagName(kTagMslBindings) +
              "' section, which only format 1." + std::to_string(kFirstMinorWithMslBindings) + " and later have";
      return false;
    }
    if (!decodeSection(file, *mslb, error, [&](ByteReader& in) { decodeMslBindings(in, mslBindings); })) return false;
  }
  if (prsh) {
    if (minor < kFirstMinorWithPreshader) {
      error = "package format 1." + std::to_string(minor) + " has a '" + tagName(kTagPreshader) +
              "' section, which only format 1." + std::to_string(kFirstMinorWithPreshader) + " and later have";
      return false;
    }
    if (!decodeSection(file, *prsh, error, [&](ByteReader& in) { decodePreshader(in, variants.size(), preshader); }))
      return false;
    if (minor < kFirstMinorWithPreshaderDivision)
      for (const PreshaderProgram& program : preshader.programs)
        if (usesPreshaderDivision(program.ops)) {
          error = "package format 1." + std::to_string(minor) +
                  " has a preshader program with a div or sqrt op, which only format 1." +
                  std::to_string(kFirstMinorWithPreshaderDivision) + " and later have";
          return false;
        }
  }

  for (const VariantInfo& v : variants) {
    for (uint32_t s = 0; s < v.shaders.size(); ++s) {
      const ShaderInfo& ref = v.shaders[s];
      if (ref.blob >= entries.size()) {
        error = "shader " + std::to_string(s) + " of variant '" + v.key + "' refers to blob " +
                std::to_string(ref.blob) + " but the package has " + std::to_string(entries.size()) + " blobs";
        return false;
      }
    }
  }
  blobs.reserve(entries.size());
  for (const BlobEntry& e : entries) blobs.push_back({e.rawSize, e.storedSize, e.codec != Codec::Raw});
  hashChecked.assign(entries.size(), false);
  return true;
}

std::optional<std::span<const uint8_t>> PackageReader::State::blobLocked(uint32_t b, std::string& error) const {
  if (b >= entries.size()) {
    error =
        "blob " + std::to_string(b) + " does not exist; the package has " + std::to_string(entries.size()) + " blobs";
    return std::nullopt;
  }
  const BlobEntry& entry = entries[b];
  const uint64_t at = dataOffset + entry.offset;
  const std::span<const uint8_t> stored = file.subspan(at, entry.storedSize);
  if (entry.codec == Codec::Raw) {
    if (!hashChecked[b]) {
      if (!checkContentHash(entry, b, stored, at, error)) return std::nullopt;
      hashChecked[b] = true;
    }
    return stored;
  }
  if (auto it = decoded.find(b); it != decoded.end()) return std::span<const uint8_t>(it->second);
  std::span<const uint8_t> dictionary;
  if (entry.codec == Codec::ZstdDictionary) {
    // decodeBlobTable refused chains, so this recursion is one level deep.
    auto d = blobLocked(entry.dictionary, error);
    if (!d) return std::nullopt;
    if (d->size() >= 4 && loadLE(d->data(), 4) == kZstdDictionaryMagic) {
      error = "dictionary blob " + std::to_string(entry.dictionary) +
              " starts with the zstd dictionary magic; package dictionaries are raw content";
      return std::nullopt;
    }
    dictionary = *d;
  }
  std::vector<uint8_t> raw;
  if (!decodeBlob(entry, b, stored, at, dictionary, raw, error)) return std::nullopt;
  bytesDecompressed += raw.size();
  return std::span<const uint8_t>(decoded.emplace(b, std::move(raw)).first->second);
}

PackageReader::PackageReader(std::unique_ptr<State> state) : state_(std::move(state)) {}
PackageReader::PackageReader(PackageReader&&) noexcept = default;
PackageReader& PackageReader::operator=(PackageReader&&) noexcept = default;
PackageReader::~PackageReader() = default;

std::optional<PackageReader> PackageReader::open(std::span<const uint8_t> bytes, std::string* error) {
  // Every size is checked before allocation, so this only fires on genuine memory exhaustion
  // within the documented limits; the contract is that no exception leaves the reader.
  try {
    auto state = std::make_unique<State>();
    state->file = bytes;
    if (!state->parse(*error)) return std::nullopt;
    return PackageReader(std::move(state));
  } catch (const std::bad_alloc&) {
    *error = "out of memory while reading package (" + std::to_string(bytes.size()) + " bytes)";
  } catch (const std::exception& e) {
    *error = std::string("internal error while reading package: ") + e.what();
  }
  return std::nullopt;
}

std::optional<PackageReader> PackageReader::openFile(const std::string& path, std::string* error) {
  std::vector<uint8_t> bytes;
  if (!readWholeFile(path, bytes, *error)) return std::nullopt;
  std::optional<PackageReader> reader = open(bytes, error);
  if (reader) {
    // The span keeps pointing at the same heap block after the move.
    reader->state_->owned = std::move(bytes);
    reader->state_->file = reader->state_->owned;
  }
  return reader;
}

uint16_t PackageReader::formatMajor() const { return kFormatMajor; }
uint16_t PackageReader::formatMinor() const { return state_->minor; }
const std::string& PackageReader::compilerVersion() const { return state_->compilerVersion; }
const MaterialInfo& PackageReader::material() const { return state_->material; }
const std::vector<VariantInfo>& PackageReader::variants() const { return state_->variants; }
const std::vector<TextureInfo>& PackageReader::textures() const { return state_->textures; }
const std::vector<BlobInfo>& PackageReader::blobs() const { return state_->blobs; }
const std::vector<MslBinding>& PackageReader::mslBindings() const { return state_->mslBindings; }
const Preshader& PackageReader::preshader() const { return state_->preshader; }

const PreshaderProgram* PackageReader::preshaderProgram(std::string_view key) const {
  for (const PreshaderProgram& p : state_->preshader.programs)
    for (uint32_t v : p.variants)
      if (state_->variants[v].key == key) return &p;
  return nullptr;
}

const Param* PackageReader::findParam(std::string_view name) const {
  for (const Param& p : state_->material.params)
    if (p.name == name) return &p;
  return nullptr;
}

const VariantInfo* PackageReader::findVariant(std::string_view key) const {
  for (const VariantInfo& v : state_->variants)
    if (v.key == key) return &v;
  return nullptr;
}

std::string PackageReader::semanticError() const {
  return package::semanticError(state_->material, state_->variants, state_->preshader, state_->mslBindings);
}

std::optional<std::span<const uint8_t>> PackageReader::blob(uint32_t index, std::string* error) const {
  try {
    std::lock_guard lock(state_->mutex);
    return state_->blobLocked(index, *error);
  } catch (const std::bad_alloc&) {
    *error = "out of memory while decoding blob " + std::to_string(index);
  }
  return std::nullopt;
}

std::optional<std::span<const uint8_t>> PackageReader::shader(std::string_view key, Stage stage, Target target,
                                                              std::string* error) const {
  const VariantInfo* v = findVariant(key);
  if (!v) {
    *error = "the package has no variant '" + std::string(key) + "'";
    return std::nullopt;
  }
  for (const ShaderInfo& s : v->shaders)
    if (s.stage == stage && s.target == target) return blob(s.blob, error);
  *error = "variant '" + v->key + "' has no " + toString(stage) + " " + toString(target) + " shader";
  return std::nullopt;
}

std::optional<std::span<const uint8_t>> PackageReader::texels(size_t index, std::string* error) const {
  if (index >= state_->textures.size()) {
    *error = "texture " + std::to_string(index) + " does not exist; the package has " +
             std::to_string(state_->textures.size()) + " textures";
    return std::nullopt;
  }
  return blob(state_->textures[index].blob, error);
}

uint64_t PackageReader::bytesDecompressed() const {
  std::lock_guard lock(state_->mutex);
  return state_->bytesDecompressed;
}

}  // namespace facet::package
