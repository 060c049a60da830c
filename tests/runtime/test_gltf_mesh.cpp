// glTF 2.0 meshes (runtime/gltf_mesh.h) and their use from scenes: attributes read into the
// ABI's vertex layout, clear errors for bad files, and a scene drawing one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "facet/runtime/gltf_mesh.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/scene/scene.h"
#include "gltf_test_files.h"
#include "test_compile.h"
#include "test_support.h"

namespace facet::runtime {
namespace {

using test::append;
using test::quadBin;
using test::writeBytes;
using test::writeQuad;
using test::writeQuadGlb;
using test::writeText;

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

TEST(GltfMesh, BinaryGlbReadsLikeItsGltf) {
  const std::string dir = test::scratchDir("gltf-glb");
  std::string error;
  auto glb = loadGltfMesh(writeQuadGlb(dir), &error);
  ASSERT_TRUE(glb) << error;
  auto gltf = loadGltfMesh(writeQuad(dir), &error);
  ASSERT_TRUE(gltf) << error;
  EXPECT_EQ(glb->vertices, gltf->vertices);
  EXPECT_EQ(glb->indices, gltf->indices);
  // A .glb cut short is an error naming the file, not a read past its end.
  std::ifstream in(dir + "/quad.glb", std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  bytes.resize(bytes.size() - 40);
  writeBytes(dir + "/short.glb", bytes);
  EXPECT_FALSE(loadGltfMesh(dir + "/short.glb", &error));
  EXPECT_NE(error.find("short.glb: error: "), std::string::npos) << error;
}

// Node transforms (glTF 2.0 §3.5.3): a parent with translation, rotation and scale, a child with a
// matrix; the mesh is placed by parent · child. Normals follow the inverse transpose.
TEST(GltfMesh, NodeHierarchyPlacesTheMesh) {
  const std::string dir = test::scratchDir("gltf-nodes");
  // Parent: translate (10, 0, 0), rotate 90° about +y (x, y, z, w), scale 2. Child: a matrix
  // (column-major) translating by (0, 3, 0) and scaling z by 5 (the quad's z is 0: no effect on
  // positions, but the normal +z must stay unit length).
  const std::string scene = R"("nodes": [
      {"children": [1], "translation": [10, 0, 0], "rotation": [0, 0.70710678, 0, 0.70710678], "scale": [2, 2, 2]},
      {"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,5,0, 0,3,0,1]},
      {"mesh": 0}],
    "scenes": [{"nodes": [0]}], "scene": 0)";
  std::string error;
  auto mesh = loadGltfMesh(writeQuad(dir, "quad.bin", scene), &error);
  ASSERT_TRUE(mesh) << error;
  // Only the scene's tree is drawn: node 2 (not in the scene) adds nothing.
  ASSERT_EQ(mesh->vertices.size(), 4 * abi::kVertexFloats);
  // Vertex 2 is (1, 1, 0): child → (1, 4, 0); scale 2 → (2, 8, 0); rotate 90° about y sends +x
  // to −z → (0, 8, −2); translate → (10, 8, −2).
  const Vertex v2 = vertexAt(*mesh, 2);
  EXPECT_NEAR(v2.position[0], 10.0f, 1e-5f);
  EXPECT_NEAR(v2.position[1], 8.0f, 1e-5f);
  EXPECT_NEAR(v2.position[2], -2.0f, 1e-5f);
  // Normal +z: rotated to +x, unit length despite both scales.
  EXPECT_NEAR(v2.normal[0], 1.0f, 1e-6f);
  EXPECT_NEAR(v2.normal[1], 0.0f, 1e-6f);
  EXPECT_NEAR(v2.normal[2], 0.0f, 1e-6f);
  // Tangent +x: rotated to −z, handedness kept.
  EXPECT_NEAR(v2.tangent[2], -1.0f, 1e-6f);
  EXPECT_EQ(v2.tangent[3], 1.0f);
  EXPECT_EQ(mesh->indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));

  // A mirror (scale −1 in x) keeps triangles front-facing: the winding and the tangent's
  // handedness flip.
  auto mirrored =
      loadGltfMesh(writeQuad(dir, "quad.bin",
                             R"("nodes": [{"mesh": 0, "scale": [-1, 1, 1]}], "scenes": [{"nodes": [0]}])", "m.gltf"),
                   &error);
  ASSERT_TRUE(mirrored) << error;
  EXPECT_EQ(mirrored->indices, (std::vector<uint32_t>{0, 2, 1, 0, 3, 2}));
  EXPECT_EQ(vertexAt(*mirrored, 2).position[0], -1.0f);
  EXPECT_EQ(vertexAt(*mirrored, 2).tangent[0], -1.0f);
  EXPECT_EQ(vertexAt(*mirrored, 2).tangent[3], -1.0f);
  EXPECT_EQ(vertexAt(*mirrored, 2).normal[2], 1.0f);

