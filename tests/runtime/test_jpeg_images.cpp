// JPEG images through libjpeg-turbo: what a texture and an environment decode to, and the files
// refused with a diagnostic naming them (before decoding when the header says enough). The JPEGs
// in tests/data/images/ are a 48×32 ramp (red = x, green = y, blue = 128) libjpeg-turbo encoded at
// quality 100 without chroma subsampling: baseline, progressive, greyscale (red ramp only), CMYK,
// and progressive in 568 scans (every AC coefficient of each component refined twice).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "facet/runtime/image_texture.h"
#include "facet/runtime/scene_image_budget.h"
#include "test_support.h"

namespace {

constexpr int kWidth = 48, kHeight = 32;

std::vector<uint8_t> imageBytes(const std::string& name) {
  const std::string text = facet::test::readText(facet::test::sourceDir() + "/tests/data/images/" + name);
  return {text.begin(), text.end()};
}

// The largest difference between the decoded level 0 and the ramp the file encodes.
int rampError(const facet::runtime::Texture& t, bool grey) {
  int worst = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const int r = x * 255 / (kWidth - 1), g = grey ? r : y * 255 / (kHeight - 1), b = grey ? r : 128;
      const uint8_t* texel = &t.levels[0][(size_t(y) * kWidth + size_t(x)) * 4];
      worst = std::max({worst, std::abs(texel[0] - r), std::abs(texel[1] - g), std::abs(texel[2] - b)});
      EXPECT_EQ(texel[3], 255) << x << "," << y;
    }
  }
  return worst;
}

// Writes bytes to a file in a scratch folder and returns its path.
std::string writeFile(const std::string& dir, const std::string& name, const std::vector<uint8_t>& bytes) {
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return path;
}

// The offset of the baseline or progressive frame header (SOF0 / SOF2) of a JPEG.
size_t frameHeader(const std::vector<uint8_t>& jpeg) {
  for (size_t at = 2; at + 4 < jpeg.size();) {
    if (jpeg[at + 1] == 0xc0 || jpeg[at + 1] == 0xc2) return at;
    at += 2 + (size_t(jpeg[at + 2]) << 8 | jpeg[at + 3]);
  }
  ADD_FAILURE() << "no frame header";
  return 0;
}

// The same JPEG saying it is width × height (the pixel data then does not match: only headers
// are read by the checks this drives).
std::vector<uint8_t> claimingSize(std::vector<uint8_t> jpeg, int width, int height) {
  const size_t sof = frameHeader(jpeg);
  jpeg[sof + 5] = uint8_t(height >> 8);
  jpeg[sof + 6] = uint8_t(height);
  jpeg[sof + 7] = uint8_t(width >> 8);
  jpeg[sof + 8] = uint8_t(width);
  return jpeg;
}

TEST(JpegImages, BaselineProgressiveAndGreyDecodeToTheirPixelsTopRowFirst) {
  for (const char* name : {"ramp.jpg", "ramp_progressive.jpg", "ramp_grey.jpg"}) {
    std::string error;
    auto t = facet::runtime::decodeImageTexture(imageBytes(name), true, name, &error);
    ASSERT_TRUE(t) << error;
    EXPECT_EQ(t->width, uint32_t(kWidth));
    EXPECT_EQ(t->height, uint32_t(kHeight));
    EXPECT_EQ(t->format, facet::runtime::TextureFormat::Rgba8Srgb);
    // Quality 100 without subsampling: what remains is the DCT's rounding (measured: 3 in colour, 0 in grey).
    EXPECT_LE(rampError(*t, std::string(name) == "ramp_grey.jpg"), 3) << name;
    EXPECT_EQ(t->levels.size(), 6u) << "48x32, 24x16, 12x8, 6x4, 3x2, 1x1";
  }
}

TEST(JpegImages, FileLoadsAsTextureAndEnvironment) {
  std::string error;
  auto t = facet::runtime::loadImageTexture(facet::test::sourceDir() + "/tests/data/images/ramp.jpg", false, &error);
  ASSERT_TRUE(t) << error;
  EXPECT_EQ(t->format, facet::runtime::TextureFormat::Rgba8Unorm);
  // An equirect environment is 2:1: the ramp is 3:2, so it is refused as one, after its header.
  EXPECT_FALSE(facet::runtime::decodeEquirectImage(imageBytes("ramp.jpg"), "ramp.jpg", &error));
  EXPECT_EQ(error, "ramp.jpg: an equirect environment is twice as wide as high; this image is 48x32");
}

