// Hostile scenes and images (issue: hostile inputs): each class of bad input ends in a clear
// error naming the file and the JSON pointer, never an abort, a hang or a silently wrong frame.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "facet/runtime/image_texture.h"
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
  EXPECT_EQ(error.rfind(path + ": cannot decode image: ", 0), 0u) << error;
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
