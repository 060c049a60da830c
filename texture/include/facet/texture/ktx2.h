// KTX 2.0 files (Khronos, "KTX File Format Specification", version 2.0): the subset Facet writes
// and reads. One 2D image (no array layers, no cube faces, no depth), every mip level stored, no
// supercompression, and one of these vkFormats: R8G8B8A8 UNORM/SRGB, or ASTC LDR 4x4, 5x5, 6x6,
// 8x8 UNORM/SRGB. The Data Format Descriptor is the basic block the specification prescribes for
// the vkFormat, and the reader holds the file's against it. docs/texture-format.md lists what is
// refused and why.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace facet::texture {

// A vkFormat of the subset, with what its level sizes and DFD follow from.
struct Ktx2Format {
  uint32_t vkFormat = 0;
  const char* name = "";    // VK_FORMAT_..., for messages
  uint32_t blockWidth = 1;  // texels per block (1 for uncompressed formats)
  uint32_t blockHeight = 1;
  uint32_t blockBytes = 4;  // bytes per block (per texel when uncompressed)
  bool astc = false;
  bool srgb = false;
};

// The formats of the subset, and the one with this vkFormat (nullptr when it is not one of them).
std::span<const Ktx2Format> ktx2Formats();
const Ktx2Format* findKtx2Format(uint32_t vkFormat);
// The ASTC format of this block size and encoding, nullptr when it is not one of the subset's.
const Ktx2Format* findAstcFormat(uint32_t blockWidth, uint32_t blockHeight, bool srgb);

// Bytes of one level of width x height texels (whole blocks at the edges).
uint64_t ktx2LevelBytes(const Ktx2Format& format, uint32_t width, uint32_t height);

// Images larger than this on a side are refused (the runtime's own limit, kMaxImageSide).
inline constexpr uint32_t kMaxKtx2Side = 8192;

struct Ktx2Image {
  uint32_t vkFormat = 0;
  uint32_t width = 0;
  uint32_t height = 0;
  // levels[0] is width x height; each next level halves both (rounding down, at least 1). Row 0
  // is the top of the picture (KTXorientation "rd"), as a PNG stores it.
  std::vector<std::vector<uint8_t>> levels;
};

// The file's bytes; the image must be one of the subset (checked: empty result and *error set
// when it is not).
std::vector<uint8_t> writeKtx2(const Ktx2Image& image, std::string* error);

// Reads a file of the subset held in memory. Anything else — another vkFormat, supercompression,
// layers, faces, depth, levelCount 0, sizes above kMaxKtx2Side, a DFD that does not describe the
// vkFormat, level byte counts or offsets that disagree with the header, a key/value entry that
// overruns its block, a truncated file — is refused with *error naming `name`:
// "<name>: KTX2: <why>".
std::optional<Ktx2Image> readKtx2(std::span<const uint8_t> bytes, const std::string& name, std::string* error);

// True when the bytes start with the KTX 2.0 identifier.
bool isKtx2(std::span<const uint8_t> bytes);

}  // namespace facet::texture