  // A node reached twice (here a cycle) is an error naming it, not an endless walk.
  EXPECT_FALSE(loadGltfMesh(
      writeQuad(dir, "quad.bin",
                R"("nodes": [{"children": [1]}, {"mesh": 0, "children": [0]}], "scenes": [{"nodes": [0]}])",
                "cycle.gltf"),
      &error));
  EXPECT_NE(error.find("cycle.gltf: error: /nodes/0: reached twice"), std::string::npos) << error;
}

// Sparse accessors (glTF 2.0 §3.6.2.3): listed elements replace the base values, which come from
// a buffer view or, without one, are zeros.
TEST(GltfMesh, SparseAccessorsSubstituteTheirElements) {
  const std::string dir = test::scratchDir("gltf-sparse");
  std::vector<uint8_t> bin;
  append<float>(&bin, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});  // 0: the quad's positions
  append<uint16_t>(&bin, {0, 1, 2, 0, 2, 3, 0, 0});               // 48: indices, padding
  append<uint16_t>(&bin, {2, 0});                                 // 64: sparse index 2, padding
  append<float>(&bin, {5, 6, 0});                                 // 68: its value
  append<uint32_t>(&bin, {0, 1, 2, 3});                           // 80: sparse indices 0..3
  append<float>(&bin, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});  // 96: their values
  writeBytes(dir + "/sparse.bin", bin);
  // bufferView 0: positions, 1: indices, 2: the sparse data (offsets above minus 64).
  const auto write = [&](const std::string& name, const std::string& positions) {
    writeText(dir + "/" + name, R"({"asset": {"version": "2.0"},
      "buffers": [{"uri": "sparse.bin", "byteLength": 144}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12},
                      {"buffer": 0, "byteOffset": 64, "byteLength": 80}],
      "accessors": [)" + positions + R"(,
                    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}]})");
    return dir + "/" + name;
  };
  std::string error;
  // Base from the buffer view, element 2 replaced by (5, 6, 0).
  auto over = loadGltfMesh(write("over.gltf", R"({"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
      "sparse": {"count": 1, "indices": {"bufferView": 2, "componentType": 5123}, "values": {"bufferView": 2, "byteOffset": 4}}})"),
                           &error);
  ASSERT_TRUE(over) << error;
  EXPECT_EQ(vertexAt(*over, 1).position[0], 1.0f);
  EXPECT_EQ(vertexAt(*over, 2).position[0], 5.0f);
  EXPECT_EQ(vertexAt(*over, 2).position[1], 6.0f);
  // No buffer view: zeros, here every element replaced: the plain quad.
  auto zeros = loadGltfMesh(write("zeros.gltf", R"({"componentType": 5126, "count": 4, "type": "VEC3",
      "sparse": {"count": 4, "indices": {"bufferView": 2, "byteOffset": 16, "componentType": 5125},
                 "values": {"bufferView": 2, "byteOffset": 32}}})"),
                            &error);
  ASSERT_TRUE(zeros) << error;
  const float quad[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  for (size_t v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(vertexAt(*zeros, v).position[c], quad[v][c]) << v << " " << c;
  // A sparse index past the accessor's elements is refused, naming the accessor.
  EXPECT_FALSE(loadGltfMesh(write("past.gltf", R"({"bufferView": 0, "componentType": 5126, "count": 2, "type": "VEC3",
      "sparse": {"count": 1, "indices": {"bufferView": 2, "componentType": 5123}, "values": {"bufferView": 2, "byteOffset": 4}}})"),
                            &error));
  EXPECT_NE(
      error.find("past.gltf: error: /meshes/0/primitives/0/attributes/POSITION: accessor 0 sparse index 2 (entry 0) "
                 "is past the elements"),
      std::string::npos)
      << error;
}

