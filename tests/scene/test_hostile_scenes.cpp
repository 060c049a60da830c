// Hostile scenes and images (docs/security.md): each class of bad input ends in a clear
// error naming the file and the JSON pointer, never an abort, a hang or a silently wrong frame.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <span>

#include "facet/package/package.h"
#include "facet/runtime/environment.h"
#include "facet/runtime/image_texture.h"
#include "facet/runtime/material.h"
#include "facet/runtime/scene_frame.h"
#include "facet/scene/json_document.h"
#include "facet/scene/scene.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

std::string parseError(const std::string& json) {
  std::string error;
  auto scene = facet::runtime::parseScene("s.json", json, &error);
  EXPECT_FALSE(scene) << "accepted: " << json;
  return error;
}

// A width × height Radiance .hdr of one colour, RGBE (128, 64, 32, 129) = (1, 0.5, 0.25): flat
// pixels, or run-length scanlines (the form encoders write for 8 <= width < 32768).
std::string radianceFile(int width, int height, bool runLength) {
  std::string file =
      "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n";
  const char rgbe[4] = {char(128), char(64), char(32), char(129)};
  for (int row = 0; row < height; ++row) {
    if (!runLength) {
      for (int x = 0; x < width; ++x) file.append(rgbe, 4);
      continue;
    }
    file += {char(2), char(2), char(width >> 8), char(width & 255)};
    for (char channel : rgbe)
      for (int left = width; left > 0; left -= std::min(left, 127)) file += {char(128 + std::min(left, 127)), channel};
  }
  return file;
}

std::span<const uint8_t> bytesOf(const std::string& s) {
  return {reinterpret_cast<const uint8_t*>(s.data()), s.size()};
}

std::string write(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// A material with a bool and an int parameter, compiled into `dir`.
std::string boolIntPackages() {
  return facet::test::writePackagesFromTexts("hostile-bool-int", {R"(material switches {
    param glossy: bool = true
    param bands: int = 2 in [1, 8]
    param roughness: float = 0.5 in [0, 1]
    surface {
        roughness = params.glossy ? params.roughness * 0.5 : float(params.bands) * 0.1
    }
}
)"});
}

}  // namespace

TEST(HostileScenes, NumberBeyondTheDoubleRangeIsAnErrorNotAnAbort) {
  EXPECT_EQ(parseError("{\"width\": 1e400, \"objects\": []}"),
            "s.json:1:11: error: invalid JSON: number overflow parsing '1e400'");
}

TEST(HostileScenes, DuplicateKeysAreErrorsWithTheirPointer) {
  EXPECT_EQ(parseError(R"({"objects": [{"material": "m"}], "objects": []})"),
            "s.json: error: /objects: duplicate key (JSON objects keep one value per key)");
  EXPECT_EQ(parseError(R"({"objects": [{"material": "m"}, {"material": "m", "params": {"r": 1, "r": 2}}]})"),
            "s.json: error: /objects/1/params/r: duplicate key (JSON objects keep one value per key)");
}

TEST(HostileScenes, SizesAreWholeNumbers) {
  EXPECT_EQ(parseError(R"({"width": 256.7, "objects": []})"),
            "s.json: error: /width: expected a whole number, not 256.7");
}

TEST(HostileScenes, DegenerateDirectionsAreRejected) {
  EXPECT_EQ(parseError(R"({"sun": {"direction": [0, 1e-300, 0]}, "objects": []})"),
            "s.json: error: /sun/direction: a direction needs a length of at least 1e-6");
  EXPECT_EQ(parseError(R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 3.9999999999]}, "objects": []})"),
            "s.json: error: /camera/target: must lie at least 1e-6 from the camera position");
  EXPECT_EQ(parseError(R"({"camera": {"position": [0, 4, 0], "target": [0, 0, 0], "up": [0, 1, 0]}, "objects": []})"),
            "s.json: error: /camera/up: must not be parallel to the view direction (target − position)");
  EXPECT_EQ(parseError(R"({"lights": [{"type": "spot", "direction": [0, 0, 0]}], "objects": []})"),
            "s.json: error: /lights/0/direction: a direction needs a length of at least 1e-6");
}

