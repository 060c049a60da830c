#include "facet/texture/ktx2.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace facet::texture {
namespace {

constexpr std::array<uint8_t, 12> kIdentifier = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
constexpr size_t kHeaderBytes = 80;      // identifier, header and index (specification section 3)
constexpr size_t kLevelIndexEntry = 24;  // byteOffset, byteLength, uncompressedByteLength
constexpr uint32_t kRgba8Unorm = 37, kRgba8Srgb = 43;

// Khronos Data Format Specification 1.3: the values of the basic descriptor block used here.
constexpr uint8_t kModelRgbsda = 1, kModelAstc = 162;
constexpr uint8_t kPrimariesBt709 = 1;
constexpr uint8_t kTransferLinear = 1, kTransferSrgb = 2;
constexpr uint8_t kChannelAlpha = 15, kQualifierLinear = 0x10;
constexpr size_t kDfdPrimariesByte = 4 + 8 + 1;  // dfdTotalSize, block header, colorModel

constexpr Ktx2Format kFormats[] = {
    {kRgba8Unorm, "VK_FORMAT_R8G8B8A8_UNORM", 1, 1, 4, false, false},
    {kRgba8Srgb, "VK_FORMAT_R8G8B8A8_SRGB", 1, 1, 4, false, true},
    {157, "VK_FORMAT_ASTC_4x4_UNORM_BLOCK", 4, 4, 16, true, false},
    {158, "VK_FORMAT_ASTC_4x4_SRGB_BLOCK", 4, 4, 16, true, true},
    {161, "VK_FORMAT_ASTC_5x5_UNORM_BLOCK", 5, 5, 16, true, false},
    {162, "VK_FORMAT_ASTC_5x5_SRGB_BLOCK", 5, 5, 16, true, true},
    {165, "VK_FORMAT_ASTC_6x6_UNORM_BLOCK", 6, 6, 16, true, false},
    {166, "VK_FORMAT_ASTC_6x6_SRGB_BLOCK", 6, 6, 16, true, true},
    {171, "VK_FORMAT_ASTC_8x8_UNORM_BLOCK", 8, 8, 16, true, false},
    {172, "VK_FORMAT_ASTC_8x8_SRGB_BLOCK", 8, 8, 16, true, true},
};

void put32(std::vector<uint8_t>* out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out->push_back(uint8_t(v >> (8 * i)));
}
void put64(std::vector<uint8_t>* out, uint64_t v) {
  for (int i = 0; i < 8; ++i) out->push_back(uint8_t(v >> (8 * i)));
}
void set64(std::vector<uint8_t>* out, size_t at, uint64_t v) {
  for (int i = 0; i < 8; ++i) (*out)[at + size_t(i)] = uint8_t(v >> (8 * i));
}
uint32_t get32(std::span<const uint8_t> b, size_t at) {
  return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
}
uint64_t get64(std::span<const uint8_t> b, size_t at) {
  return uint64_t(get32(b, at)) | uint64_t(get32(b, at + 4)) << 32;
}

uint64_t alignUp(uint64_t v, uint64_t a) { return (v + a - 1) / a * a; }

// Level data is aligned to lcm(texel block size, 4) (specification section 3.8, mipPadding).
uint64_t levelAlignment(const Ktx2Format& f) { return f.blockBytes % 4 == 0 ? f.blockBytes : f.blockBytes * 4; }

uint32_t fullChainLength(uint32_t width, uint32_t height) {
  uint32_t levels = 1;
  for (uint32_t size = std::max(width, height); size > 1; size >>= 1) ++levels;
  return levels;
}

uint32_t levelExtent(uint32_t size, size_t level) { return std::max(1u, size >> level); }

// The DFD the specification gives for the vkFormat: a basic block, one sample per channel for
// RGBA8 (alpha linear even in the sRGB format), one 128-bit ASTC_DATA sample for ASTC.
std::vector<uint8_t> expectedDfd(const Ktx2Format& f) {
  const uint32_t samples = f.astc ? 1 : 4;
  const uint32_t blockSize = 24 + 16 * samples;
  std::vector<uint8_t> d;
  put32(&d, 4 + blockSize);  // dfdTotalSize
  put32(&d, 0);              // vendorId KHRONOS, descriptorType BASICFORMAT
  d.push_back(2);            // versionNumber 2 (KDF 1.3), little-endian u16
  d.push_back(0);
  d.push_back(uint8_t(blockSize));
  d.push_back(uint8_t(blockSize >> 8));
  d.push_back(f.astc ? kModelAstc : kModelRgbsda);
  d.push_back(kPrimariesBt709);
  d.push_back(f.srgb ? kTransferSrgb : kTransferLinear);
  d.push_back(0);  // flags: straight alpha
  d.push_back(uint8_t(f.blockWidth - 1));
  d.push_back(uint8_t(f.blockHeight - 1));
  d.push_back(0);
  d.push_back(0);
  d.push_back(uint8_t(f.blockBytes));  // bytesPlane0
  for (int i = 1; i < 8; ++i) d.push_back(0);
  auto sample = [&](uint16_t bitOffset, uint8_t bitLengthMinus1, uint8_t channel, uint32_t upper) {
    d.push_back(uint8_t(bitOffset));
    d.push_back(uint8_t(bitOffset >> 8));
    d.push_back(bitLengthMinus1);
    d.push_back(channel);
    for (int i = 0; i < 4; ++i) d.push_back(0);  // samplePosition
    put32(&d, 0);                                // sampleLower
    put32(&d, upper);
  };
  if (f.astc) {
    sample(0, 127, 0, 0xFFFFFFFFu);
  } else {
    for (uint8_t c = 0; c < 4; ++c) {
      const uint8_t channel = c == 3 ? uint8_t(kChannelAlpha | (f.srgb ? kQualifierLinear : 0)) : c;
      sample(uint16_t(8 * c), 7, channel, 255);
    }
  }
  return d;
}

// The key/value data Facet writes: the orientation (row 0 is the top) and the writer, sorted by
// key as the specification requires.
std::vector<uint8_t> keyValueData() {
  std::vector<uint8_t> kvd;
  for (const auto& [key, value] :
       {std::pair<const char*, const char*>{"KTXorientation", "rd"}, {"KTXwriter", "Facet"}}) {
    const size_t length = std::strlen(key) + 1 + std::strlen(value) + 1;
    put32(&kvd, uint32_t(length));
    kvd.insert(kvd.end(), key, key + std::strlen(key) + 1);
    kvd.insert(kvd.end(), value, value + std::strlen(value) + 1);
    kvd.resize(alignUp(kvd.size(), 4), 0);
  }
  return kvd;
}

}  // namespace

