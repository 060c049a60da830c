#include "gltf_glb.h"

#include <cstring>

namespace facet::runtime::gltf {
namespace {

constexpr uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr size_t kHeaderBytes = 12;
constexpr size_t kChunkHeaderBytes = 8;

uint32_t word(std::span<const uint8_t> file, size_t at) {
  uint32_t v;
  std::memcpy(&v, file.data() + at, 4);  // little-endian, as the container is (x86 and ARM hosts)
  return v;
}

}  // namespace

std::optional<GlbChunks> readGlbContainer(std::span<const uint8_t> file, std::string* error) {
  if (file.size() < kHeaderBytes || word(file, 0) != kMagic) {
    *error = "GLB header: not a binary glTF file (no \"glTF\" magic in a 12-byte header)";
    return std::nullopt;
  }
  if (const uint32_t version = word(file, 4); version != 2) {
    *error = "GLB header: container version " + std::to_string(version) + " (only version 2, glTF 2.0, is read)";
    return std::nullopt;
  }
  if (const uint32_t length = word(file, 8); length != file.size()) {
    *error =
        "GLB header: declares " + std::to_string(length) + " bytes, but the file has " + std::to_string(file.size());
    return std::nullopt;
  }
  GlbChunks chunks;
  bool hasJson = false;
  size_t index = 0;
  for (size_t at = kHeaderBytes; at < file.size(); ++index) {
    const std::string chunk = "GLB chunk " + std::to_string(index) + " at byte " + std::to_string(at);
    // `at` and every length are multiples of 4, and the file's size is below 4 GiB (its header
    // says so in 32 bits): no sum below wraps.
    if (file.size() - at < kChunkHeaderBytes) {
      *error = chunk + ": " + std::to_string(file.size() - at) + " bytes left, too few for a chunk header";
      return std::nullopt;
    }
    const size_t length = word(file, at), type = word(file, at + 4);
    const size_t data = at + kChunkHeaderBytes;
    if (length > file.size() - data) {
      *error = chunk + ": its " + std::to_string(length) + " bytes reach past the end of the file (" +
               std::to_string(file.size()) + " bytes)";
      return std::nullopt;
    }
    if (length % 4 != 0) {
      *error = chunk + ": length " + std::to_string(length) + " is not a multiple of 4 (chunks are 4-byte aligned)";
      return std::nullopt;
    }
    const bool json = type == kJsonChunk, bin = type == kBinChunk;
    if (index == 0 && (!json || length == 0)) {
      *error = chunk + ": the first chunk must be a JSON chunk that is not empty";
      return std::nullopt;
    }
    if ((json && index != 0) || (bin && index != 1)) {
      *error = chunk + ": a " + (json ? "JSON" : "BIN") + " chunk may only come " + (json ? "first" : "second, once");
      return std::nullopt;
    }
    if (json) {
      chunks.json = std::string_view(reinterpret_cast<const char*>(file.data() + data), length);
      chunks.jsonOffset = data;
      hasJson = true;
    }
    if (bin) chunks.bin = file.subspan(data, length);
    at = data + length;
  }
  if (!hasJson) {
    *error = "GLB: no JSON chunk";
    return std::nullopt;
  }
  return chunks;
}

}  // namespace facet::runtime::gltf
