// Hostile glTF files (runtime/gltf_mesh.h, docs/security.md "Files"): each class of bad input ends
// in an error naming the file and the place, through loadGltfMesh and through a scene, never a
// crash, a read outside the file's memory or folder, or an unbounded allocation.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "facet/runtime/gltf_mesh.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/scene_frame.h"
#include "facet/scene/scene.h"
#include "fuzz/gltf_fuzz_input.h"
#include "gltf_test_files.h"
#include "test_compile.h"
#include "test_support.h"

namespace facet::runtime {
namespace {

namespace fs = std::filesystem;
using test::append;
using test::glb;
using test::quadBin;
using test::quadJson;
using test::writeBytes;
using test::writeText;

std::string loadError(const std::string& path, const GltfReadOptions& options = {}) {
  std::string error;
  auto mesh = loadGltfMesh(path, &error, options);
  EXPECT_FALSE(mesh) << "accepted: " << path;
  return error;
}

// The package folder of material `flat`, compiled once per test process.
const std::string& flatPackages() {
  static const std::string packages = test::writePackagesFromTexts(
      "gltf-hostile-packages", {"material flat { shading unlit\n surface { baseColor = vec3(0.5) } }"});
  return packages;
}

// A scene of one object drawing `mesh` (relative to `dir`, where the scene file is), prepared as
// facet-view does; the error it ends in.
std::string sceneError(const std::string& dir, const std::string& mesh, const SceneReadOptions& options = {}) {
  const std::string& packages = flatPackages();
  std::string error;
  auto scene = parseScene(dir + "/scene.json", R"({"objects": [{"mesh": ")" + mesh + R"(", "material": "flat"}]})",
                          &error, options);
  if (!scene) return error;
  EXPECT_FALSE(SceneFrame::prepare(*scene, packages, &error)) << "accepted: " << mesh;
  return error;
}

void setFloat(std::vector<uint8_t>* bytes, size_t at, float value) { std::memcpy(bytes->data() + at, &value, 4); }

// The quad with its .bin edited: `name`.gltf and `name`.bin in `dir`. `scene` replaces the node part.
std::string writeEditedQuad(const std::string& dir, const std::string& name, const std::vector<uint8_t>& bin,
                            const std::string& json = "") {
  writeBytes(dir + "/" + name + ".bin", bin);
  writeText(dir + "/" + name + ".gltf",
            json.empty() ? quadJson(R"({"uri": ")" + name + R"(.bin", "byteLength": 236})") : json);
  return dir + "/" + name + ".gltf";
}

// JSON nested `depth` arrays deep under the root's `extras`, on the file's second line.
std::string deepJson(size_t depth) {
  return "{\"asset\": {\"version\": \"2.0\"},\n\"extras\": " + std::string(depth, '[') + std::string(depth, ']') + "}";
}

// An empty regular file of `size` bytes that takes no disk space (a sparse file).
void sparseFile(const std::string& path, uintmax_t size) {
  writeText(path, "");
  fs::resize_file(path, size);
}

}  // namespace

// tinygltf converts `extras` recursively: 20,000 nested arrays in 40 KB overflowed its stack.
// The depth is checked on the text first, for a .gltf and for a .glb's JSON chunk.
TEST(GltfHostile, DeepJsonIsRefusedAtItsLineBeforeTinygltfParsesIt) {
  const std::string dir = test::scratchDir("gltf-deep");
  writeText(dir + "/deep.gltf", deepJson(20000));
  // The root object is level 1: the 64th '[' opens level 65, at column 10 + 64 of line 2.
  EXPECT_EQ(loadError(dir + "/deep.gltf"), dir +
                                               "/deep.gltf:2:74: error: arrays and objects nest more than 64 deep here "
                                               "(Facet reads JSON at most that deep)");
  writeBytes(dir + "/deep.glb", glb(deepJson(20000), {}));
  EXPECT_EQ(loadError(dir + "/deep.glb"), dir +
                                              "/deep.glb:2:74: error: in the JSON chunk at byte 20: arrays and objects "
                                              "nest more than 64 deep here (Facet reads JSON at most that deep)");
  // 64 deep is read (and then refused for what it lacks, not for its depth).
  writeText(dir + "/ok.gltf", deepJson(63));
  EXPECT_EQ(loadError(dir + "/ok.gltf").find("nest more than"), std::string::npos);
  // Through a scene: the object and the place.
  EXPECT_EQ(sceneError(dir, "deep.gltf"), "object 0: " + dir +
                                              "/deep.gltf:2:74: error: arrays and objects nest more than 64 deep "
                                              "here (Facet reads JSON at most that deep)");
}

// tinygltf's model is far larger than its JSON: 16 MiB of empty nodes took 4.2 GB and 10 s.
// Estimated from the text before any document is built.
TEST(GltfHostile, JsonThatExpandsInMemoryIsRefusedBeforeParsing) {
  const std::string dir = test::scratchDir("gltf-expanding");
  std::string nodes = R"({"asset": {"version": "2.0"}, "nodes": [{})";
  for (int i = 0; i < 1 << 20; ++i) nodes += ",{}";
  writeText(dir + "/nodes.gltf", nodes + "]}");
  EXPECT_EQ(loadError(dir + "/nodes.gltf"),
            dir +
                "/nodes.gltf: error: /nodes: the JSON would take more than 256 MiB once "
                "read into the glTF model (its elements are far larger in memory than "
                "in the file)");
  std::string materials = R"({"asset": {"version": "2.0"}, "materials": [{})";
  for (int i = 0; i < 200000; ++i) materials += ",{}";
  writeText(dir + "/materials.gltf", materials + "]}");
  EXPECT_NE(loadError(dir + "/materials.gltf")
                .find("materials.gltf: error: /materials: the JSON would take more than 256 MiB"),
            std::string::npos);
}

// Files are read whole, so their sizes are checked first: a sparse 6 GiB buffer used to end in
// std::bad_alloc, a 257 MiB .gltf was read. A scene's files share the 256 MiB.
TEST(GltfHostile, FileSizesAreBoundedBeforeReading) {
  const std::string dir = test::scratchDir("gltf-sizes");
  sparseFile(dir + "/huge.bin", uintmax_t(6) << 30);
  writeText(dir + "/huge.gltf", quadJson(R"({"uri": "huge.bin", "byteLength": 6442450944})"));
  EXPECT_EQ(loadError(dir + "/huge.gltf"),
            dir + "/huge.gltf: error: /buffers/0/uri: 'huge.bin' is 6442450944 bytes; with the " +
                std::to_string(fs::file_size(dir + "/huge.gltf")) +
                " read before it, more than the 268435456 bytes left for glTF files (a scene's glTF files and their "
                "buffers take at most 256 MiB together)");
  sparseFile(dir + "/big.gltf", (uintmax_t(256) << 20) + 1);
  EXPECT_EQ(loadError(dir + "/big.gltf"),
            dir +
                "/big.gltf: error: the glTF file is 268435457 bytes; with the 0 read before "
                "it, more than the 268435456 bytes left for glTF files (a scene's glTF "
                "files and their buffers take at most 256 MiB together)");
  // What a scene's earlier files read is gone for the later ones.
  test::writeQuad(dir);
  GltfBudget budget;
  budget.fileBytes = fs::file_size(dir + "/quad.gltf") + 236 + 10;
  std::string error;
  ASSERT_TRUE(loadGltfMesh(dir + "/quad.gltf", &error, {"", &budget})) << error;
  EXPECT_EQ(budget.fileBytes, 10u);
  EXPECT_EQ(
      loadError(dir + "/quad.gltf", {"", &budget}),
      dir + "/quad.gltf: error: the glTF file is " + std::to_string(fs::file_size(dir + "/quad.gltf")) +
          " bytes; with the 0 read before it, more than the 10 bytes left for glTF files (a scene's glTF files and "
          "their buffers take at most 256 MiB together)");
  // Through a scene.
  EXPECT_NE(sceneError(dir, "huge.gltf")
                .find("object 0: " + dir + "/huge.gltf: error: /buffers/0/uri: 'huge.bin' is 6442450944 bytes"),
            std::string::npos);
}

// Images are not part of a mesh: tinygltf used to read every image file the glTF names, whole,
// even with decoding skipped. A 6 GiB image file is not opened now: the load succeeds with the
// address space limited to 1 GiB.
TEST(GltfHostile, ImageFilesAreNotRead) {
  const std::string dir = test::scratchDir("gltf-images");
  sparseFile(dir + "/huge.png", uintmax_t(6) << 30);
  test::writeQuad(dir, "quad.bin", std::string(test::kQuadScene) + R"(, "images": [{"uri": "huge.png"}])",
                  "images.gltf");
  const auto load = [&] {
#if !defined(__SANITIZE_ADDRESS__)  // AddressSanitizer reserves terabytes of address space
    // 1 GiB more than the process maps already (its libraries, the Vulkan loader's).
    size_t pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t bytes = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + (rlim_t(1) << 30);
    const rlimit limit{bytes, bytes};
    setrlimit(RLIMIT_AS, &limit);
#endif
    std::string error;
    std::exit(loadGltfMesh(dir + "/images.gltf", &error) ? 0 : 1);
  };
  EXPECT_EXIT(load(), testing::ExitedWithCode(0), "");
}

// Scenes may name 4096 objects: the vertices of all their glTF files (each node's copy counted,
// a file shared by objects once) are bounded together, before each file's mesh is built. Two
// files of 3 and 2 nodes placing a 1 Mi-vertex sparse accessor (a few hundred bytes each) used
// to build 5 Mi vertices.
TEST(GltfHostile, SceneMeshesShareOneVertexBudget) {
  const std::string dir = test::scratchDir("gltf-scene-budget");
  std::vector<uint8_t> bin;
  append<uint16_t>(&bin, {0, 0});
  append<float>(&bin, {0, 0, 0});
  writeBytes(dir + "/one.bin", bin);
  const auto write = [&](const std::string& name, int nodes) {
    std::string list, roots;
    for (int i = 0; i < nodes; ++i) {
      list += std::string(i ? ", " : "") + R"({"mesh": 0})";
      roots += (i ? ", " : "") + std::to_string(i);
    }
    writeText(dir + "/" + name, R"({"asset": {"version": "2.0"},
      "buffers": [{"uri": "one.bin", "byteLength": 16}], "bufferViews": [{"buffer": 0, "byteLength": 16}],
      "accessors": [{"componentType": 5126, "count": 1048575, "type": "VEC3",
        "sparse": {"count": 1, "indices": {"bufferView": 0, "componentType": 5123}, "values": {"bufferView": 0, "byteOffset": 4}}}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "nodes": [)" + list + R"(], "scenes": [{"nodes": [)" +
                                    roots + "]}]}");
  };
  write("three.gltf", 3);
  write("two.gltf", 2);
  GltfBudget budget;
  std::string error;
  ASSERT_TRUE(loadGltfMesh(dir + "/three.gltf", &error, {"", &budget})) << error;
  EXPECT_EQ(budget.vertices, GltfBudget::kMaxVertices - 3 * 1048575);
  EXPECT_EQ(loadError(dir + "/two.gltf", {"", &budget}),
            dir +
                "/two.gltf: error: /nodes/1/mesh: the file places more than the 1048579 vertices left of the 4194304 a "
                "scene's glTF meshes may hold (counting every node's copy)");
  // Through a scene: the second object's file is refused, named with its object.
  auto scene = parseScene(dir + "/scene.json", R"({"objects": [{"mesh": "three.gltf", "material": "flat"},
      {"mesh": "three.gltf", "material": "flat"}, {"mesh": "two.gltf", "material": "flat"}]})",
                          &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(SceneFrame::prepare(*scene, flatPackages(), &error));
  // Object 1 shares object 0's mesh: only the third costs more.
  EXPECT_EQ(error, "object 2: " + dir +
                       "/two.gltf: error: /nodes/1/mesh: the file places more than the 1048579 vertices "
                       "left of the 4194304 a scene's glTF meshes may hold (counting every node's copy)");
}

// Each placed primitive is read and transformed on its own: 1023 nodes placing a mesh of 4096
// one-vertex primitives (200 KB) took 45 s of CPU. Bounded like the vertices, before building.
TEST(GltfHostile, PlacedPrimitivesAreBounded) {
  const std::string dir = test::scratchDir("gltf-primitives");
  std::vector<uint8_t> bin;
  append<float>(&bin, {0, 0, 0});
  append<uint16_t>(&bin, {0, 0, 0, 0});
  writeBytes(dir + "/tiny.bin", bin);
  std::string primitives, nodes, roots;
  for (int i = 0; i < 4096; ++i)
    primitives += std::string(i ? ", " : "") + R"({"attributes": {"POSITION": 0}, "indices": 1})";
  for (int i = 0; i < 17; ++i) {
    nodes += std::string(i ? ", " : "") + R"({"mesh": 0})";
    roots += (i ? ", " : "") + std::to_string(i);
  }
  writeText(dir + "/many.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "tiny.bin", "byteLength": 20}],
    "bufferViews": [{"buffer": 0, "byteLength": 12}, {"buffer": 0, "byteOffset": 12, "byteLength": 6}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 1, "type": "VEC3"},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
    "meshes": [{"primitives": [)" + primitives +
                                    R"(]}], "nodes": [)" + nodes + R"(], "scenes": [{"nodes": [)" + roots + "]}]}");
  // 16 nodes place 65536 primitives; the 17th is one too many.
  EXPECT_EQ(
      loadError(dir + "/many.gltf"),
      dir +
          "/many.gltf: error: /nodes/16/mesh: the file places more than 65536 primitives (counting every node's copy)");
}

// tinygltf 2.7 accepted a BIN chunk whose length counts its own 8-byte header and read 8 bytes
// past the file's memory. The container is checked whole before tinygltf sees it.
TEST(GltfHostile, GlbContainerIsCheckedBeforeTinygltf) {
  const std::string dir = test::scratchDir("gltf-glb");
  const std::string json = quadJson(R"({"byteLength": 244})");
  std::vector<uint8_t> overlong = glb(json, quadBin());
  const size_t binHeader = 12 + 8 + (json.size() + 3) / 4 * 4;  // after the header and the padded JSON chunk
  overlong[binHeader] += 8;                                     // 236 -> 244
  writeBytes(dir + "/overlong.glb", overlong);
  EXPECT_EQ(loadError(dir + "/overlong.glb"),
            dir + "/overlong.glb: error: GLB chunk 1 at byte " + std::to_string(binHeader) +
                ": its 244 bytes reach past the end of the file (" + std::to_string(overlong.size()) + " bytes)");
  const auto edited = [&](const std::string& name, size_t at, uint32_t value) {
    std::vector<uint8_t> bytes = glb(quadJson(R"({"byteLength": 236})"), quadBin());
    std::memcpy(bytes.data() + at, &value, 4);
    writeBytes(dir + "/" + name, bytes);
    return loadError(dir + "/" + name);
  };
  EXPECT_EQ(edited("v1.glb", 4, 1),
            dir + "/v1.glb: error: GLB header: container version 1 (only version 2, glTF 2.0, is read)");
  EXPECT_EQ(edited("long.glb", 8, uint32_t(overlong.size() + 4)),
            dir + "/long.glb: error: GLB header: declares " + std::to_string(overlong.size() + 4) +
                " bytes, but the file has " + std::to_string(overlong.size()));
  const size_t jsonChunk = (json.size() + 3) / 4 * 4;
  EXPECT_EQ(edited("odd.glb", 12, uint32_t(jsonChunk - 2)), dir + "/odd.glb: error: GLB chunk 0 at byte 12: length " +
                                                                std::to_string(jsonChunk - 2) +
                                                                " is not a multiple of 4 (chunks are 4-byte aligned)");
  EXPECT_EQ(
      edited("binfirst.glb", 16, 0x004E4942u),
      dir + "/binfirst.glb: error: GLB chunk 0 at byte 12: the first chunk must be a JSON chunk that is not empty");
  EXPECT_EQ(edited("twojson.glb", binHeader + 4, 0x4E4F534Au), dir + "/twojson.glb: error: GLB chunk 1 at byte " +
                                                                   std::to_string(binHeader) +
                                                                   ": a JSON chunk may only come first");
  // JSON errors in a .glb are placed in its JSON chunk.
  writeBytes(dir + "/syntax.glb", glb("{\"asset\": nope}", {}));
  EXPECT_EQ(loadError(dir + "/syntax.glb")
                .rfind(dir + "/syntax.glb:1:12: error: in the JSON chunk at byte 20: invalid JSON: ", 0),
            0u)
      << loadError(dir + "/syntax.glb");
  // Through a scene.
  EXPECT_NE(sceneError(dir, "overlong.glb").find("object 0: " + dir + "/overlong.glb: error: GLB chunk 1 at byte"),
            std::string::npos);
}

// Buffers are confined by real paths, like a scene's images: a symbolic link inside the folder
// that leads out used to be followed (the check compared the text of the path).
TEST(GltfHostile, BufferLinksLeadingOutAreRefused) {
  const std::string dir = test::scratchDir("gltf-links");
  fs::create_directories(dir + "/scene/models");
  writeBytes(dir + "/secret.bin", quadBin());
  fs::create_symlink(dir + "/secret.bin", dir + "/scene/models/link.bin");
  fs::create_directory_symlink(dir, dir + "/scene/models/up");
  const std::string expected =
      "' is outside the folder this glTF file may read buffers from (" + dir + "/scene/models)";
  EXPECT_EQ(loadError(test::writeQuad(dir + "/scene/models", "link.bin", test::kQuadScene, "link.gltf")),
            dir + "/scene/models/link.gltf: error: /buffers/0/uri: 'link.bin" + expected);
  EXPECT_EQ(loadError(test::writeQuad(dir + "/scene/models", "up/secret.bin", test::kQuadScene, "up.gltf")),
            dir + "/scene/models/up.gltf: error: /buffers/0/uri: 'up/secret.bin" + expected);
  // In a scene, buffers follow the images' rule: anywhere under the asset root (the scene's
  // folder unless the app widens it), here one folder above the glTF's own.
  writeBytes(dir + "/scene/quad.bin", quadBin());
  test::writeQuad(dir + "/scene/models", "../quad.bin", test::kQuadScene, "shared.gltf");
  EXPECT_NE(loadError(dir + "/scene/models/shared.gltf").find("'../quad.bin' is outside"), std::string::npos);
  std::string error;
  EXPECT_TRUE(loadGltfMesh(dir + "/scene/models/shared.gltf", &error, {dir + "/scene"})) << error;
  EXPECT_EQ(sceneError(dir + "/scene", "models/link.gltf"),
            "object 0: " + dir +
                "/scene/models/link.gltf: error: /buffers/0/uri: 'link.bin' is outside the folder this glTF "
                "file may read buffers from (" +
                dir + "/scene)");
  // Widened to the folder holding the link's target, the same file loads.
  EXPECT_TRUE(loadGltfMesh(dir + "/scene/models/link.gltf", &error, {dir})) << error;
}

// A path outside the folder gets the same answer whether or not its file exists: the error used
// to say "File not found" for one and "outside" for the other, so a scene could probe the
// machine's files. Dangling links count by their target.
TEST(GltfHostile, OutsidePathsDoNotRevealWhetherFilesExist) {
  const std::string dir = test::scratchDir("gltf-oracle");
  fs::create_directories(dir + "/scene");
  writeBytes(dir + "/exists.bin", quadBin());
  fs::create_symlink(dir + "/exists.bin", dir + "/scene/to-existing.bin");
  fs::create_symlink(dir + "/missing.bin", dir + "/scene/to-missing.bin");
  // The message without the quoted name.
  const auto unnamed = [](const std::string& message) {
    const size_t open = message.find('\''), close = message.find('\'', open + 1);
    return close == std::string::npos ? message : message.substr(0, open) + message.substr(close + 1);
  };
  const auto errorFor = [&](const std::string& uri) {
    return unnamed(loadError(test::writeQuad(dir + "/scene", uri, test::kQuadScene, "q.gltf")));
  };
  EXPECT_EQ(errorFor("../exists.bin"), errorFor("../missing.bin"));
  EXPECT_EQ(errorFor("to-existing.bin"), errorFor("to-missing.bin"));
  EXPECT_EQ(errorFor(dir + "/exists.bin"), errorFor(dir + "/missing.bin"));
  EXPECT_NE(errorFor("to-missing.bin").find("is outside the folder"), std::string::npos) << errorFor("to-missing.bin");
  // Inside the folder, a missing file is simply missing.
  EXPECT_NE(errorFor("absent.bin").find("/buffers/0/uri:  does not exist"), std::string::npos)
      << errorFor("absent.bin");
  // The scene's own paths (meshes, images) follow the same rule.
  writeText(dir + "/exists.gltf", "{}");
  fs::create_symlink(dir + "/exists.gltf", dir + "/scene/to-existing.gltf");
  fs::create_symlink(dir + "/missing.gltf", dir + "/scene/to-missing.gltf");
  const auto sceneErrorFor = [&](const std::string& mesh) { return unnamed(sceneError(dir + "/scene", mesh)); };
  EXPECT_EQ(sceneErrorFor("to-existing.gltf"), sceneErrorFor("to-missing.gltf"));
  EXPECT_EQ(sceneErrorFor("../exists.gltf"), sceneErrorFor("../missing.gltf"));
  EXPECT_NE(
      sceneErrorFor("to-missing.gltf").find("/objects/0/mesh:  is outside the folder this scene may read files from"),
      std::string::npos)
      << sceneErrorFor("to-missing.gltf");
}

// Every value Facet reads must be finite (only positions were checked: NaN normals, tangents or
// texture coordinates turned objects flat grey or black); normals and tangents need a direction,
// and a tangent's w is the bitangent's sign, +1 or -1.
TEST(GltfHostile, AttributeValuesAreChecked) {
  const std::string dir = test::scratchDir("gltf-values");
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const auto attribute = [](const std::string& name, int accessor, size_t element, const std::string& why) {
    return "/meshes/0/primitives/0/attributes/" + name + ": /accessors/" + std::to_string(accessor) + " element " +
           std::to_string(element) + why;
  };
  const auto edited = [&](const std::string& name, size_t at, float value) {
    std::vector<uint8_t> bin = quadBin();
    setFloat(&bin, at, value);
    return loadError(writeEditedQuad(dir, name, bin));
  };
  EXPECT_EQ(edited("nan-normal", 48 + 2 * 12 + 4, nan),
            dir + "/nan-normal.gltf: error: " + attribute("NORMAL", 1, 2, " is not finite"));
  std::vector<uint8_t> bin = quadBin();
  setFloat(&bin, 48 + 3 * 12 + 8, 0);  // normal 3: (0, 0, 0)
  EXPECT_EQ(loadError(writeEditedQuad(dir, "zero-normal", bin)),
            dir + "/zero-normal.gltf: error: " +
                attribute("NORMAL", 1, 3, " is shorter than 1e-6 (a normal needs a direction)"));
  EXPECT_EQ(edited("nan-tangent", 96 + 16 + 4, nan),
            dir + "/nan-tangent.gltf: error: " + attribute("TANGENT", 2, 1, " is not finite"));
  EXPECT_EQ(edited("half-w", 96 + 12, 0.5f),
            dir + "/half-w.gltf: error: " +
                attribute("TANGENT", 2, 0, ": w is 0.500000, not +1 or -1 (the bitangent's sign)"));
  bin = quadBin();
  setFloat(&bin, 96, 0);  // tangent 0: (0, 0, 0, 1)
  EXPECT_EQ(loadError(writeEditedQuad(dir, "zero-tangent", bin)),
            dir + "/zero-tangent.gltf: error: " +
                attribute("TANGENT", 2, 0, ": xyz is shorter than 1e-6 (a tangent needs a direction)"));
  EXPECT_EQ(edited("inf-uv", 160 + 3 * 8, -inf),
            dir + "/inf-uv.gltf: error: " + attribute("TEXCOORD_0", 3, 3, " is not finite"));
  EXPECT_EQ(edited("nan-position", 4, nan),
            dir + "/nan-position.gltf: error: " + attribute("POSITION", 0, 0, " is not finite"));
  // Float colours: COLOR_0 read from the tangents' floats, one of them infinite.
  bin = quadBin();
  setFloat(&bin, 96 + 2 * 16 + 12, inf);
  std::string json = quadJson(R"({"uri": "colour.bin", "byteLength": 236})");
  json.replace(json.find(R"("TANGENT": 2, )"), 14, "");
  json.replace(json.find(R"("COLOR_0": 5)"), 12, R"("COLOR_0": 2)");
  EXPECT_EQ(loadError(writeEditedQuad(dir, "colour", bin, json)),
            dir + "/colour.gltf: error: " + attribute("COLOR_0", 2, 2, " is not finite"));
  // A normal that is not unit length (here 2) is normalised, not refused.
  bin = quadBin();
  setFloat(&bin, 48 + 8, 2);
  std::string error;
  auto mesh = loadGltfMesh(writeEditedQuad(dir, "long-normal", bin), &error);
  ASSERT_TRUE(mesh) << error;
  EXPECT_EQ(mesh->vertices[5], 1.0f);  // vertex 0's normal z (runtime::Vertex: position, then normal)
  // Through a scene.
  EXPECT_EQ(sceneError(dir, "nan-normal.gltf"),
            "object 0: " + dir + "/nan-normal.gltf: error: " + attribute("NORMAL", 1, 2, " is not finite"));
}

// What the spec says a loader must refuse, and what tinygltf lets through.
TEST(GltfHostile, SpecRulesTinygltfIgnoresAreEnforced) {
  const std::string dir = test::scratchDir("gltf-spec");
  const auto withJson = [&](const std::string& name, std::string json) {
    writeBytes(dir + "/quad.bin", quadBin());
    writeText(dir + "/" + name, json);
    return loadError(dir + "/" + name);
  };
  const std::string quad = quadJson(R"({"uri": "quad.bin", "byteLength": 236})");
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string json = quad;
    return json.replace(json.find(from), from.size(), to);
  };
  // A file that requires an extension this loader lacks must not be loaded (glTF 2.0 §3.12).
  EXPECT_EQ(
      withJson("draco.gltf",
               replaced(R"("asset": {"version": "2.0"},)",
                        R"("asset": {"version": "2.0"}, "extensionsRequired": ["KHR_draco_mesh_compression"],)")),
      dir +
          "/draco.gltf: error: /extensionsRequired/0: the file requires extension 'KHR_draco_mesh_compression', which "
          "this loader does not implement (it implements KHR_mesh_quantization and KHR_texture_transform; the glTF "
          "spec says such a file "
          "must not be loaded)");
  // KHR_mesh_quantization is implemented; an unknown one after it is still named.
  EXPECT_EQ(withJson("after.gltf", replaced(R"("asset": {"version": "2.0"},)",
                                            R"("asset": {"version": "2.0"}, "extensionsUsed": ["KHR_mesh_quantization"],
                                 "extensionsRequired": ["KHR_mesh_quantization", "EXT_meshopt_compression"],)")),
            dir +
                "/after.gltf: error: /extensionsRequired/1: the file requires extension 'EXT_meshopt_compression', "
                "which this loader does not implement (it implements KHR_mesh_quantization and KHR_texture_transform; "
                "the glTF spec says "
                "such a file must not be loaded)");
  // byteStride, when present: a multiple of 4 in 4..252 (tinygltf ignored 0 and negative ones).
  for (const char* stride : {"0", "-12", "6", "256", "12.5"}) {
    EXPECT_EQ(withJson("stride.gltf",
                       replaced(R"("byteOffset": 0, "byteLength": 224})",
                                R"("byteOffset": 0, "byteLength": 224, "byteStride": )" + std::string(stride) + "}")),
              dir + "/stride.gltf: error: /bufferViews/0/byteStride: " + stride +
                  " is not a multiple of 4 in 4..252 (glTF 2.0 bufferView.byteStride)");
  }
  // Versions: 2.x only, and no minVersion above 2.0.
  EXPECT_EQ(withJson("v1.gltf", replaced(R"("version": "2.0")", R"("version": "1.0")")),
            dir + "/v1.gltf: error: /asset/version: '1.0' is not a glTF 2.x version (this loader reads glTF 2.0)");
  EXPECT_EQ(
      withJson("min.gltf", replaced(R"("version": "2.0")", R"("version": "2.1", "minVersion": "2.1")")),
      dir +
          "/min.gltf: error: /asset/minVersion: '2.1' is not a version this loader supports (glTF 2.0), or is above "
          "the asset's version");
  std::string error;
  writeText(dir + "/v21.gltf", replaced(R"("version": "2.0")", R"("version": "2.1", "minVersion": "2.0")"));
  EXPECT_TRUE(loadGltfMesh(dir + "/v21.gltf", &error)) << error;
  // URIs: a NUL used to cut the path short (here to quad.bin); %-escapes are decoded as RFC 3986
  // says, and '+' is a plus (tinygltf read it as a space).
  EXPECT_EQ(
      withJson("nul.gltf", replaced(R"("uri": "quad.bin")", R"("uri": "quad.bin\u0000.png")")),
      dir +
          "/nul.gltf: error: /buffers/0/uri: 'quad.bin\\u0000.png' holds a NUL character, which would cut the file "
          "name short");
  EXPECT_EQ(withJson("pct.gltf", replaced(R"("uri": "quad.bin")", R"("uri": "quad.bin%00.png")")),
            dir + "/pct.gltf: error: /buffers/0/uri: 'quad.bin%00.png' has a malformed %-escape or %00 at character 8");
  EXPECT_EQ(
      withJson("http.gltf", replaced(R"("uri": "quad.bin")", R"("uri": "http://example.com/quad.bin")")),
      dir +
          "/http.gltf: error: /buffers/0/uri: 'http://example.com/quad.bin' is neither a relative path nor a base64 "
          "data: URI of type application/octet-stream or application/gltf-buffer");
  writeBytes(dir + "/my quad+1.bin", quadBin());
  writeText(dir + "/escaped.gltf", replaced(R"("uri": "quad.bin")", R"("uri": "my%20quad+1.bin")"));
  EXPECT_TRUE(loadGltfMesh(dir + "/escaped.gltf", &error)) << error;
  // A .glb gives each buffer without a uri a copy of its BIN chunk: only the first may omit it.
  std::string many = quadJson(R"({"byteLength": 236}, {"byteLength": 236})");
  writeBytes(dir + "/copies.glb", glb(many, quadBin()));
  EXPECT_EQ(loadError(dir + "/copies.glb"),
            dir +
                "/copies.glb: error: /buffers/1: no uri (only the first buffer of a .glb "
                "may omit it, for the BIN chunk)");
  // An empty buffer (the schema's minimum is 1): tinygltf threw std::out_of_range copying a
  // .glb's BIN chunk into it, which ended the process.
  writeBytes(dir + "/empty.glb", glb(quadJson(R"({"byteLength": 0})"), quadBin()));
  EXPECT_EQ(loadError(dir + "/empty.glb"),
            dir + "/empty.glb: error: /buffers/0/byteLength: expected a whole number of bytes, at least 1");
  // tinygltf's own errors are kept short and on one line (it quotes names in full).
  const std::string name(1 << 20, 'n');
  const std::string error2 = withJson(
      "named.gltf", replaced(R"("meshes": [)", R"("images": [{"name": ")" + name +
                                                   "\", \"uri\": \"a.png\", \"bufferView\": 0}],\n  \"meshes\": ["));
  EXPECT_EQ(error2.rfind(dir + "/named.gltf: error: Only one of `bufferView` or `uri` should be defined", 0), 0u)
      << error2.substr(0, 300);
  EXPECT_NE(error2.find("...("), std::string::npos);
  EXPECT_LT(error2.size(), 600u);
  EXPECT_EQ(error2.find('\n'), std::string::npos);
  // `extensions` is an object of objects wherever it appears (tinygltf dropped any other value,
  // so a material's sheen given as a number was imported without it); `extras` is left free.
  EXPECT_EQ(
      withJson("extnum.gltf", replaced(R"("meshes": [)", R"("materials": [{"extensions": {"KHR_materials_sheen": 1}}],
  "meshes": [)")),
      dir +
          "/extnum.gltf: error: /materials/0/extensions/KHR_materials_sheen: expected an object (an "
          "extension's value in glTF 2.0), got number");
  EXPECT_EQ(withJson("extarr.gltf",
                     replaced(R"("asset": {"version": "2.0"},)", R"("asset": {"version": "2.0", "extensions": []},)")),
            dir +
                "/extarr.gltf: error: /asset/extensions: expected an object (glTF 2.0's extensions, one member per "
                "extension), got array");
  EXPECT_EQ(withJson("extdeep.gltf", replaced(R"("indices": 6)", R"("indices": 6, "extensions": {"a/b~": "x"})")),
            dir +
                "/extdeep.gltf: error: /meshes/0/primitives/0/extensions/a~1b~0: expected an object (an "
                "extension's value in glTF 2.0), got string");
  writeText(dir + "/extras.gltf", replaced(R"("asset": {"version": "2.0"},)",
                                           R"("asset": {"version": "2.0", "extras": {"extensions": 3},
  "extensions": {"EXT_unknown": {"extensions": {}}}},)"));
  EXPECT_TRUE(loadGltfMesh(dir + "/extras.gltf", &error)) << error;
  // Through a scene.
  EXPECT_NE(sceneError(dir, "draco.gltf").find("object 0: " + dir + "/draco.gltf: error: /extensionsRequired/0:"),
            std::string::npos);
}

// The fuzzer's seeds are valid files that load (so fuzzing starts from inputs reaching the mesh
// builder), and every input it ever failed on ends in a mesh or an error naming the file, read
// as fuzz_gltf reads them (tests/fuzz/gltf_fuzz_input.h). A mesh that loads also packs for
// upload, as in fuzz_gltf: only UV bounds too far apart for a finite scale may stop it. Run in
// the ASan + UBSan build too.
TEST(GltfHostile, FuzzSeedsLoadAndFindingsEndInErrors) {
  const std::string dir = test::scratchDir("gltf-fuzz-inputs");
  size_t seeds = 0, findings = 0;
  for (const char* folder : {"gltf_corpus", "gltf_regressions"}) {
    for (const auto& entry : fs::directory_iterator(test::sourceDir() + "/tests/fuzz/" + folder)) {
      if (entry.path().filename() == "README.md") continue;
      SCOPED_TRACE(entry.path().string());
      const std::string path = fuzz::writeGltfFuzzInput(test::readText(entry.path().string()), dir);
      std::string error;
      auto mesh = loadGltfMesh(path, &error);
      if (std::string(folder) == "gltf_corpus") {
        EXPECT_TRUE(mesh) << error;
        ++seeds;
      } else {
        EXPECT_TRUE(mesh || error.rfind(path + ":", 0) == 0) << error;
        ++findings;
      }
      if (mesh) {
        EXPECT_TRUE(fuzz::packsAfterLoading(*mesh, &error)) << error;
      }
    }
  }
  EXPECT_GE(seeds, 8u);  // quantized.gltf: KHR_mesh_quantization
  EXPECT_GE(findings, 2u);
}

}  // namespace facet::runtime