TEST(JpegImages, TruncatedOrCorruptDataIsAnErrorNotGreyBlocks) {
  const std::vector<uint8_t> whole = imageBytes("ramp.jpg");
  std::string error;
  std::vector<uint8_t> cut(whole.begin(), whole.begin() + std::ptrdiff_t(whole.size() * 2 / 3));
  EXPECT_FALSE(facet::runtime::decodeImageTexture(cut, true, "cut.jpg", &error));
  EXPECT_EQ(error, "cut.jpg: cannot decode image: Premature end of JPEG file");
  std::vector<uint8_t> headerOnly(whole.begin(), whole.begin() + std::ptrdiff_t(frameHeader(whole)));
  EXPECT_FALSE(facet::runtime::decodeImageTexture(headerOnly, true, "head.jpg", &error));
  EXPECT_EQ(error.rfind("head.jpg: cannot read image: ", 0), 0u) << error;
  std::vector<uint8_t> noise = whole;
  for (size_t i = whole.size() / 2; i < whole.size() / 2 + 64; ++i) noise[i] = uint8_t(i * 37);
  EXPECT_FALSE(facet::runtime::decodeImageTexture(noise, true, "noise.jpg", &error));
  EXPECT_EQ(error.rfind("noise.jpg: cannot decode image: ", 0), 0u) << error;
}

TEST(JpegImages, CmykAndEndlessProgressiveFilesAreRefused) {
  std::string error;
  EXPECT_FALSE(facet::runtime::decodeImageTexture(imageBytes("ramp_cmyk.jpg"), true, "cmyk.jpg", &error));
  EXPECT_EQ(error, "cmyk.jpg: cannot read image: a CMYK JPEG (textures are greyscale or colour JPEGs)");
  EXPECT_FALSE(facet::runtime::decodeImageTexture(imageBytes("ramp_568_scans.jpg"), true, "scans.jpg", &error));
  EXPECT_EQ(error,
            "scans.jpg: cannot decode image: a progressive JPEG of more than 500 scans (the limit; encoders "
            "write a few dozen)");
}

TEST(JpegImages, SizeIsCheckedBeforeDecoding) {
  std::string error;
  const auto huge = claimingSize(imageBytes("ramp.jpg"), 8193, 16);
  EXPECT_FALSE(facet::runtime::decodeImageTexture(huge, true, "huge.jpg", &error));
  EXPECT_EQ(error, "huge.jpg: image is 8193x16; the limit is 8192 on each side");
  EXPECT_FALSE(facet::runtime::decodeEquirectImage(huge, "huge.jpg", &error));
  EXPECT_EQ(error, "huge.jpg: image is 8193x16; the limit is 8192 on each side");
}

// The scene's decoded-image budget counts a JPEG from its frame header, also when Exif or ICC
// segments put that header past the first 64 KiB of the file.
TEST(JpegImages, SceneBudgetCountsJpegsByTheirHeader) {
  std::vector<uint8_t> big = claimingSize(imageBytes("ramp.jpg"), 8192, 8192);
  std::vector<uint8_t> segments;
  for (int i = 0; i < 2; ++i) {
    const uint16_t length = 65000;
    segments.insert(segments.end(), {0xff, 0xe1, uint8_t(length >> 8), uint8_t(length & 0xff)});
    segments.insert(segments.end(), length - 2u, uint8_t('x'));
  }
  std::vector<uint8_t> late(big.begin(), big.begin() + 2);
  late.insert(late.end(), segments.begin(), segments.end());
  late.insert(late.end(), big.begin() + 2, big.end());
  const std::string dir = facet::test::scratchDir("jpeg-budget");
  facet::runtime::Scene scene;
  scene.objects.emplace_back().textures["albedo"] = writeFile(dir, "a.jpg", big);
  std::string error;
  EXPECT_TRUE(facet::runtime::checkSceneImageBudget(scene, &error)) << error;
  scene.objects.emplace_back().textures["albedo"] = writeFile(dir, "late.jpg", late);
  EXPECT_FALSE(facet::runtime::checkSceneImageBudget(scene, &error));
  // 2 × 8192² × 4 bytes with their mip chains (4/3) = 683 MiB.
  EXPECT_EQ(error.rfind("the scene's images decode to 683 MiB (2 images; largest: ", 0), 0u) << error;
  EXPECT_NE(error.find("late.jpg (8192x8192)"), std::string::npos) << error;
}

}  // namespace
