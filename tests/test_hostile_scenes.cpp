// Hostile scenes and images (issue: hostile inputs): each class of bad input ends in a clear
// error naming the file and the JSON pointer, never an abort, a hang or a silently wrong frame.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "facet/package.h"
#include "facet/runtime/image_texture.h"
#include "facet/runtime/material.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/scene_frame.h"
#include "test_support.h"

namespace {

std::string parseError(const std::string& json) {
  std::string error;
  auto scene = facet::runtime::parseScene("s.json", json, &error);
  EXPECT_FALSE(scene) << "accepted: " << json;
  return error;
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
  EXPECT_EQ(parseError("{\"width\": 1e400, \"objects\": []}"), "s.json:1:11: error: invalid JSON: number overflow parsing '1e400'");
}

TEST(HostileScenes, DuplicateKeysAreErrorsWithTheirPointer) {
  EXPECT_EQ(parseError(R"({"objects": [{"material": "m"}], "objects": []})"),
            "s.json: error: /objects: duplicate key (JSON objects keep one value per key)");
  EXPECT_EQ(parseError(R"({"objects": [{"material": "m"}, {"material": "m", "params": {"r": 1, "r": 2}}]})"),
            "s.json: error: /objects/1/params/r: duplicate key (JSON objects keep one value per key)");
}

TEST(HostileScenes, SizesAreWholeNumbers) {
  EXPECT_EQ(parseError(R"({"width": 256.7, "objects": []})"), "s.json: error: /width: expected a whole number, not 256.7");
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
  EXPECT_NE(parseError(R"({"objects": [{"material": "..\/secrets"}]})").find("/objects/0/material: expected a material name"),
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
  int w = 0, h = 0;
  EXPECT_FALSE(facet::runtime::probeImageSize(fifo, &w, &h, &error));  // every texture and environment load calls it first
  EXPECT_EQ(error, fifo + ": cannot read image: not a regular file");
}

TEST(HostileScenes, TruncatedImageSaysWhy) {
  std::string dir = facet::test::scratchDir("hostile-png");
  std::string png = facet::test::readText(facet::test::examplePath("textures/tiles.png"));
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

TEST(HostileScenes, PackageHoldingAnotherMaterialIsRefused) {
  std::string packages = facet::test::writeExamplePackages("hostile-renamed");
  std::filesystem::copy_file(packages + "/red_plastic.matpkg", packages + "/impostor.matpkg");
  std::string error;
  auto scene = facet::runtime::parseScene("s.json", R"({"objects": [{"material": "impostor"}]})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(facet::runtime::SceneFrame::prepare(*scene, packages, &error));
  EXPECT_NE(error.find("impostor.matpkg: holds material 'red_plastic', not 'impostor' as the scene asks"), std::string::npos)
      << error;
}

TEST(HostileScenes, ParameterValuesMatchTheParameterType) {
  std::string packages = boolIntPackages();
  auto prepare = [&](const std::string& params, std::string* error) {
    auto scene = facet::runtime::parseScene("s.json", R"({"objects": [{"material": "switches", "params": )" + params + "}]}", error);
    EXPECT_TRUE(scene) << *error;
    return scene ? facet::runtime::SceneFrame::prepare(*scene, packages, error) : nullptr;
  };
  std::string error;
  EXPECT_TRUE(prepare(R"({"glossy": false, "bands": 3, "roughness": 0.25})", &error)) << error;
  EXPECT_FALSE(prepare(R"({"roughness": true})", &error));
  EXPECT_NE(error.find("parameter 'roughness' of material 'switches' is float, not a bool"), std::string::npos) << error;
  EXPECT_FALSE(prepare(R"({"glossy": 1})", &error));
  EXPECT_NE(error.find("parameter 'glossy' of material 'switches' is bool: give true or false"), std::string::npos) << error;
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
  EXPECT_NE(loadError(truncated, "high.dir1").find("variant high.dir1: the fragment shader is invalid SPIR-V"), std::string::npos);
  facet::package::Package flipped = p;
  s = spirv(flipped, "high.dir1", Stage::Vertex);
  s->code[s->code.size() / 2] ^= 0x40;
  EXPECT_NE(loadError(flipped, "high.dir1").find("the vertex shader is"), std::string::npos);
  facet::package::Package text = p;
  s = spirv(text, "high.dir1", Stage::Vertex);
  s->code.assign({'#', 'v', 'e', 'r', 's', 'i', 'o', 'n', ' ', '3', '0', '0', ' ', 'e', 's', '\n', 'x', 'x', 'x', 'x'});
  // Shader code is checked when its variant is first asked for (the loader decompresses lazily).
  EXPECT_NE(loadError(text, "high.dir1").find("the vertex spirv shader of variant 'high.dir1' is not SPIR-V"), std::string::npos);
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
  expectRejected([](auto& p) { p.material.params[1].defaultValue[0] = std::nan(""); }, "its default is not a finite number");
  expectRejected([](auto& p) { p.material.params[1].defaultValue[0] = INFINITY; }, "its default is not a finite number");
  expectRejected([](auto& p) { p.material.shading = "glossy"; }, "unknown shading model 'glossy'");
  expectRejected([](auto& p) { p.material.blending = "multiply"; }, "unknown blending mode 'multiply'");
  expectRejected([](auto& p) { p.material.params[1].name = p.material.params[0].name; }, "is declared twice");
  expectRejected([](auto& p) { p.material.params[0].name = "base.color"; }, "a parameter name is an identifier");
  expectRejected([](auto& p) { p.material.name = std::string("red\0plastic", 11); }, "is not an identifier");
  expectRejected([](auto& p) { p.material.params[1].rangeMin = 2.0; p.material.params[1].rangeMax = 1.0; },
                 "its range is not a finite interval");
  expectRejected([](auto& p) { p.material.params[1].rangeMin = std::nan(""); p.material.params[1].rangeMax = 1.0; },
                 "its range is not a finite interval");
  expectRejected([](auto& p) { p.variants[0].key = "ultra.dir1"; }, "variant key 'ultra.dir1' is not a valid key");
  expectRejected([](auto& p) { p.variants[1].key = p.variants[0].key; }, "is stored twice");
  expectRejected([](auto& p) { p.material.paramBlockSize = 0xffffffffu; }, "the parameter block is 4294967295 bytes; the limit is 4096");
}

// fuzz_image's finding: a PNG whose chunk declares more bytes than the file holds made
// stb_image allocate what the header said (2 GB from a 200-byte file).
TEST(HostileScenes, PngChunkLongerThanTheFileIsRefusedBeforeDecoding) {
  std::string bytes = facet::test::readText(facet::test::sourceDir() + "/tests/fuzz/image_regressions/png_chunk_length_beyond_file.png");
  ASSERT_FALSE(bytes.empty());
  std::string error;
  std::vector<uint8_t> data(bytes.begin(), bytes.end());
  EXPECT_FALSE(facet::runtime::decodeImageTexture(data, true, "x.png", &error));
  EXPECT_NE(error.find("x.png: cannot read image: PNG chunk at byte "), std::string::npos) << error;
  EXPECT_NE(error.find("remain in the file"), std::string::npos) << error;
}

// fuzz_image's JPEG finding (stb_image reads past a Huffman table): JPEG is not decoded at all.
TEST(HostileScenes, JpegIsRefusedNotDecoded) {
  std::string bytes = facet::test::readText(facet::test::sourceDir() + "/tests/fuzz/image_regressions/jpeg_huffman_table_overrun.jpg");
  ASSERT_FALSE(bytes.empty());
  std::vector<uint8_t> data(bytes.begin(), bytes.end());
  std::string error;
  EXPECT_FALSE(facet::runtime::decodeImageTexture(data, true, "x.jpg", &error));
  EXPECT_EQ(error.rfind("x.jpg: cannot read image: ", 0), 0u) << error;
}
