// ASTC textures from KTX2 files on both backends: GL uploads the blocks where the context samples
// ASTC (llvmpipe's GLES does) and decodes them on the CPU where told to; Vulkan decodes them on
// lavapipe, which samples no ASTC. The renders agree with each other and with the PNG scene, the
// path taken shows in ResourceCounts, and bad files and wrong encodings end in errors naming them.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "facet/runtime/image_texture.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/runtime/scene_image_budget.h"
#include "facet/texture/ktx2.h"
#include "test_compile.h"
#include "test_images.h"
#include "test_support.h"

namespace {

using facet::runtime::FrameResult;

const std::string& packages() {
  static const std::string folder = facet::test::writeExamplePackages("compressed-texture-packages");
  return folder;
}

std::unique_ptr<facet::runtime::SceneFrame> prepare(const std::string& scene, std::string* error) {
  auto loaded = facet::runtime::loadScene(scene, error);
  if (!loaded) return nullptr;
  return facet::runtime::SceneFrame::prepare(*loaded, packages(), error);
}

int maxDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  int d = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) d = std::max(d, std::abs(int(a[i]) - int(b[i])));
  return a.size() == b.size() ? d : 256;
}

double shareWithin1(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  size_t within = 0;
  for (size_t i = 0; i < a.size(); ++i) within += std::abs(int(a[i]) - int(b[i])) <= 1;
  return double(within) / double(a.size());
}

std::string copyExampleScene(const std::string& scratch, const std::string& json) {
  const std::string dir = facet::test::scratchDir(scratch);
  std::filesystem::create_directories(dir + "/textures");
  for (const char* file : {"tiles.ktx2", "tiles_normal.ktx2"})
    std::filesystem::copy_file(facet::test::examplePath(std::string("scenes/textures/") + file),
                               dir + "/textures/" + file, std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir + "/scene.json") << json;
  return dir;
}

}  // namespace

TEST(CompressedTextures, GlUploadsAstcBlocksAndMatchesItsCpuDecoding) {
  std::string error;
  auto frame = prepare(facet::test::examplePath("scenes/tiles_astc.json"), &error);
  ASSERT_TRUE(frame) << error;
  auto compressed = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(compressed) << error;
  facet::runtime::GlOptions decodeOptions;
  decodeOptions.decodeCompressedTextures = true;
  auto decoded = facet::runtime::createGlBackend(decodeOptions, &error);
  ASSERT_TRUE(decoded) << error;
  FrameResult a, b;
  ASSERT_TRUE(compressed->render(frame->frame(), &a, &error)) << error;
  ASSERT_TRUE(decoded->render(frame->frame(), &b, &error)) << error;
  // The albedo and the normal map: uploaded as ASTC blocks by one, as RGBA8 by the other.
  EXPECT_EQ(compressed->resources().compressedTextureUploads, 2u);
  EXPECT_EQ(compressed->resources().decodedTextureUploads, 0u);
  EXPECT_EQ(decoded->resources().compressedTextureUploads, 0u);
  EXPECT_EQ(decoded->resources().decodedTextureUploads, 2u);
  std::printf("tiles_astc.json GL ASTC vs GL CPU-decoded: max %d steps, %.4f%% within 1, PSNR %.2f dB\n",
              maxDifference(a.ldr, b.ldr), 100.0 * shareWithin1(a.ldr, b.ldr), facet::test::psnr(a.ldr, b.ldr));
  // Mesa's ASTC decoder and astcenc agree on nearly every value (74 dB measured); the few further
  // apart (about 43 of 537600, up to 5 steps) stay within the bound the PNG scene keeps across
  // the two rasterisers (test_render.cpp, tiles.json).
  EXPECT_LE(maxDifference(a.ldr, b.ldr), 6);
  EXPECT_GE(shareWithin1(a.ldr, b.ldr), 0.9995);
  EXPECT_GT(facet::test::psnr(a.ldr, b.ldr), 60.0);
  EXPECT_TRUE(compressed->validationErrors().empty());
  EXPECT_TRUE(decoded->validationErrors().empty());
}

