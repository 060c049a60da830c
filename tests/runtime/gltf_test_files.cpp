#include "gltf_test_files.h"

#include <fstream>
#include <iterator>

namespace facet::test {

void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::vector<uint8_t> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<uint8_t> quadBin() {
  std::vector<uint8_t> bin;
  append<float>(&bin, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});                               // 0: 48
  append<float>(&bin, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});                                   // 48: 48
  append<float>(&bin, {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -1});                      // 96: 64
  append<float>(&bin, {0, 0, 1, 0, 1, 1, 0, 1});                                               // 160: 32
  append<uint16_t>(&bin, {0, 0, 65535, 0, 65535, 65535, 0, 65535});                            // 192: 16
  append<uint8_t>(&bin, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 51});  // 208: 16
  append<uint16_t>(&bin, {0, 1, 2, 0, 2, 3});                                                  // 224: 12
  return bin;
}

std::string quadJson(const std::string& buffer, const std::string& scene) {
  return R"({"asset": {"version": "2.0"},
  "buffers": [)" +
         buffer + R"(],
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
  )" + scene +
         "}";
}

std::string writeQuad(const std::string& dir, const std::string& binUri, const std::string& scene,
                      const std::string& name) {
  writeBytes(dir + "/quad.bin", quadBin());
  writeText(dir + "/" + name, quadJson(R"({"uri": ")" + binUri + R"(", "byteLength": 236})", scene));
  return dir + "/" + name;
}

std::vector<uint8_t> glb(std::string json, std::vector<uint8_t> bin) {
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin.push_back(0);
  std::vector<uint8_t> file;
  const size_t total = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size());
  append<uint32_t>(&file, {0x46546C67u, 2u, uint32_t(total)});    // "glTF", version 2
  append<uint32_t>(&file, {uint32_t(json.size()), 0x4E4F534Au});  // "JSON"
  file.insert(file.end(), json.begin(), json.end());
  if (!bin.empty()) {
    append<uint32_t>(&file, {uint32_t(bin.size()), 0x004E4942u});  // "BIN\0"
    file.insert(file.end(), bin.begin(), bin.end());
  }
  return file;
}

std::string writeQuadGlb(const std::string& dir, const std::string& name) {
  writeBytes(dir + "/" + name, glb(quadJson(R"({"byteLength": 236})"), quadBin()));
  return dir + "/" + name;
}

}  // namespace facet::test
