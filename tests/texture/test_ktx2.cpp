// The KTX2 subset (texture/src/ktx2.cpp): what the writer writes reads back the same, and each way
// a file can disagree with its header is refused with a message naming the file and the field.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "facet/texture/ktx2.h"
#include "test_support.h"

namespace {

using facet::texture::Ktx2Image;

constexpr uint32_t kAstc6x6Srgb = 166, kRgba8Unorm = 37;

// A 20x12 image of the format, full mip chain (5 levels), every byte numbered.
Ktx2Image sample(uint32_t vkFormat, uint32_t width = 20, uint32_t height = 12) {
  const facet::texture::Ktx2Format* format = facet::texture::findKtx2Format(vkFormat);
  Ktx2Image image{vkFormat, width, height, {}};
  for (uint32_t w = width, h = height;; w = std::max(1u, w / 2), h = std::max(1u, h / 2)) {
    std::vector<uint8_t> level(facet::texture::ktx2LevelBytes(*format, w, h));
    for (size_t i = 0; i < level.size(); ++i) level[i] = uint8_t(i * 7 + image.levels.size());
    image.levels.push_back(std::move(level));
    if (w == 1 && h == 1) break;
  }
  return image;
}

std::vector<uint8_t> written(const Ktx2Image& image) {
  std::string error;
  std::vector<uint8_t> bytes = facet::texture::writeKtx2(image, &error);
  EXPECT_FALSE(bytes.empty()) << error;
  return bytes;
}

void put32(std::vector<uint8_t>* b, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) (*b)[at + size_t(i)] = uint8_t(v >> (8 * i));
}
void put64(std::vector<uint8_t>* b, size_t at, uint64_t v) {
  for (int i = 0; i < 8; ++i) (*b)[at + size_t(i)] = uint8_t(v >> (8 * i));
}
uint32_t get32(const std::vector<uint8_t>& b, size_t at) {
  return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
}

// The message readKtx2 gives for these bytes ("" when it reads them).
std::string refusal(const std::vector<uint8_t>& bytes) {
  std::string error;
  auto image = facet::texture::readKtx2(bytes, "bad.ktx2", &error);
  if (image) return "";
  EXPECT_EQ(error.rfind("bad.ktx2: KTX2: ", 0), 0u) << error;
  return error;
}

#define EXPECT_REFUSED(bytes, words)                                             \
  do {                                                                           \
    const std::string why = refusal(bytes);                                      \
    EXPECT_NE(why.find(words), std::string::npos) << "message: '" << why << "'"; \
  } while (0)

}  // namespace

TEST(Ktx2, EveryFormatRoundTrips) {
  for (const facet::texture::Ktx2Format& format : facet::texture::ktx2Formats()) {
    const Ktx2Image image = sample(format.vkFormat);
    std::string error;
    auto read = facet::texture::readKtx2(written(image), "round.ktx2", &error);
    ASSERT_TRUE(read) << format.name << ": " << error;
    EXPECT_EQ(read->vkFormat, image.vkFormat);
    EXPECT_EQ(read->width, 20u);
    EXPECT_EQ(read->height, 12u);
    EXPECT_EQ(read->levels, image.levels) << format.name;
  }
}

TEST(Ktx2, ASingleLevelAndAnOddSizeRoundTrip) {
  Ktx2Image image = sample(kAstc6x6Srgb, 13, 7);
  image.levels.resize(1);
  std::string error;
  auto read = facet::texture::readKtx2(written(image), "one.ktx2", &error);
  ASSERT_TRUE(read) << error;
  EXPECT_EQ(read->levels, image.levels);
}