TEST(HostileScenes, LightColoursAreNonNegative) {
  EXPECT_EQ(parseError(R"({"sun": {"color": [1, -1, 1]}, "objects": []})"),
            "s.json: error: /sun/color/1: a colour component must lie in [0, 1000]");
  EXPECT_EQ(parseError(R"({"lights": [{"type": "point", "color": [1e6, 1, 1]}], "objects": []})"),
            "s.json: error: /lights/0/color/0: a colour component must lie in [0, 1000]");
}

TEST(HostileScenes, MaterialAndParameterNamesAreIdentifiers) {
  // A NUL would cut the package's file name short; a path would open another file.
  EXPECT_NE(parseError(R"({"objects": [{"material": "red\u0000plastic"}]})")
                .find("/objects/0/material: expected a material name (letters, digits, _), not 'red\\u0000plastic'"),
            std::string::npos);
  EXPECT_NE(
      parseError(R"({"objects": [{"material": "..\/secrets"}]})").find("/objects/0/material: expected a material name"),
      std::string::npos);
  EXPECT_NE(parseError(R"({"objects": [{"material": "m", "params": {"a.b": 1}}]})")
                .find("/objects/0/params/a.b: expected a parameter name"),
            std::string::npos);
}

TEST(HostileScenes, HugeUnknownNamesAreNotEchoedInFull) {
  std::string key(1 << 20, 'k');
  std::string error = parseError("{\"" + key + "\": 1, \"objects\": []}");
  EXPECT_LT(error.size(), 300u);
  EXPECT_NE(error.find("...(1048576 bytes)"), std::string::npos) << error.substr(0, 300);
}

TEST(HostileScenes, OnlyRegularFilesAreRead) {
  std::string dir = facet::test::scratchDir("hostile-fifo");
  std::string fifo = dir + "/pipe";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::string error;
  EXPECT_FALSE(facet::runtime::loadScene(fifo, &error));
  EXPECT_EQ(error, fifo + ": error: cannot open the scene file: not a regular file");
  EXPECT_FALSE(facet::runtime::loadScene(dir, &error));
  EXPECT_EQ(error, dir + ": error: cannot open the scene file: not a regular file");
  std::vector<uint8_t> bytes;
  EXPECT_FALSE(
      facet::runtime::readImageFile(fifo, &bytes, &error));  // every texture and environment load reads through it
  EXPECT_EQ(error, fifo + ": cannot read image: not a regular file");
}

TEST(HostileScenes, TruncatedImageSaysWhy) {
  std::string dir = facet::test::scratchDir("hostile-png");
  std::string png = facet::test::readText(facet::test::examplePath("scenes/textures/tiles.png"));
  std::string path = write(dir + "/cut.png", png.substr(0, png.size() / 2));
  std::string error;
  EXPECT_FALSE(facet::runtime::loadImageTexture(path, true, &error));
  // Cut inside a chunk: the chunk check names it; either way the message says why.
  EXPECT_EQ(error.rfind(path + ": cannot read image: PNG chunk at byte ", 0), 0u) << error;
  std::string cutAtChunkEnd = png.substr(0, 33);  // the header chunk whole, no data, no IEND
  path = write(dir + "/headeronly.png", cutAtChunkEnd);
  EXPECT_FALSE(facet::runtime::loadImageTexture(path, true, &error));
  EXPECT_EQ(error.rfind(path + ": cannot ", 0), 0u) << error;
  EXPECT_GT(error.size(), (path + ": cannot decode image: ").size()) << "no reason given: " << error;
}