// KHR_mesh_quantization: integer positions, normals, tangents and UVs, normalized or not, read
// as the extension's table and glTF 2.0 §3.11 say (signed normalized: max(c / (2^(b−1) − 1), −1)).
TEST(GltfMesh, QuantizedAttributesReadAsKhrMeshQuantizationSays) {
  const std::string dir = test::scratchDir("gltf-quantized");
  std::vector<uint8_t> bin;
  // 0: positions, SHORT normalized VEC3, stride 8 (each element 4-byte aligned).
  append<int16_t>(&bin, {-32767, -32767, 0, 0, 32767, -32768, 0, 0, 32767, 32767, 0, 0, -32767, 32767, 16384, 0});
  append<int8_t>(&bin, {0, 0, 127, 0, 0, 0, 127, 0, 0, 90, 90, 0, 0, 0, -128, 0});  // 32: normals, BYTE normalized
  append<int8_t>(&bin, {127, 0, 0, 127, 127, 0, 0, 127, 127, 0, 0, -127, 127, 0, 0, -128});  // 48: tangents
  append<uint16_t>(&bin, {0, 0, 3, 0, 3, 3, 0, 3});  // 64: uv0, UNSIGNED_SHORT (not normalized): tiled 3×
  append<int16_t>(&bin, {-32767, 0, 32767, 0, 0, 16384, 0, -32768});        // 80: uv1, SHORT normalized
  append<uint16_t>(&bin, {0, 1, 2, 0, 2, 3});                               // 96: indices
  append<int8_t>(&bin, {-2, 0, 5, 0, 7, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0});  // 108: positions, BYTE (not normalized)
  writeBytes(dir + "/quantized.bin", bin);
  const auto write = [&](const std::string& name, const std::string& extensions, int positionAccessor) {
    writeText(dir + "/" + name, R"({"asset": {"version": "2.0"}, )" + extensions + R"(
      "buffers": [{"uri": "quantized.bin", "byteLength": 124}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 32, "byteStride": 8},
                      {"buffer": 0, "byteOffset": 32, "byteLength": 16, "byteStride": 4},
                      {"buffer": 0, "byteOffset": 48, "byteLength": 16, "byteStride": 4},
                      {"buffer": 0, "byteOffset": 64, "byteLength": 16, "byteStride": 4},
                      {"buffer": 0, "byteOffset": 80, "byteLength": 16, "byteStride": 4},
                      {"buffer": 0, "byteOffset": 96, "byteLength": 12},
                      {"buffer": 0, "byteOffset": 108, "byteLength": 16, "byteStride": 4}],
      "accessors": [{"bufferView": 0, "componentType": 5122, "normalized": true, "count": 4, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5120, "normalized": true, "count": 4, "type": "VEC3"},
                    {"bufferView": 2, "componentType": 5120, "normalized": true, "count": 4, "type": "VEC4"},
                    {"bufferView": 3, "componentType": 5123, "count": 4, "type": "VEC2"},
                    {"bufferView": 4, "componentType": 5122, "normalized": true, "count": 4, "type": "VEC2"},
                    {"bufferView": 5, "componentType": 5123, "count": 6, "type": "SCALAR"},
                    {"bufferView": 6, "componentType": 5120, "count": 4, "type": "VEC3"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
                                    std::to_string(positionAccessor) + R"(, "NORMAL": 1, "TANGENT": 2,
                                   "TEXCOORD_0": 3, "TEXCOORD_1": 4}, "indices": 5}]}],
      "nodes": [{"mesh": 0, "scale": [2, 2, 2]}], "scenes": [{"nodes": [0]}], "scene": 0})");
    return dir + "/" + name;
  };
  const std::string used =
      R"("extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"],)";
  std::string error;
  auto mesh = loadGltfMesh(write("normalized.gltf", used, 0), &error);
  ASSERT_TRUE(mesh) << error;
  ASSERT_EQ(mesh->vertices.size(), 4 * abi::kVertexFloats);
  const Vertex v0 = vertexAt(*mesh, 0), v1 = vertexAt(*mesh, 1), v2 = vertexAt(*mesh, 2), v3 = vertexAt(*mesh, 3);
  EXPECT_EQ(v0.position[0], -2.0f);  // −32767 / 32767, scaled 2 by the node
  EXPECT_EQ(v1.position[1], -2.0f);  // −32768 clamps to −1
  EXPECT_FLOAT_EQ(v3.position[2], float(2 * 16384 / 32767.0));
  EXPECT_EQ(v0.normal[2], 1.0f);                         // 127 / 127
  EXPECT_FLOAT_EQ(v2.normal[1], float(std::sqrt(0.5)));  // (0, 90, 90) / 127, normalised
  EXPECT_EQ(v3.normal[2], -1.0f);                        // −128 clamps to −1
  EXPECT_EQ(v0.tangent[0], 1.0f);
  EXPECT_EQ(v0.tangent[3], 1.0f);
  EXPECT_EQ(v2.tangent[3], -1.0f);  // −127 / 127
  EXPECT_EQ(v3.tangent[3], -1.0f);  // −128 clamps to −1
  EXPECT_EQ(v2.uv0[0], 3.0f);       // not normalized: the integer
  EXPECT_EQ(v2.uv0[1], 3.0f);
  EXPECT_EQ(v0.uv1[0], -1.0f);
  EXPECT_FLOAT_EQ(v2.uv1[1], float(16384 / 32767.0));
  EXPECT_EQ(v3.uv1[1], -1.0f);
  // Non-normalized BYTE positions: the integers, placed by the node.
  auto integers = loadGltfMesh(write("integers.gltf", used, 6), &error);
  ASSERT_TRUE(integers) << error;
  EXPECT_EQ(vertexAt(*integers, 0).position[0], -4.0f);
  EXPECT_EQ(vertexAt(*integers, 0).position[2], 10.0f);
  EXPECT_EQ(vertexAt(*integers, 1).position[0], 14.0f);
  // Without the extension these types are not glTF 2.0: refused, naming the attribute.
  EXPECT_FALSE(loadGltfMesh(write("plain.gltf", "", 0), &error));
  EXPECT_NE(error.find("plain.gltf: error: /meshes/0/primitives/0/attributes/POSITION: accessor 0 has a type or "
                       "component type this attribute cannot have"),
            std::string::npos)
      << error;
  // With it, what the extension's table leaves out still is: non-normalized BYTE normals.
  std::string text = test::readText(write("bad.gltf", used, 0));
  text.replace(text.find(R"("componentType": 5120, "normalized": true, "count": 4, "type": "VEC3")"), 69,
               R"("componentType": 5120, "normalized": false, "count": 4, "type": "VEC3")");
  writeText(dir + "/bad.gltf", text);
  EXPECT_FALSE(loadGltfMesh(dir + "/bad.gltf", &error));
  EXPECT_NE(error.find("bad.gltf: error: /meshes/0/primitives/0/attributes/NORMAL: accessor 1 has a type or "
                       "component type this attribute cannot have"),
            std::string::npos)
      << error;
}