TEST(Ktx2, LayoutFollowsTheSpecification) {
  const std::vector<uint8_t> bytes = written(sample(kAstc6x6Srgb));
  // typeSize 1, faceCount 1, 5 levels, no supercompression.
  EXPECT_EQ(get32(bytes, 16), 1u);
  EXPECT_EQ(get32(bytes, 36), 1u);
  EXPECT_EQ(get32(bytes, 40), 5u);
  EXPECT_EQ(get32(bytes, 44), 0u);
  // Levels 16-byte aligned, the smallest first in the file.
  uint64_t previous = 0;
  for (int level = 4; level >= 0; --level) {
    const uint64_t offset = get32(bytes, 80 + 24 * size_t(level));
    EXPECT_EQ(offset % 16, 0u);
    EXPECT_GT(offset, previous);
    previous = offset;
  }
  // The DFD: ASTC colour model (162), sRGB transfer (2), 6x6 blocks of 16 bytes.
  const size_t dfd = get32(bytes, 48);
  EXPECT_EQ(bytes[dfd + 12], 162);
  EXPECT_EQ(bytes[dfd + 14], 2);
  EXPECT_EQ(bytes[dfd + 16], 5);
  EXPECT_EQ(bytes[dfd + 17], 5);
  EXPECT_EQ(bytes[dfd + 20], 16);
}

TEST(Ktx2, HeaderDisagreementsAreRefused) {
  const std::vector<uint8_t> good = written(sample(kAstc6x6Srgb));
  std::vector<uint8_t> b = good;
  b[0] = 'x';
  EXPECT_REFUSED(b, "no KTX 2.0 identifier");
  EXPECT_REFUSED(std::vector<uint8_t>(good.begin(), good.begin() + 40), "inside its 80-byte header");
  b = good;
  put32(&b, 12, 131);  // VK_FORMAT_BC1_RGB_UNORM_BLOCK
  EXPECT_REFUSED(b, "vkFormat 131 is not one Facet reads");
  b = good;
  put32(&b, 44, 2);  // Zstandard
  EXPECT_REFUSED(b, "supercompressionScheme 2");
  b = good;
  put32(&b, 16, 4);
  EXPECT_REFUSED(b, "typeSize is 4");
  b = good;
  put32(&b, 36, 6);
  EXPECT_REFUSED(b, "faceCount 6");
  b = good;
  put32(&b, 32, 2);
  EXPECT_REFUSED(b, "layerCount 2");
  b = good;
  put32(&b, 28, 4);
  EXPECT_REFUSED(b, "pixelDepth 4");
  b = good;
  put32(&b, 20, 100000);
  EXPECT_REFUSED(b, "the image is 100000x12");
  b = good;
  put32(&b, 24, 0);
  EXPECT_REFUSED(b, "the image is 20x0");
  b = good;
  put32(&b, 40, 0);
  EXPECT_REFUSED(b, "levelCount is 0");
  b = good;
  put32(&b, 40, 6);
  EXPECT_REFUSED(b, "levelCount is 6; a 20x12 image has at most 5");
  b = good;
  put64(&b, 64, 200);
  put64(&b, 72, 16);
  EXPECT_REFUSED(b, "supercompression global data");
}

TEST(Ktx2, DimensionsAndSizeDisagreementsAreRefused) {
  const std::vector<uint8_t> good = written(sample(kAstc6x6Srgb));
  // The header says 40x12: level 0 then needs more blocks than the index gives.
  std::vector<uint8_t> b = good;
  put32(&b, 20, 40);
  EXPECT_REFUSED(b, "level 0 (40x12) declares 128 bytes");
  // A level whose byte count is not its blocks'.
  b = good;
  put64(&b, 80 + 24 + 8, 48);
  EXPECT_REFUSED(b, "level 1 (10x6) declares 48 bytes");
  // uncompressedByteLength must equal byteLength without supercompression.
  b = good;
  put64(&b, 80 + 16, 4096);
  EXPECT_REFUSED(b, "(4096 uncompressed)");
  // A misaligned level, and one overlapping the level before it in the file.
  b = good;
  put64(&b, 80 + 24 * 4, get32(good, 80 + 24 * 4) + 4);
  EXPECT_REFUSED(b, "level 4 (1x1) at byte");
  EXPECT_REFUSED(b, "is not 16-byte aligned");
  b = good;
  put64(&b, 80 + 24, get32(good, 80) + 16);
  EXPECT_REFUSED(b, "level 1 (10x6) at byte");
  // A level that points into the header.
  b = good;
  put64(&b, 80, 16);
  EXPECT_REFUSED(b, "between the level index");
}