// Packages built without shadows hold no receiver: a casting sun is refused with the variant it
// needs, never drawn without the shadow.
TEST(HostileScenes, ACastingSunNeedsReceiverVariants) {
  std::string packages = facet::test::writeExamplePackages("hostile-shadows");
  std::string error;
  auto scene = facet::runtime::parseScene(
      "s.json", R"({"sun": {"castShadows": true}, "objects": [{"material": "red_plastic"}]})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*scene, packages, &error));
  EXPECT_NE(error.find("high.dir1.sh4"), std::string::npos) << error;
  scene->sun->castShadows = false;
  EXPECT_TRUE(facet::runtime::SceneFrame::prepare(*scene, packages, &error)) << error;
}

TEST(HostileScenes, PackageHoldingAnotherMaterialIsRefused) {
  std::string packages = facet::test::writeExamplePackages("hostile-renamed");
  std::filesystem::copy_file(packages + "/red_plastic.matpkg", packages + "/impostor.matpkg");
  std::string error;
  auto scene = facet::runtime::parseScene("s.json", R"({"objects": [{"material": "impostor"}]})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*scene, packages, &error));
  EXPECT_NE(error.find("impostor.matpkg: holds material 'red_plastic', not 'impostor' as the scene asks"),
            std::string::npos)
      << error;
}

TEST(HostileScenes, ParameterValuesMatchTheParameterType) {
  std::string packages = boolIntPackages();
  auto prepare = [&](const std::string& params, std::string* error) {
    auto scene = facet::runtime::parseScene(
        "s.json", R"({"objects": [{"material": "switches", "params": )" + params + "}]}", error);
    EXPECT_TRUE(scene) << *error;
    return scene ? facet::runtime::SceneFrame::prepare(*scene, packages, error) : nullptr;
  };
  std::string error;
  EXPECT_TRUE(prepare(R"({"glossy": false, "bands": 3, "roughness": 0.25})", &error)) << error;
  EXPECT_FALSE(prepare(R"({"roughness": true})", &error));
  EXPECT_NE(error.find("parameter 'roughness' of material 'switches' is float, not a bool"), std::string::npos)
      << error;
  EXPECT_FALSE(prepare(R"({"glossy": 1})", &error));
  EXPECT_NE(error.find("parameter 'glossy' of material 'switches' is bool: give true or false"), std::string::npos)
      << error;
  EXPECT_FALSE(prepare(R"({"bands": 2.5})", &error));
  EXPECT_NE(error.find("parameter 'bands' of material 'switches' is int, not 2.5"), std::string::npos) << error;
}

// Hostile packages: checksum-valid (written by package::write), so every check below is the
// runtime's, past the byte-level reader.
namespace {

facet::package::Package examplePackage() {
  std::string packages = facet::test::writeExamplePackages("hostile-packages-src");
  auto r = facet::package::readFile(packages + "/red_plastic.matpkg");
  EXPECT_TRUE(r.package) << r.error;
  return r.package.value_or(facet::package::Package{});
}

// Writes `p` as red_plastic.matpkg in a fresh folder and loads it as an app would.
std::string loadError(const facet::package::Package& p, const std::string& variant = "") {
  std::string dir = facet::test::scratchDir("hostile-packages");
  std::string error;
  EXPECT_TRUE(facet::package::writeFile(dir + "/red_plastic.matpkg", facet::package::write(p), &error)) << error;
  auto material = facet::runtime::LoadedMaterial::load(dir + "/red_plastic.matpkg", &error);
  if (material && !variant.empty() && material->program(variant, &error)) return "";
  return material && variant.empty() ? "" : error;
}

facet::package::Shader* spirv(facet::package::Package& p, const std::string& key, facet::package::Stage stage) {
  for (auto& v : p.variants)
    if (v.key == key)
      for (auto& s : v.shaders)
        if (s.stage == stage && s.target == facet::package::Target::Spirv) return &s;
  return nullptr;
}

}  // namespace

TEST(HostilePackages, MalformedSpirvNeverReachesTheDriver) {
  using facet::package::Stage;
  facet::package::Package p = examplePackage();
  ASSERT_EQ(loadError(p, "high.dir1"), "");
  facet::package::Package truncated = p;
  auto* s = spirv(truncated, "high.dir1", Stage::Fragment);
  ASSERT_TRUE(s);
  s->code.resize(s->code.size() / 2 / 4 * 4);
  EXPECT_NE(loadError(truncated, "high.dir1").find("variant high.dir1: the fragment shader is invalid SPIR-V"),
            std::string::npos);
  facet::package::Package flipped = p;
  s = spirv(flipped, "high.dir1", Stage::Vertex);
  s->code[s->code.size() / 2] ^= 0x40;
  EXPECT_NE(loadError(flipped, "high.dir1").find("the vertex shader is"), std::string::npos);
  facet::package::Package text = p;
  s = spirv(text, "high.dir1", Stage::Vertex);
  s->code.assign({'#', 'v', 'e', 'r', 's', 'i', 'o', 'n', ' ', '3', '0', '0', ' ', 'e', 's', '\n', 'x', 'x', 'x', 'x'});
  // Shader code is checked when its variant is first asked for (the loader decompresses lazily).
  EXPECT_NE(loadError(text, "high.dir1").find("the vertex spirv shader of variant 'high.dir1' is not SPIR-V"),
            std::string::npos);
  facet::package::Package empty = p;
  spirv(empty, "high.dir1", Stage::Vertex)->code.clear();
  EXPECT_NE(loadError(empty, "high.dir1").find("is not SPIR-V"), std::string::npos);
}

TEST(HostilePackages, MeaningIsCheckedNotOnlyBytes) {
  const facet::package::Package good = examplePackage();
  auto expectRejected = [&](auto edit, const std::string& why) {
    facet::package::Package p = good;
    edit(p);
    std::string error = loadError(p);
    EXPECT_NE(error.find(why), std::string::npos) << "expected '" << why << "', got '" << error << "'";
  };
  auto& params = good.material.params;
  ASSERT_GE(params.size(), 2u);
  expectRejected([](auto& p) { p.material.params[1].defaultValue[0] = std::nan(""); },
                 "its default is not a finite number");
  expectRejected([](auto& p) { p.material.params[1].defaultValue[0] = INFINITY; },
                 "its default is not a finite number");
  expectRejected([](auto& p) { p.material.shading = "glossy"; }, "unknown shading model 'glossy'");
  expectRejected([](auto& p) { p.material.blending = "multiply"; }, "unknown blending mode 'multiply'");
  expectRejected([](auto& p) { p.material.params[1].name = p.material.params[0].name; }, "is declared twice");
  expectRejected([](auto& p) { p.material.params[0].name = "base.color"; }, "a parameter name is an identifier");
  expectRejected([](auto& p) { p.material.name = std::string("red\0plastic", 11); }, "is not an identifier");
  expectRejected(
      [](auto& p) {
        p.material.params[1].rangeMin = 2.0;
        p.material.params[1].rangeMax = 1.0;
      },
      "its range is not a finite interval");
  expectRejected(
      [](auto& p) {
        p.material.params[1].rangeMin = std::nan("");
        p.material.params[1].rangeMax = 1.0;
      },
      "its range is not a finite interval");
  expectRejected([](auto& p) { p.variants[0].key = "ultra.dir1"; }, "variant key 'ultra.dir1' is not a valid key");
  expectRejected([](auto& p) { p.variants[1].key = p.variants[0].key; }, "is stored twice");
  expectRejected([](auto& p) { p.material.paramBlockSize = 0xffffffffu; },
                 "the parameter block is 4294967295 bytes; the limit is 4096");
}

// fuzz_image's finding: a PNG whose chunk declares more bytes than the file holds made
// stb_image allocate what the header said (2 GB from a 200-byte file).
TEST(HostileScenes, PngChunkLongerThanTheFileIsRefusedBeforeDecoding) {
  std::string bytes = facet::test::readText(facet::test::sourceDir() +
                                            "/tests/fuzz/image_regressions/png_chunk_length_beyond_file.png");
  ASSERT_FALSE(bytes.empty());
  std::string error;
  std::vector<uint8_t> data(bytes.begin(), bytes.end());
  EXPECT_FALSE(facet::runtime::decodeImageTexture(data, true, "x.png", &error));
  EXPECT_NE(error.find("x.png: cannot read image: PNG chunk at byte "), std::string::npos) << error;
  EXPECT_NE(error.find("remain in the file"), std::string::npos) << error;
}

// fuzz_image's JPEG finding in stb_image (it read past a Huffman table): libjpeg-turbo, which
// decodes JPEG now, refuses the file with a diagnostic naming it.
TEST(HostileScenes, JpegHuffmanTableFindingIsRefused) {
  std::string bytes =
      facet::test::readText(facet::test::sourceDir() + "/tests/fuzz/image_regressions/jpeg_huffman_table_overrun.jpg");
  ASSERT_FALSE(bytes.empty());
  std::vector<uint8_t> data(bytes.begin(), bytes.end());
  std::string error;
  EXPECT_FALSE(facet::runtime::decodeImageTexture(data, true, "x.jpg", &error));
  EXPECT_EQ(error.rfind("x.jpg: cannot read image: ", 0), 0u) << error;
}

// A scene names images relative to its folder and may not leave it (by `..`, an absolute path or
// a symbolic link), unless the app widens the asset root.
TEST(HostileScenes, ImagesOutsideTheSceneFolderAreRefused) {
  namespace fs = std::filesystem;
  std::string dir = facet::test::scratchDir("hostile-paths");
  fs::create_directories(dir + "/scene/textures");
  write(dir + "/secret.png", "not an image");
  write(dir + "/scene/textures/inside.png", "not an image");
  std::error_code ec;
  fs::remove(dir + "/scene/textures/link.png", ec);
  fs::create_symlink(dir + "/secret.png", dir + "/scene/textures/link.png");
  const std::string scenePath = dir + "/scene/s.json";
  auto sceneNaming = [](const std::string& image) {
    return R"({"environment": {"image": ")" + image + R"("}, "objects": [{"material": "m", "params": {"albedo": ")" +
           image + R"("}}]})";
  };
  for (const std::string& image : {std::string("../secret.png"), dir + "/secret.png", std::string("textures/link.png"),
                                   std::string("textures/../../secret.png")}) {
    std::string error;
    EXPECT_FALSE(facet::runtime::parseScene(scenePath, sceneNaming(image), &error)) << image;
    EXPECT_NE(error.find(": error: /environment/image: '" + facet::scene::shownValue(image) +
                         "' is outside the folder this scene may read files from"),
              std::string::npos)
        << error;
    error.clear();
    EXPECT_FALSE(facet::runtime::parseScene(
        scenePath, R"({"objects": [{"material": "m", "params": {"albedo": ")" + image + R"("}}]})", &error))
        << image;
    EXPECT_NE(error.find("/objects/0/params/albedo: '"), std::string::npos) << error;
  }
  std::string error;
  auto inside = facet::runtime::parseScene(scenePath, sceneNaming("textures/inside.png"), &error);
  ASSERT_TRUE(inside) << error;
  EXPECT_EQ(inside->objects.at(0).textures.at("albedo"), dir + "/scene/textures/inside.png");
  auto widened = facet::runtime::parseScene(scenePath, sceneNaming("../secret.png"), &error, {.assetRoot = dir});
  ASSERT_TRUE(widened) << error;
  EXPECT_EQ(widened->environment->image, dir + "/secret.png");
}

