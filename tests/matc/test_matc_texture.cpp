// matc texture as users run it (facet-texture, run by matc): a PNG becomes a KTX2 file the
// reader takes back, the same bytes on every run; usage errors exit 2, input errors 1, each
// naming the file, with no output left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "facet/texture/ktx2.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using facet::test::run;

const std::string kMatc = FACET_MATC;
const std::string kTiles = facet::test::examplePath("scenes/textures/tiles.png");
const std::string kNormals = facet::test::examplePath("scenes/textures/tiles_normal.png");

std::optional<facet::texture::Ktx2Image> readBack(const std::string& path) {
  const std::string text = facet::test::readText(path);
  std::string error;
  auto image = facet::texture::readKtx2({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, path, &error);
  EXPECT_TRUE(image) << error;
  return image;
}

}  // namespace

TEST(MatcTexture, EncodesEachUsageWithItsDefaultBlockAndEveryLevel) {
  const std::string dir = facet::test::scratchDir("cli-texture");
  auto r = run(kMatc + " texture " + kTiles + " -o " + dir + "/colour.ktx2 --usage color");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("64x64, 7 levels, VK_FORMAT_ASTC_6x6_SRGB_BLOCK, 2768 bytes of levels (RGBA8: 21844"),
            std::string::npos)
      << r.out;
  auto colour = readBack(dir + "/colour.ktx2");
  ASSERT_TRUE(colour);
  EXPECT_EQ(colour->levels.size(), 7u);

  r = run(kMatc + " texture " + kNormals + " -o " + dir + "/normal.ktx2 --usage normal");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto normal = readBack(dir + "/normal.ktx2");
  ASSERT_TRUE(normal);
  EXPECT_EQ(normal->vkFormat, facet::texture::findAstcFormat(5, 5, false)->vkFormat);

  r = run(kMatc + " texture " + kNormals + " -o " + dir + "/data.ktx2 --usage data --block 8x8");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto data = readBack(dir + "/data.ktx2");
  ASSERT_TRUE(data);
  EXPECT_EQ(data->vkFormat, facet::texture::findAstcFormat(8, 8, false)->vkFormat);
}

TEST(MatcTexture, OutputIsTheSameBytesOnEveryRunAndMatchesTheExamples) {
  const std::string dir = facet::test::scratchDir("cli-texture-determinism");
  for (const char* name : {"a", "b"})
    ASSERT_EQ(run(kMatc + " texture " + kTiles + " -o " + dir + "/" + name + ".ktx2 --usage color").exitCode, 0);
  EXPECT_EQ(facet::test::readText(dir + "/a.ktx2"), facet::test::readText(dir + "/b.ktx2"));
  // The committed example textures are what matc texture writes from the PNGs beside them.
  EXPECT_EQ(facet::test::readText(dir + "/a.ktx2"),
            facet::test::readText(facet::test::examplePath("scenes/textures/tiles.ktx2")));
  ASSERT_EQ(run(kMatc + " texture " + kNormals + " -o " + dir + "/n.ktx2 --usage normal").exitCode, 0);
  EXPECT_EQ(facet::test::readText(dir + "/n.ktx2"),
            facet::test::readText(facet::test::examplePath("scenes/textures/tiles_normal.ktx2")));
}

TEST(MatcTexture, UsageErrorsExit2AndInputErrorsExit1NamingTheFile) {
  const std::string dir = facet::test::scratchDir("cli-texture-errors");
  auto r = run(kMatc + " texture " + kTiles + " -o " + dir + "/x.ktx2 --usage albedo");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--usage: albedo not in {color,normal,data}"), std::string::npos) << r.err;
  r = run(kMatc + " texture " + kTiles + " -o " + dir + "/x.ktx2 --usage color --block 7x7");
  EXPECT_EQ(r.exitCode, 2);
  r = run(kMatc + " texture " + kTiles + " --usage color");
  EXPECT_EQ(r.exitCode, 2);

  r = run(kMatc + " texture " + dir + "/missing.png -o " + dir + "/x.ktx2 --usage color");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("matc: error: " + dir + "/missing.png: cannot read image: no such file"), std::string::npos)
      << r.err;
  std::ofstream(dir + "/broken.png", std::ios::binary) << std::string("\x89PNG\r\n\x1a\nnot really", 18);
  r = run(kMatc + " texture " + dir + "/broken.png -o " + dir + "/x.ktx2 --usage color");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(dir + "/broken.png: cannot"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/x.ktx2"));

  // The output may not be the input.
  fs::copy_file(kTiles, dir + "/same.png");
  r = run(kMatc + " texture " + dir + "/same.png -o " + dir + "/same.png --usage color");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(facet::test::readText(dir + "/same.png"), facet::test::readText(kTiles));
}

// matc links no encoder: facet-texture, beside it, does the work, and speaks as matc when matc
// runs it, as itself when run alone.
TEST(MatcTexture, RunsFacetTextureBesideMatc) {
  const std::string dir = fs::canonical(facet::test::scratchDir("cli-texture-program")).string();
  const std::string alone = dir + "/matc";
  fs::copy_file(kMatc, alone);
  auto absent = run("PATH=/usr/bin:/bin " + alone + " texture " + kTiles + " -o " + dir + "/x.ktx2 --usage color");
  EXPECT_EQ(absent.exitCode, 1);
  EXPECT_NE(absent.err.find("matc: error: matc texture runs facet-texture, which is neither beside matc (" + dir +
                            "/facet-texture) nor on PATH"),
            std::string::npos)
      << absent.err;
  const std::string built = fs::path(kMatc).parent_path().string();
  auto itself = run(built + "/facet-texture " + dir + "/nope.png -o " + dir + "/x.ktx2 --usage data");
  EXPECT_EQ(itself.exitCode, 1);
  EXPECT_NE(itself.err.find("facet-texture: error: " + dir + "/nope.png"), std::string::npos) << itself.err;
}
