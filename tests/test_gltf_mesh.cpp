// glTF 2.0 meshes (runtime/gltf_mesh.h) and their use from scenes: attributes read into the
// ABI's vertex layout, clear errors for bad files, and a scene drawing one.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "facet/render_backend.h"
#include "facet/runtime/gltf_mesh.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/scene.h"
#include "facet/runtime/scene_frame.h"
#include "test_support.h"

namespace facet::runtime {
namespace {

void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}
void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

template <class T>
void append(std::vector<uint8_t>* bytes, std::initializer_list<T> values) {
  for (T v : values) {
    const size_t at = bytes->size();
    bytes->resize(at + sizeof(T));
    std::memcpy(bytes->data() + at, &v, sizeof(T));
  }
}

// A unit quad in z = 0 facing +z, every attribute the runtime reads, in quad.bin beside it:
// positions, normals, tangents (float), uv0 (float), uv1 (normalised ushort), colour (normalised
// ubyte VEC4), indices (ushort).
std::string writeQuad(const std::string& dir, const std::string& binUri = "quad.bin") {
  std::vector<uint8_t> bin;
  append<float>(&bin, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});                           // 0: 48
  append<float>(&bin, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});                               // 48: 48
  append<float>(&bin, {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -1});                  // 96: 64
  append<float>(&bin, {0, 0, 1, 0, 1, 1, 0, 1});                                           // 160: 32
  append<uint16_t>(&bin, {0, 0, 65535, 0, 65535, 65535, 0, 65535});                        // 192: 16
  append<uint8_t>(&bin, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 51});  // 208: 16
  append<uint16_t>(&bin, {0, 1, 2, 0, 2, 3});                                              // 224: 12
  writeBytes(dir + "/quad.bin", bin);
  const std::string gltf = R"({"asset": {"version": "2.0"},
  "buffers": [{"uri": ")" + binUri + R"(", "byteLength": 236}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 224}, {"buffer": 0, "byteOffset": 224, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
    {"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC3"},
    {"bufferView": 0, "byteOffset": 96, "componentType": 5126, "count": 4, "type": "VEC4"},
    {"bufferView": 0, "byteOffset": 160, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 0, "byteOffset": 192, "componentType": 5123, "normalized": true, "count": 4, "type": "VEC2"},
    {"bufferView": 0, "byteOffset": 208, "componentType": 5121, "normalized": true, "count": 4, "type": "VEC4"},
    {"bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TANGENT": 2, "TEXCOORD_0": 3,
    "TEXCOORD_1": 4, "COLOR_0": 5}, "indices": 6}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
  writeText(dir + "/quad.gltf", gltf);
  return dir + "/quad.gltf";
}

Vertex vertexAt(const Mesh& mesh, size_t i) {
  Vertex v;
  std::memcpy(static_cast<void*>(&v), mesh.vertices.data() + i * abi::kVertexFloats, sizeof v);
  return v;
}