// stb_image decodes a Radiance file cut short as if the missing pixels were black; the runtime
// refuses it and says where it ends.
TEST(HostileScenes, TruncatedRadianceImageIsRefused) {
  for (bool runLength : {true, false}) {
    const int width = runLength ? 16 : 4, height = width / 2;
    const std::string whole = radianceFile(width, height, runLength);
    std::string error;
    auto image = facet::runtime::decodeEquirectImage(bytesOf(whole), "sky.hdr", &error);
    ASSERT_TRUE(image) << error;
    EXPECT_EQ(image->rgb.at(0), 1.0f);
    EXPECT_EQ(image->rgb.at(image->rgb.size() - 2), 0.5f);
    EXPECT_EQ(image->rgb.back(), 0.25f);
    const size_t pixelBytes = whole.size() - (whole.find('\n', whole.find("+X")) + 1);  // after the resolution line
    for (size_t cut : {size_t(1), size_t(2), pixelBytes / 2, pixelBytes}) {
      const std::string truncated = whole.substr(0, whole.size() - cut);
      EXPECT_FALSE(facet::runtime::decodeEquirectImage(bytesOf(truncated), "sky.hdr", &error)) << cut;
      EXPECT_EQ(
          error.rfind(
              "sky.hdr: cannot read image: Radiance pixel data ends at byte " + std::to_string(truncated.size()), 0),
          0u)
          << error;
      EXPECT_NE(error.find("(the file is truncated)"), std::string::npos) << error;
    }
  }
  // Through a scene: the message names the file.
  std::string dir = facet::test::scratchDir("hostile-hdr");
  const std::string sky = radianceFile(16, 8, true);
  write(dir + "/cut.hdr", sky.substr(0, sky.size() - 3));
  std::string error;
  auto scene =
      facet::runtime::parseScene(dir + "/s.json", R"({"environment": {"image": "cut.hdr"}, "objects": []})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::buildEnvironmentLighting(*scene, 1.0, &error));
  EXPECT_EQ(error.rfind(dir + "/cut.hdr: cannot read image: Radiance pixel data ends", 0), 0u) << error;
}

// The image fuzzer's seeds are valid files (Radiance flat and run-length coded; baseline,
// progressive and greyscale JPEG), so fuzzing starts from inputs that reach the pixel decoders.
TEST(HostileScenes, ImageFuzzSeedsDecode) {
  size_t radiance = 0, jpeg = 0;
  for (const auto& entry : std::filesystem::directory_iterator(facet::test::sourceDir() + "/tests/fuzz/image_corpus")) {
    std::string bytes = facet::test::readText(entry.path().string());
    std::string error;
    if (entry.path().extension() == ".jpg") {  // the JPEG seeds are textures (3:2, not equirect)
      EXPECT_TRUE(facet::runtime::decodeImageTexture(bytesOf(bytes), true, entry.path().filename().string(), &error))
          << error;
      ++jpeg;
      continue;
    }
    auto image = facet::runtime::decodeEquirectImage(bytesOf(bytes), entry.path().filename().string(), &error);
    ASSERT_TRUE(image) << error;
    EXPECT_GT(*std::max_element(image->rgb.begin(), image->rgb.end()), 0.0f) << entry.path();
    ++radiance;
  }
  EXPECT_EQ(radiance, 2u);
  EXPECT_EQ(jpeg, 3u);
}

namespace {

// The start of a PNG of width × height RGBA8: signature and header chunk only (enough for a size
// probe; a decoder fails on it).
std::string pngHeader(uint32_t width, uint32_t height) {
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0d", 4) + "IHDR";
  for (uint32_t v : {width, height})
    for (int shift = 24; shift >= 0; shift -= 8) png += char((v >> shift) & 0xff);
  png += std::string("\x08\x06\0\0\0", 5) + std::string(4, '\0');  // 8-bit RGBA, CRC (not checked)
  return png;
}

}  // namespace

// Each image is within its own limit, but a scene's images together are bounded before any is
// decoded (eight distinct 8192² textures used to take 8.5 GB).
TEST(HostileScenes, SceneImageMemoryIsBoundedBeforeDecoding) {
  std::string packages = facet::test::writePackagesFromTexts("hostile-budget-packages", {R"(material textured {
    param albedo: texture(srgb) = vec4(0.5, 0.5, 0.5, 1.0)
    surface {
        baseColor = sample(params.albedo, vertex.uv0).rgb
    }
}
)"});
  std::string dir = facet::test::scratchDir("hostile-budget");
  std::string objects;
  for (int i = 0; i < 3; ++i) {
    write(dir + "/big" + std::to_string(i) + ".png", pngHeader(8192, 8192));
    objects += std::string(i ? ", " : "") + R"({"material": "textured", "params": {"albedo": "big)" +
               std::to_string(i) + R"(.png"}})";
  }
  std::string error;
  auto scene = facet::runtime::parseScene(dir + "/s.json", R"({"sun": {}, "objects": [)" + objects + "]}", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*scene, packages, &error));
  // 3 × (8192² × 4 bytes and its mip chain, 4/3 of it) = 1024 MiB.
  EXPECT_EQ(error.rfind("the scene's images decode to 1024 MiB (3 images; largest: " + dir + "/big", 0), 0u) << error;
  EXPECT_NE(error.find("a scene may use at most 512 MiB of decoded images"), std::string::npos) << error;

  // One of them is within the budget: the decoder then reports the file itself.
  scene = facet::runtime::parseScene(
      dir + "/s.json", R"({"sun": {}, "objects": [{"material": "textured", "params": {"albedo": "big0.png"}}]})",
      &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*scene, packages, &error));
  EXPECT_EQ(error.rfind("object 0: " + dir + "/big0.png: cannot decode image", 0), 0u) << error;
}

// Every input fuzz_image ever found (stb_image crashes, allocations, a spin in its Radiance
// run-length loop) ends in an error naming the image, as a texture and as an environment.
TEST(HostileScenes, ImageFuzzFindingsEndInErrors) {
  size_t inputs = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(facet::test::sourceDir() + "/tests/fuzz/image_regressions")) {
    const std::string bytes = facet::test::readText(entry.path().string());
    std::string error;
    EXPECT_FALSE(facet::runtime::decodeImageTexture(bytesOf(bytes), true, "finding", &error)) << entry.path();
    EXPECT_EQ(error.rfind("finding: cannot ", 0), 0u) << error;
    EXPECT_FALSE(facet::runtime::decodeEquirectImage(bytesOf(bytes), "finding", &error)) << entry.path();
    EXPECT_EQ(error.rfind("finding: ", 0), 0u) << error;
    ++inputs;
  }
  EXPECT_GE(inputs, 4u);
}