std::span<const Ktx2Format> ktx2Formats() { return kFormats; }

const Ktx2Format* findKtx2Format(uint32_t vkFormat) {
  for (const Ktx2Format& f : kFormats)
    if (f.vkFormat == vkFormat) return &f;
  return nullptr;
}

const Ktx2Format* findAstcFormat(uint32_t blockWidth, uint32_t blockHeight, bool srgb) {
  for (const Ktx2Format& f : kFormats)
    if (f.astc && f.blockWidth == blockWidth && f.blockHeight == blockHeight && f.srgb == srgb) return &f;
  return nullptr;
}

uint64_t ktx2LevelBytes(const Ktx2Format& f, uint32_t width, uint32_t height) {
  const uint64_t blocksX = (uint64_t(width) + f.blockWidth - 1) / f.blockWidth;
  const uint64_t blocksY = (uint64_t(height) + f.blockHeight - 1) / f.blockHeight;
  return blocksX * blocksY * f.blockBytes;
}

bool isKtx2(std::span<const uint8_t> bytes) {
  return bytes.size() >= kIdentifier.size() && std::equal(kIdentifier.begin(), kIdentifier.end(), bytes.begin());
}

std::vector<uint8_t> writeKtx2(const Ktx2Image& image, std::string* error) {
  const Ktx2Format* f = findKtx2Format(image.vkFormat);
  if (!f) {
    *error = "KTX2: vkFormat " + std::to_string(image.vkFormat) + " is not one Facet writes";
    return {};
  }
  if (image.width == 0 || image.height == 0 || image.width > kMaxKtx2Side || image.height > kMaxKtx2Side ||
      image.levels.empty() || image.levels.size() > fullChainLength(image.width, image.height)) {
    *error = "KTX2: a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " image with " +
             std::to_string(image.levels.size()) + " levels is outside the subset";
    return {};
  }
  for (size_t i = 0; i < image.levels.size(); ++i) {
    if (image.levels[i].size() != ktx2LevelBytes(*f, levelExtent(image.width, i), levelExtent(image.height, i))) {
      *error = "KTX2: level " + std::to_string(i) + " holds " + std::to_string(image.levels[i].size()) +
               " bytes, not the size of a " + f->name + " level";
      return {};
    }
  }
  const auto levelCount = uint32_t(image.levels.size());
  const std::vector<uint8_t> dfd = expectedDfd(*f);
  const std::vector<uint8_t> kvd = keyValueData();
  std::vector<uint8_t> out(kIdentifier.begin(), kIdentifier.end());
  for (uint32_t v : {image.vkFormat, 1u, image.width, image.height, 0u, 0u, 1u, levelCount, 0u}) put32(&out, v);
  const uint64_t dfdOffset = kHeaderBytes + kLevelIndexEntry * levelCount;
  const uint64_t kvdOffset = dfdOffset + dfd.size();
  put32(&out, uint32_t(dfdOffset));
  put32(&out, uint32_t(dfd.size()));
  put32(&out, uint32_t(kvdOffset));
  put32(&out, uint32_t(kvd.size()));
  put64(&out, 0);  // no supercompression global data
  put64(&out, 0);
  const size_t levelIndex = out.size();
  out.resize(out.size() + kLevelIndexEntry * levelCount, 0);
  out.insert(out.end(), dfd.begin(), dfd.end());
  out.insert(out.end(), kvd.begin(), kvd.end());
  // The smallest level first (specification section 3.9).
  for (size_t i = levelCount; i-- > 0;) {
    out.resize(alignUp(out.size(), levelAlignment(*f)), 0);
    const size_t at = levelIndex + kLevelIndexEntry * i;
    set64(&out, at, out.size());
    set64(&out, at + 8, image.levels[i].size());
    set64(&out, at + 16, image.levels[i].size());
    out.insert(out.end(), image.levels[i].begin(), image.levels[i].end());
  }
  return out;
}

