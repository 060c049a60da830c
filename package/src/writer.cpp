// Package -> bytes. Everything here is a pure function of the Package (and the zstd version), so
// the same input always gives the same file.
#include <algorithm>
#include <map>
#include <optional>
#include <unordered_map>

#include "blob_codec.h"
#include "byte_io.h"
#include "checksum.h"
#include "format.h"
#include "rows.h"
#include "sections.h"

namespace facet::package {

using namespace detail;

namespace {

struct Section {
  uint32_t tag;
  std::vector<uint8_t> bytes;
};

// Assigns blob indices in order of first use (variant order, then shader order), storing each
// distinct code once. Candidates are found by hash and confirmed by comparing bytes, so even a
// hash collision cannot make two shaders share the wrong code.
// `kind` is the (stage, target) a blob was first used for, or kTextureKind.
inline constexpr int kTextureKind = -1;
int shaderKind(const Shader& s) { return int(s.stage) * (kLastTarget + 1) + int(s.target); }

class BlobDeduplicator {
 public:
  uint32_t add(const std::vector<uint8_t>& code, int kind) {
    uint64_t hash = contentHash(code);
    std::vector<uint32_t>& candidates = byHash_[hash];
    for (uint32_t index : candidates) {
      if (*codes_[index] == code) return index;
    }
    uint32_t index = uint32_t(codes_.size());
    codes_.push_back(&code);
    hashes_.push_back(hash);
    kinds_.push_back(kind);
    candidates.push_back(index);
    return index;
  }

  size_t size() const { return codes_.size(); }
  const std::vector<uint8_t>& code(size_t i) const { return *codes_[i]; }
  uint64_t hash(size_t i) const { return hashes_[i]; }
  int kind(size_t i) const { return kinds_[i]; }