// A few hundred bytes may not make the loader build gigabytes: a sparse accessor without data
// declares a million (zero) vertices, five nodes place it. Refused from the declared counts,
// before any vertex is read.
TEST(GltfMesh, PlacedVertexTotalIsBounded) {
  const std::string dir = test::scratchDir("gltf-bounded");
  std::vector<uint8_t> bin;
  append<uint16_t>(&bin, {0, 0});
  append<float>(&bin, {0, 0, 0});
  writeBytes(dir + "/one.bin", bin);
  writeText(dir + "/many.gltf", R"({"asset": {"version": "2.0"},
    "buffers": [{"uri": "one.bin", "byteLength": 16}],
    "bufferViews": [{"buffer": 0, "byteLength": 16}],
    "accessors": [{"componentType": 5126, "count": 1048575, "type": "VEC3",
      "sparse": {"count": 1, "indices": {"bufferView": 0, "componentType": 5123}, "values": {"bufferView": 0, "byteOffset": 4}}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "nodes": [{"mesh": 0}, {"mesh": 0}, {"mesh": 0}, {"mesh": 0}, {"mesh": 0}],
    "scenes": [{"nodes": [0, 1, 2, 3, 4]}]})");
  std::string error;
  EXPECT_FALSE(loadGltfMesh(dir + "/many.gltf", &error));
  EXPECT_NE(error.find("many.gltf: error: /nodes/4/mesh: the file places more than 4194304 vertices"),
            std::string::npos)
      << error;
}

TEST(GltfMesh, BadFilesGiveErrorsNamingTheFileAndField) {
  const std::string dir = test::scratchDir("gltf-errors");
  std::string error;
  EXPECT_FALSE(loadGltfMesh(dir + "/missing.gltf", &error));
  EXPECT_NE(error.find("missing.gltf: error: cannot open the glTF file: it does not exist"), std::string::npos)
      << error;
  std::filesystem::create_directory(dir + "/folder.gltf");
  EXPECT_FALSE(loadGltfMesh(dir + "/folder.gltf", &error));
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  writeText(dir + "/broken.gltf", "{ not json");
  EXPECT_FALSE(loadGltfMesh(dir + "/broken.gltf", &error));
  EXPECT_NE(error.find("broken.gltf:1:4: error: invalid JSON"), std::string::npos) << error;
  // A buffer outside the file's folder is not read.
  std::filesystem::create_directory(dir + "/sub");
  writeQuad(dir);
  const std::string escaping = writeQuad(dir + "/sub", "../quad.bin");
  EXPECT_FALSE(loadGltfMesh(escaping, &error));
  EXPECT_NE(
      error.find("sub/quad.gltf: error: /buffers/0/uri: '../quad.bin' is outside the folder this glTF file may read "
                 "buffers from"),
      std::string::npos)
      << error;
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
      "objects": [{"mesh": ")" +
           mesh + R"(", "material": "flat_colour"}, {"mesh": ")" + mesh +
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
    // Both objects share the file's one Mesh (and so, opaque with the same material, one
    // instanced draw).
    const std::vector<DrawItem> draws = oneDrawPerInstance(frame->frame().draws);
    if (draws.size() != 2) return false;
    EXPECT_EQ(draws[0].mesh, draws[1].mesh);
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