TEST(Ktx2, TruncatedFilesAreRefusedWherePastTheirEnd) {
  const std::vector<uint8_t> good = written(sample(kAstc6x6Srgb));
  // Every cut is refused, none crashes; the cuts inside level 0 say so.
  for (size_t size = 0; size < good.size(); ++size) {
    const std::vector<uint8_t> cut(good.begin(), good.begin() + ptrdiff_t(size));
    EXPECT_FALSE(refusal(cut).empty()) << "read a file cut at byte " << size;
  }
  EXPECT_REFUSED(std::vector<uint8_t>(good.begin(), good.end() - 1), "(truncated)");
  EXPECT_REFUSED(std::vector<uint8_t>(good.begin(), good.begin() + 100), "inside its level index");
}

TEST(Ktx2, DfdThatDoesNotDescribeTheFormatIsRefused) {
  const std::vector<uint8_t> good = written(sample(kAstc6x6Srgb));
  const size_t dfd = get32(good, 48);
  std::vector<uint8_t> b = good;
  b[dfd + 16] = 3;  // 4x6 blocks
  EXPECT_REFUSED(b, "the DFD gives 4x6 texel blocks; VK_FORMAT_ASTC_6x6_SRGB_BLOCK has 6x6");
  b = good;
  b[dfd + 14] = 1;  // linear transfer
  EXPECT_REFUSED(b, "transfer function is 1");
  b = good;
  b[dfd + 12] = 1;  // RGBSDA colour model
  EXPECT_REFUSED(b, "the DFD does not describe VK_FORMAT_ASTC_6x6_SRGB_BLOCK (byte 12");
  b = good;
  put32(&b, 52, 40);  // a shorter dfdByteLength
  EXPECT_REFUSED(b, "the DFD holds 40 bytes");
  b = good;
  put32(&b, 48, uint32_t(good.size()) - 8);
  EXPECT_REFUSED(b, "the DFD (byte");
  // The colour primaries are not read: any value is accepted.
  b = good;
  b[dfd + 13] = 10;
  EXPECT_EQ(refusal(b), "");
}

TEST(Ktx2, KeyValueDataIsCheckedEntryByEntry) {
  const std::vector<uint8_t> good = written(sample(kRgba8Unorm));
  const size_t kvd = get32(good, 56);
  std::vector<uint8_t> b = good;
  put32(&b, kvd, 1000);  // the first entry's length runs past the block
  EXPECT_REFUSED(b, "runs past the end of the key/value data");
  b = good;
  // "KTXorientation\0rd\0" -> "ru": rows bottom first.
  b[kvd + 4 + 15 + 1] = 'u';
  EXPECT_REFUSED(b, "KTXorientation is 'ru'");
  b = good;
  put32(&b, 60, uint32_t(good.size()));
  EXPECT_REFUSED(b, "the key/value data");
}

TEST(Ktx2, WriterRefusesImagesOutsideTheSubset) {
  std::string error;
  Ktx2Image image = sample(kAstc6x6Srgb);
  image.vkFormat = 131;
  EXPECT_TRUE(facet::texture::writeKtx2(image, &error).empty());
  EXPECT_NE(error.find("vkFormat 131"), std::string::npos) << error;
  image = sample(kAstc6x6Srgb);
  image.levels[2].pop_back();
  EXPECT_TRUE(facet::texture::writeKtx2(image, &error).empty());
  EXPECT_NE(error.find("level 2"), std::string::npos) << error;
}

// Every input fuzz_ktx2 once got wrong is replayed here (tests/fuzz/ktx2_regressions/), with the
// seeds (tests/fuzz/ktx2_corpus/): each reads or is refused naming the file.
TEST(Ktx2, FuzzCorpusAndRegressionsReadOrAreRefused) {
  size_t files = 0;
  for (const char* folder : {"/tests/fuzz/ktx2_corpus", "/tests/fuzz/ktx2_regressions"}) {
    const std::string dir = facet::test::sourceDir() + folder;
    if (!std::filesystem::exists(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().filename() == "README.md") continue;
      const std::string text = facet::test::readText(entry.path().string());
      std::string error;
      auto image = facet::texture::readKtx2({reinterpret_cast<const uint8_t*>(text.data()), text.size()},
                                            entry.path().string(), &error);
      if (!image) {
        EXPECT_EQ(error.rfind(entry.path().string() + ": KTX2: ", 0), 0u) << error;
      }
      ++files;
    }
  }
  EXPECT_GT(files, 0u);
}