TEST(CompressedTextures, VulkanDecodesAstcWhereTheDeviceCannotSampleIt) {
  std::string error;
  auto frame = prepare(facet::test::examplePath("scenes/tiles_astc.json"), &error);
  ASSERT_TRUE(frame) << error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(vk && gl) << error;
  FrameResult a, b;
  ASSERT_TRUE(vk->render(frame->frame(), &a, &error)) << error;
  ASSERT_TRUE(gl->render(frame->frame(), &b, &error)) << error;
  // lavapipe reports no ASTC format as sampled (it offers BC): both textures were decoded.
  EXPECT_EQ(vk->resources().decodedTextureUploads, 2u);
  EXPECT_EQ(vk->resources().compressedTextureUploads, 0u);
  std::printf("tiles_astc.json Vulkan (decoded) vs GL (ASTC): max %d steps, %.4f%% within 1\n",
              maxDifference(a.ldr, b.ldr), 100.0 * shareWithin1(a.ldr, b.ldr));
  // The bound of the PNG scene across the two rasterisers (test_render.cpp, tiles.json).
  EXPECT_LE(maxDifference(a.ldr, b.ldr), 6);
  EXPECT_GE(shareWithin1(a.ldr, b.ldr), 0.995);
  EXPECT_TRUE(vk->validationErrors().empty());
}

TEST(CompressedTextures, AstcSceneStaysCloseToThePngScene) {
  std::string error;
  auto png = prepare(facet::test::examplePath("scenes/tiles.json"), &error);
  auto astc = prepare(facet::test::examplePath("scenes/tiles_astc.json"), &error);
  ASSERT_TRUE(png && astc) << error;
  auto gl = facet::runtime::createGlBackend(&error);
  ASSERT_TRUE(gl) << error;
  FrameResult a, b;
  ASSERT_TRUE(gl->render(png->frame(), &a, &error)) << error;
  ASSERT_TRUE(gl->render(astc->frame(), &b, &error)) << error;
  const double db = facet::test::psnr(a.ldr, b.ldr);
  std::printf("tiles_astc.json against tiles.json (GL): PSNR %.2f dB, max %d steps\n", db, maxDifference(a.ldr, b.ldr));
  // Level 0 of the albedo keeps 48.5 dB and the normal map 42.0 dB (docs/runtime.md); lit and
  // tone-mapped, the frame stays above 40 dB of the PNG one.
  EXPECT_GT(db, 40.0);
}

// A KTX2 file of the PNG's own RGBA8 levels (what `matc texture --format rgba8` writes) draws the
// very frame the PNG draws: the levels, their order and the rows' orientation are read as written.
TEST(CompressedTextures, Rgba8Ktx2DrawsThePngsFrame) {
  const std::string dir =
      copyExampleScene("ktx2-rgba8", R"({"width": 160, "height": 96, "sun": {}, "camera": {"position": [0, 0, 3.2]},
                        "objects": [{"material": "painted_tiles", "params": {"albedo": "textures/tiles.png"}}]})");
  std::filesystem::copy_file(facet::test::examplePath("scenes/textures/tiles.png"), dir + "/textures/tiles.png");
  std::string error;
  auto png = facet::runtime::loadImageTexture(dir + "/textures/tiles.png", true, &error);
  ASSERT_TRUE(png) << error;
  const std::vector<uint8_t> bytes = facet::texture::writeKtx2({43, png->width, png->height, png->levels}, &error);
  ASSERT_FALSE(bytes.empty()) << error;
  std::ofstream(dir + "/textures/rgba8.ktx2", std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  std::string json = facet::test::readText(dir + "/scene.json");
  json.replace(json.find("tiles.png"), 9, "rgba8.ktx2");
  std::ofstream(dir + "/scene_ktx2.json") << json;

  auto fromPng = prepare(dir + "/scene.json", &error);
  auto fromKtx2 = prepare(dir + "/scene_ktx2.json", &error);
  ASSERT_TRUE(fromPng && fromKtx2) << error;
  auto vk = facet::runtime::createVulkanBackend({true}, &error);
  ASSERT_TRUE(vk) << error;
  FrameResult a, b;
  ASSERT_TRUE(vk->render(fromPng->frame(), &a, &error)) << error;
  ASSERT_TRUE(vk->render(fromKtx2->frame(), &b, &error)) << error;
  EXPECT_EQ(maxDifference(a.ldr, b.ldr), 0);
  EXPECT_EQ(vk->resources().compressedTextureUploads + vk->resources().decodedTextureUploads, 0u);
  EXPECT_TRUE(vk->validationErrors().empty());
}