TEST(GltfMesh, ReadsEveryAttributeIntoTheVertexLayout) {
  const std::string dir = test::scratchDir("gltf-attributes");
  std::string error;
  auto mesh = loadGltfMesh(writeQuad(dir), &error);
  ASSERT_TRUE(mesh) << error;
  ASSERT_EQ(mesh->vertices.size(), 4 * abi::kVertexFloats);
  EXPECT_EQ(mesh->indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  const Vertex v2 = vertexAt(*mesh, 2), v3 = vertexAt(*mesh, 3);
  EXPECT_EQ(v2.position[0], 1.0f);
  EXPECT_EQ(v2.position[1], 1.0f);
  EXPECT_EQ(v2.normal[2], 1.0f);
  EXPECT_EQ(v3.tangent[3], -1.0f);
  EXPECT_EQ(v2.uv0[0], 1.0f);
  EXPECT_EQ(v2.uv0[1], 1.0f);
  EXPECT_EQ(v2.uv1[0], 1.0f);  // 65535, normalised
  EXPECT_EQ(v3.uv1[0], 0.0f);
  EXPECT_EQ(v2.color[2], 1.0f);  // 255, normalised
  EXPECT_EQ(v2.color[0], 0.0f);
  EXPECT_FLOAT_EQ(v3.color[3], 0.2f);  // 51 / 255
}

TEST(GltfMesh, BadFilesGiveErrorsNamingTheFileAndField) {
  const std::string dir = test::scratchDir("gltf-errors");
  std::string error;
  EXPECT_FALSE(loadGltfMesh(dir + "/missing.gltf", &error));
  EXPECT_NE(error.find("missing.gltf: error: cannot open the glTF file: it does not exist"), std::string::npos) << error;
  std::filesystem::create_directory(dir + "/folder.gltf");
  EXPECT_FALSE(loadGltfMesh(dir + "/folder.gltf", &error));
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  writeText(dir + "/broken.gltf", "{ not json");
  EXPECT_FALSE(loadGltfMesh(dir + "/broken.gltf", &error));
  EXPECT_NE(error.find("broken.gltf: error: "), std::string::npos) << error;
  // A buffer outside the file's folder is not read.
  std::filesystem::create_directory(dir + "/sub");
  writeQuad(dir);
  const std::string escaping = writeQuad(dir + "/sub", "../quad.bin");
  EXPECT_FALSE(loadGltfMesh(escaping, &error));
  EXPECT_NE(error.find("outside the glTF file's folder"), std::string::npos) << error;
  // An index past the vertices.
  std::string text = test::readText(writeQuad(dir));
  std::vector<uint8_t> bin;
  {
    std::ifstream in(dir + "/quad.bin", std::ios::binary);
    bin.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  bin[224 + 2 * 5] = 9;  // the last index: 9 of 4 vertices
  writeBytes(dir + "/quad.bin", bin);
  EXPECT_FALSE(loadGltfMesh(dir + "/quad.gltf", &error));
  EXPECT_NE(error.find("/meshes/0/primitives/0/indices: index 9 is past the 4 vertices"), std::string::npos) << error;
  // An accessor reaching past its buffer view.
  writeQuad(dir);
  const std::string tooLong = std::string(text).replace(text.find("\"count\": 6"), 10, "\"count\": 60");
  writeText(dir + "/long.gltf", tooLong);
  EXPECT_FALSE(loadGltfMesh(dir + "/long.gltf", &error));
  EXPECT_NE(error.find("/meshes/0/primitives/0/indices: accessor 6 reaches past"), std::string::npos) << error;
}

TEST(GltfMesh, SceneObjectDrawsAGltfMeshInsideTheScenesFolder) {
  const std::string packages = test::writePackagesFromTexts(
      "gltf-scene", {"material flat_colour { shading unlit\n param c: color = vec3(0.8, 0.4, 0.2)\n"
                     " surface { baseColor = params.c } }"});
  const std::string dir = test::scratchDir("gltf-scene-files");
  writeQuad(dir);
  const auto sceneWith = [](const std::string& mesh) {
    return R"({"width": 32, "height": 32, "sky": {"luminance": 6000}, "camera": {"position": [0, 0, 4], "fovY": 40},
      "objects": [{"mesh": ")" + mesh + R"(", "material": "flat_colour"}, {"mesh": ")" + mesh +
           R"(", "material": "flat_colour", "position": [5, 0, 0]}]})";
  };
  std::string error;
  VulkanOptions options;
  options.validation = true;
  auto backend = createVulkanBackend(options, &error);
  ASSERT_NE(backend, nullptr) << error;
  const auto render = [&](const std::string& mesh, FrameResult* result) {
    auto scene = parseScene(dir + "/scene.json", sceneWith(mesh), &error);
    if (!scene) return false;
    auto frame = SceneFrame::prepare(*scene, packages, &error);
    if (!frame) return false;
    // Both objects share the file's one Mesh.
    EXPECT_EQ(frame->frame().draws[0].mesh, frame->frame().draws[1].mesh);
    return backend->render(frame->frame(), result, &error);
  };
  FrameResult quad, sphere;
  ASSERT_TRUE(render("quad.gltf", &quad)) << error;
  ASSERT_TRUE(render("sphere", &sphere)) << error;
  // Unlit: the centre is the material's colour, whichever mesh covers it.
  const size_t centre = (16 * 32 + 16) * 4;
  for (int c = 0; c < 3; ++c) EXPECT_EQ(quad.hdr[centre + c], sphere.hdr[centre + c]) << c;
  // The quad (2 x 2) covers more of the frame than the unit sphere does: near a corner of the
  // sphere's bounding square (the quad reaches 11 pixels from the centre, the sphere's silhouette
  // 11.35 pixels round it) the sphere shows the background and the quad its colour.
  const size_t corner = (7 * 32 + 7) * 4;
  EXPECT_EQ(quad.hdr[corner], quad.hdr[centre]);
  EXPECT_NE(sphere.hdr[corner], sphere.hdr[centre]);
  EXPECT_TRUE(backend->validationErrors().empty());

  // A mesh file outside the scene's folder is refused when the scene is read.
  EXPECT_FALSE(parseScene(dir + "/scene.json", sceneWith("../quad.gltf"), &error));
  EXPECT_NE(error.find("/objects/0/mesh"), std::string::npos) << error;
  EXPECT_NE(error.find("is outside the folder this scene may read files from"), std::string::npos) << error;
  EXPECT_FALSE(parseScene(dir + "/scene.json", sceneWith("quad.obj"), &error));
  EXPECT_NE(error.find("unknown mesh"), std::string::npos) << error;
}

}  // namespace
}  // namespace facet::runtime