 private:
  std::vector<const std::vector<uint8_t>*> codes_;
  std::vector<uint64_t> hashes_;
  std::vector<int> kinds_;
  std::unordered_map<uint64_t, std::vector<uint32_t>> byHash_;
};

// The package dictionary (format 1.1): the largest shader blob of each (stage, target), first
// on ties, in kind order. Variants of one material differ in a few functions and defines, so
// every other blob of a kind is mostly a copy of its representative; compressing against it
// keeps each blob decodable on its own (it needs only the dictionary) while sharing the text.
// Measured on red_plastic's 8 variants (docs/package-format.md, "Blob data").
// Empty when it would not pay: fewer than two shader blobs.
std::vector<uint8_t> chooseDictionary(const BlobDeduplicator& blobs) {
  std::map<int, size_t> largest;
  size_t shaderBlobs = 0;
  for (size_t i = 0; i < blobs.size(); ++i) {
    if (blobs.kind(i) == kTextureKind) continue;
    ++shaderBlobs;
    auto [it, inserted] = largest.try_emplace(blobs.kind(i), i);
    if (!inserted && blobs.code(i).size() > blobs.code(it->second).size()) it->second = i;
  }
  std::vector<uint8_t> dictionary;
  if (shaderBlobs < 2) return dictionary;
  for (auto [kind, index] : largest)
    dictionary.insert(dictionary.end(), blobs.code(index).begin(), blobs.code(index).end());
  // zstd would read a dictionary starting with its own magic as a trained one, not raw content.
  if (dictionary.size() >= 4 && loadLE(dictionary.data(), 4) == kZstdDictionaryMagic) dictionary.clear();
  return dictionary;
}

}  // namespace

std::vector<uint8_t> write(const Package& pkg) {
  BlobDeduplicator blobs;
  std::vector<VariantInfo> variants;
  variants.reserve(pkg.variants.size());
  for (const Variant& v : pkg.variants)
    variants.push_back(variantRow(v, [&](const Shader& s) { return blobs.add(s.code, shaderKind(s)); }));
  // Texture blobs follow every shader's, so a package without textures is unchanged.
  std::vector<TextureInfo> textures;
  for (const Texture& t : pkg.textures) textures.push_back(textureRow(t, blobs.add(t.texels, kTextureKind)));
  // The dictionary is one more blob, after every other (or an existing blob of equal bytes).
  const std::vector<uint8_t> dictionaryBytes = chooseDictionary(blobs);
  const size_t shaderAndTextureBlobs = blobs.size();
  std::optional<uint32_t> dictionary;
  if (!dictionaryBytes.empty()) dictionary = blobs.add(dictionaryBytes, kTextureKind);

  std::vector<BlobEntry> blobTable;
  std::vector<uint8_t> blobData;
  BlobEncoder encoder;
  if (dictionary) encoder.setDictionary(dictionaryBytes);
  std::vector<uint8_t> stored;
  bool usesDictionary = false;
  for (size_t i = 0; i < blobs.size(); ++i) {
    BlobEntry b;
    b.contentHash = blobs.hash(i);
    b.offset = blobData.size();
    b.rawSize = blobs.code(i).size();
    const bool againstDictionary =
        dictionary && i != *dictionary && i < shaderAndTextureBlobs && blobs.kind(i) != kTextureKind;
    b.codec =
        againstDictionary ? encoder.encodeWithDictionary(blobs.code(i), stored) : encoder.encode(blobs.code(i), stored);
    if (b.codec == Codec::ZstdDictionary) {
      b.dictionary = *dictionary;
      usesDictionary = true;
    }
    b.storedSize = stored.size();
    blobData.insert(blobData.end(), stored.begin(), stored.end());
    blobTable.push_back(b);
  }

  // META, VARS, [TEXS], [MSLB], [PRSH], BTAB, BDAT. TEXS, MSLB and PRSH exist only when not
  // empty, so packages without them keep their earlier bytes.
  std::vector<Section> sections;
  auto section = [&](uint32_t tag, const auto& encode) {
    sections.push_back({tag, {}});
    ByteWriter out(sections.back().bytes);
    encode(out);
  };
  section(kTagMeta, [&](ByteWriter& out) { encodeMetadata(out, pkg.compilerVersion, pkg.material); });
  section(kTagVariants, [&](ByteWriter& out) { encodeVariantTable(out, variants); });
  if (!textures.empty()) section(kTagTextures, [&](ByteWriter& out) { encodeTextureTable(out, textures); });
  if (!pkg.mslBindings.empty())
    section(kTagMslBindings, [&](ByteWriter& out) { encodeMslBindings(out, pkg.mslBindings); });
  const bool preshaded = !pkg.preshader.programs.empty();
  if (preshaded) section(kTagPreshader, [&](ByteWriter& out) { encodePreshader(out, pkg.preshader); });
  section(kTagBlobTable, [&](ByteWriter& out) { encodeBlobTable(out, blobTable); });
  sections.push_back({kTagBlobData, std::move(blobData)});

  std::vector<uint8_t> file;
  ByteWriter out(file);
  out.bytes(kMagic);
  out.u16(kFormatMajor);
  // The lowest minor that describes the file. Shaders reading instance transforms: 1.6; the two
  // packed vertex streams: 1.5, and a lit material's shaders sample the environment as a cube map: 1.4, so that an
  // older runtime (which binds one fp32 stream, or an octahedral map) refuses the file instead
  // of drawing it wrong.
  // Depth-only programs: 1.7, so that a runtime without the shadow pass does not take a
  // `<tier>.depth` variant for a key it cannot parse.
  const bool depthPrograms =
      std::any_of(pkg.variants.begin(), pkg.variants.end(), [](const Variant& v) { return isDepthProgramKey(v.key); });
  // The preshader's div and sqrt: 1.8, so that a runtime without them refuses the file by its
  // version rather than by an op it does not know.
  const bool preshaderDivision = std::any_of(pkg.preshader.programs.begin(), pkg.preshader.programs.end(),
                                             [](const PreshaderProgram& p) { return usesPreshaderDivision(p.ops); });
  out.u16(preshaderDivision               ? kFirstMinorWithPreshaderDivision
          : depthPrograms                 ? kFirstMinorWithDepthPrograms
          : pkg.instanceTransforms        ? kFirstMinorWithInstanceTransforms
          : pkg.packedVertices            ? kFirstMinorWithPackedVertices
          : pkg.material.shading == "lit" ? kFirstMinorWithCubeEnvironment
          : preshaded                     ? kFirstMinorWithPreshader
          : !pkg.mslBindings.empty()      ? kFirstMinorWithMslBindings
          : usesDictionary                ? kFirstMinorWithDictionary
                                          : 0);
  out.u32(uint32_t(sections.size()));
  out.u64(0);  // file size, patched below
  out.u64(0);  // checksum, patched below

  uint64_t offset = kHeaderSize + sections.size() * kTocEntrySize;
  for (const Section& s : sections) {
    offset = (offset + kSectionAlignment - 1) / kSectionAlignment * kSectionAlignment;
    out.u32(s.tag);
    out.u32(0);
    out.u64(offset);
    out.u64(s.bytes.size());
    offset += s.bytes.size();
  }
  for (const Section& s : sections) {
    out.padTo(kSectionAlignment);
    out.bytes(s.bytes);
  }

  storeLE(file.data() + kFileSizeOffset, file.size(), 8);
  storeLE(file.data() + kChecksumOffset, fileChecksum(file), 8);
  return file;
}

}  // namespace facet::package