std::optional<Ktx2Image> readKtx2(std::span<const uint8_t> bytes, const std::string& name, std::string* error) {
  auto fail = [&](const std::string& why) {
    *error = name + ": KTX2: " + why;
    return std::nullopt;
  };
  if (!isKtx2(bytes)) return fail("no KTX 2.0 identifier at the start of the file");
  if (bytes.size() < kHeaderBytes)
    return fail("the file ends at byte " + std::to_string(bytes.size()) + ", inside its " +
                std::to_string(kHeaderBytes) + "-byte header");
  const uint32_t vkFormat = get32(bytes, 12), typeSize = get32(bytes, 16);
  const uint32_t width = get32(bytes, 20), height = get32(bytes, 24), depth = get32(bytes, 28);
  const uint32_t layers = get32(bytes, 32), faces = get32(bytes, 36), levelCount = get32(bytes, 40);
  const uint32_t scheme = get32(bytes, 44);
  const uint32_t dfdOffset = get32(bytes, 48), dfdLength = get32(bytes, 52);
  const uint32_t kvdOffset = get32(bytes, 56), kvdLength = get32(bytes, 60);
  const uint64_t sgdOffset = get64(bytes, 64), sgdLength = get64(bytes, 72);

  const Ktx2Format* f = findKtx2Format(vkFormat);
  if (!f) {
    std::string known;
    for (const Ktx2Format& k : kFormats) known += (known.empty() ? "" : ", ") + std::to_string(k.vkFormat);
    return fail("vkFormat " + std::to_string(vkFormat) + " is not one Facet reads (" + known +
                ": RGBA8 and ASTC LDR 4x4, 5x5, 6x6, 8x8, UNORM and SRGB)");
  }
  if (scheme != 0)
    return fail("supercompressionScheme " + std::to_string(scheme) +
                ": supercompressed files (BasisLZ, Zstandard, ZLIB) are not read; write it without supercompression");
  if (typeSize != 1) return fail("typeSize is " + std::to_string(typeSize) + "; " + f->name + " has typeSize 1");
  if (depth != 0 || layers != 0 || faces != 1)
    return fail("pixelDepth " + std::to_string(depth) + ", layerCount " + std::to_string(layers) + ", faceCount " +
                std::to_string(faces) + ": only 2D textures (0, 0, 1) are read, not 3D, arrays or cube maps");
  if (width == 0 || height == 0 || width > kMaxKtx2Side || height > kMaxKtx2Side)
    return fail("the image is " + std::to_string(width) + "x" + std::to_string(height) + "; each side must be 1.." +
                std::to_string(kMaxKtx2Side));
  const uint32_t fullChain = fullChainLength(width, height);
  if (levelCount == 0)
    return fail("levelCount is 0 (generate mipmaps at load): Facet reads files that carry their levels");
  if (levelCount > fullChain)
    return fail("levelCount is " + std::to_string(levelCount) + "; a " + std::to_string(width) + "x" +
                std::to_string(height) + " image has at most " + std::to_string(fullChain));
  const uint64_t indexEnd = kHeaderBytes + uint64_t(kLevelIndexEntry) * levelCount;
  if (bytes.size() < indexEnd)
    return fail("the file ends at byte " + std::to_string(bytes.size()) + ", inside its level index (" +
                std::to_string(levelCount) + " levels end at byte " + std::to_string(indexEnd) + ")");

  // The DFD: where it is, then that it describes this vkFormat.
  const std::vector<uint8_t> dfd = expectedDfd(*f);
  if (dfdOffset < indexEnd || dfdOffset % 4 != 0 || uint64_t(dfdOffset) + dfdLength > bytes.size())
    return fail("the DFD (byte " + std::to_string(dfdOffset) + ", " + std::to_string(dfdLength) +
                " bytes) is not a 4-byte-aligned range after the level index and inside the " +
                std::to_string(bytes.size()) + "-byte file");
  if (dfdLength != dfd.size() || get32(bytes, dfdOffset) != dfdLength)
    return fail("the DFD holds " + std::to_string(dfdLength) + " bytes (dfdTotalSize " +
                (dfdLength >= 4 ? std::to_string(get32(bytes, dfdOffset)) : std::string("missing")) + "); " + f->name +
                "'s basic descriptor block takes " + std::to_string(dfd.size()));
  const std::span<const uint8_t> fileDfd = bytes.subspan(dfdOffset, dfdLength);
  const size_t blockDims = 4 + 8 + 4;  // texelBlockDimension0, after dfdTotalSize, the block header, the colour fields
  if (fileDfd[blockDims] + 1u != f->blockWidth || fileDfd[blockDims + 1] + 1u != f->blockHeight)
    return fail("the DFD gives " + std::to_string(fileDfd[blockDims] + 1) + "x" +
                std::to_string(fileDfd[blockDims + 1] + 1) + " texel blocks; " + f->name + " has " +
                std::to_string(f->blockWidth) + "x" + std::to_string(f->blockHeight));
  const size_t transfer = kDfdPrimariesByte + 1;
  if (fileDfd[transfer] != dfd[transfer])
    return fail("the DFD's transfer function is " + std::to_string(fileDfd[transfer]) + " but " + f->name + " is " +
                (f->srgb ? "sRGB (2)" : "linear (1)"));
  for (size_t i = 0; i < dfd.size(); ++i) {
    // The colour primaries are not used: the texture's values are sampled as stored.
    if (i != kDfdPrimariesByte && fileDfd[i] != dfd[i])
      return fail("the DFD does not describe " + std::string(f->name) + " (byte " + std::to_string(i) + " is " +
                  std::to_string(fileDfd[i]) + ", not " + std::to_string(dfd[i]) + ")");
  }

  // Key/value data: every entry inside the block; the orientation, when given, must be Facet's.
  if (kvdLength != 0) {
    if (kvdOffset < indexEnd || uint64_t(kvdOffset) + kvdLength > bytes.size())
      return fail("the key/value data (byte " + std::to_string(kvdOffset) + ", " + std::to_string(kvdLength) +
                  " bytes) is not inside the file after the level index");
    for (uint64_t at = kvdOffset, end = uint64_t(kvdOffset) + kvdLength; at < end;) {
      const uint32_t length = end - at >= 4 ? get32(bytes, size_t(at)) : 0;
      if (end - at < 4 || length > end - at - 4)
        return fail("a key/value entry at byte " + std::to_string(at) + " runs past the end of the key/value data");
      const auto* entry = reinterpret_cast<const char*>(bytes.data() + at + 4);
      const size_t keyLength = strnlen(entry, length);
      if (keyLength == length || keyLength == 0)
        return fail("the key/value entry at byte " + std::to_string(at) + " has no NUL-terminated key");
      const std::string key(entry, keyLength);
      if (key == "KTXorientation") {
        const std::string value(entry + keyLength + 1, strnlen(entry + keyLength + 1, length - keyLength - 1));
        if (value.substr(0, 2) != "rd")
          return fail("KTXorientation is '" + value + "'; Facet reads 'rd' (row 0 is the top of the image)");
      }
      at = std::min(end, alignUp(at + 4 + length, 4));
    }
  }
  if (sgdOffset != 0 || sgdLength != 0)
    return fail("supercompression global data is given (byte " + std::to_string(sgdOffset) + ", " +
                std::to_string(sgdLength) + " bytes) without a supercompression scheme");

  // The levels: each the size its extent needs, aligned, inside the file, smaller levels first,
  // none overlapping the header or another.
  Ktx2Image image;
  image.vkFormat = vkFormat;
  image.width = width;
  image.height = height;
  image.levels.resize(levelCount);
  uint64_t nextStart = bytes.size();  // the previous (larger) level's start
  for (uint32_t i = 0; i < levelCount; ++i) {
    const size_t at = kHeaderBytes + kLevelIndexEntry * i;
    const uint64_t offset = get64(bytes, at), length = get64(bytes, at + 8), uncompressed = get64(bytes, at + 16);
    const uint32_t w = levelExtent(width, i), h = levelExtent(height, i);
    const uint64_t expected = ktx2LevelBytes(*f, w, h);
    const std::string which = "level " + std::to_string(i) + " (" + std::to_string(w) + "x" + std::to_string(h) + ")";
    if (length != expected || uncompressed != expected)
      return fail(which + " declares " + std::to_string(length) + " bytes (" + std::to_string(uncompressed) +
                  " uncompressed); " + f->name + " needs " + std::to_string(expected));
    // length is at most 8192² × 4 here, so offset + length cannot wrap unless offset is absurd.
    if (offset >= indexEnd && offset <= UINT64_MAX - length && offset + length > bytes.size())
      return fail(which + " takes bytes " + std::to_string(offset) + ".." + std::to_string(offset + length) +
                  "; the file ends at byte " + std::to_string(bytes.size()) + " (truncated)");
    if (offset % levelAlignment(*f) != 0 || offset < indexEnd || offset > nextStart || length > nextStart - offset)
      return fail(which + " at byte " + std::to_string(offset) + " is not " + std::to_string(levelAlignment(*f)) +
                  "-byte aligned between the level index and " +
                  (i == 0 ? "the end of the " + std::to_string(bytes.size()) + "-byte file"
                          : "level " + std::to_string(i - 1) + " (byte " + std::to_string(nextStart) + ")"));
    image.levels[i].assign(bytes.begin() + ptrdiff_t(offset), bytes.begin() + ptrdiff_t(offset + length));
    nextStart = offset;
  }
  return image;
}

}  // namespace facet::texture
