// The binary glTF container (.glb, glTF 2.0 §4.4), checked before tinygltf sees it: tinygltf
// 2.7's own check lets a BIN chunk whose length counts its 8-byte header through, and then reads
// 8 bytes past the end of the file's memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace facet::runtime::gltf {

struct GlbChunks {
  std::string_view json;         // the JSON chunk's bytes
  size_t jsonOffset = 0;         // where they start in the file
  std::span<const uint8_t> bin;  // the BIN chunk's bytes (empty when there is none)
};

// The header (magic "glTF", container version 2, total length = the file's size) and every
// chunk: each header and its data inside the file, lengths multiples of 4 (chunks start and end
// on 4-byte boundaries), the first chunk JSON and not empty, at most one BIN chunk and only
// second; chunks of other types are skipped, as the spec says. *error: what is wrong and at
// which byte, e.g. "GLB chunk 1 at byte 1020: its 1028 bytes reach past the end of the file (1032 bytes)".
std::optional<GlbChunks> readGlbContainer(std::span<const uint8_t> file, std::string* error);

}  // namespace facet::runtime::gltf