TEST(CompressedTextures, TextureEncodedForAnotherUsageIsRefusedNamingIt) {
  const std::string dir = copyExampleScene(
      "astc-wrong-usage",
      R"({"sun": {}, "objects": [{"material": "painted_tiles", "params": {"albedo": "textures/tiles_normal.ktx2"}}]})");
  std::string error;
  EXPECT_FALSE(prepare(dir + "/scene.json", &error));
  EXPECT_NE(error.find("tiles_normal.ktx2: the texture is VK_FORMAT_ASTC_5x5_UNORM_BLOCK (linear) but the material "
                       "samples it as sRGB colour (texture(srgb)): encode it with --usage color"),
            std::string::npos)
      << error;
}

TEST(CompressedTextures, DamagedKtx2InASceneNamesTheFile) {
  const std::string dir = copyExampleScene(
      "astc-damaged",
      R"({"sun": {}, "objects": [{"material": "painted_tiles", "params": {"albedo": "textures/tiles.ktx2"}}]})");
  std::filesystem::resize_file(dir + "/textures/tiles.ktx2", 1000);
  std::string error;
  EXPECT_FALSE(prepare(dir + "/scene.json", &error));
  EXPECT_NE(error.find("textures/tiles.ktx2: KTX2: level 0 (64x64)"), std::string::npos) << error;
  EXPECT_NE(error.find("(truncated)"), std::string::npos) << error;
}

// The budget counts a KTX2 texture's level bytes: 8192² ASTC 4x4 with its 14 levels is 85.3 MiB,
// where the same image as PNG counts 341.3 MiB of RGBA8. Five such files fit in 512 MiB, seven do
// not. Only the header is read, so the files hold nothing else.
TEST(CompressedTextures, SceneImageBudgetCountsTheBytesOfAstcLevels) {
  const std::string dir = facet::test::scratchDir("astc-budget");
  auto headerOnly = [&](int i) {
    std::vector<uint8_t> b(80, 0);
    const uint8_t id[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
    std::copy(id, id + 12, b.begin());
    auto put = [&](size_t at, uint32_t v) {
      for (int k = 0; k < 4; ++k) b[at + size_t(k)] = uint8_t(v >> (8 * k));
    };
    put(12, 158);  // VK_FORMAT_ASTC_4x4_SRGB_BLOCK
    put(20, 8192);
    put(24, 8192);
    put(40, 14);
    const std::string path = dir + "/big" + std::to_string(i) + ".ktx2";
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
    return path;
  };
  facet::runtime::Scene scene;
  for (int i = 0; i < 5; ++i) scene.objects.emplace_back().textures["albedo"] = headerOnly(i);
  std::string error;
  EXPECT_TRUE(facet::runtime::checkSceneImageBudget(scene, &error)) << error;
  for (int i = 5; i < 7; ++i) scene.objects.emplace_back().textures["albedo"] = headerOnly(i);
  EXPECT_FALSE(facet::runtime::checkSceneImageBudget(scene, &error));
  EXPECT_NE(error.find("decode to 598 MiB (7 images"), std::string::npos) << error;
  EXPECT_NE(error.find("(8192x8192, VK_FORMAT_ASTC_4x4_SRGB_BLOCK)"), std::string::npos) << error;
}
