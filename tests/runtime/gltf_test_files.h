// glTF files written by tests (test_gltf_mesh, test_gltf_hostile): a quad with every attribute
// the runtime reads, as .gltf with a .bin beside it or as one .glb, and the pieces to build
// hostile variants of them.
#pragma once

#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

namespace facet::test {

void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes);
void writeText(const std::string& path, const std::string& text);
std::vector<uint8_t> readBytes(const std::string& path);

template <class T>
void append(std::vector<uint8_t>* bytes, std::initializer_list<T> values) {
  for (T v : values) {
    const size_t at = bytes->size();
    bytes->resize(at + sizeof(T));
    std::memcpy(bytes->data() + at, &v, sizeof(T));
  }
}

// The bytes of quad.bin (236): positions (0), normals (48), tangents (96), uv0 (160, float),
// uv1 (192, normalised ushort), colours (208, normalised ubyte VEC4), indices (224, ushort).
std::vector<uint8_t> quadBin();

// The node part of quad.gltf's JSON: one node, one scene.
inline constexpr const char* kQuadScene = R"("nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0)";

// quad.gltf's JSON: `buffer` is its buffer's object, `scene` what follows the meshes.
std::string quadJson(const std::string& buffer, const std::string& scene = kQuadScene);

// A unit quad in z = 0 facing +z, every attribute the runtime reads, in quad.bin beside it.
// `scene`: the node part of the JSON. Returns the .gltf's path.
std::string writeQuad(const std::string& dir, const std::string& binUri = "quad.bin",
                      const std::string& scene = kQuadScene, const std::string& name = "quad.gltf");

// A binary glTF (glTF 2.0 §4.4): 12-byte header, a JSON chunk padded with spaces and, when `bin`
// is not empty, a BIN chunk padded with zeros to 4 bytes.
std::vector<uint8_t> glb(std::string json, std::vector<uint8_t> bin);

// The same quad as one .glb, the buffer without a uri. Returns its path.
std::string writeQuadGlb(const std::string& dir, const std::string& name = "quad.glb");

}  // namespace facet::test
