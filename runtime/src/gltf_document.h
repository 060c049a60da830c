// The checks on a glTF's JSON that must happen before tinygltf reads it: what tinygltf accepts
// against the spec, and what it would read from the file system on the file's behalf.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace facet::runtime::gltf {

// A buffer stored in a file beside the glTF (not a data: URI, not a .glb's BIN chunk).
struct ExternalBuffer {
  std::string pointer;  // "/buffers/2/uri", for messages
  std::string uri;      // as written
  std::string path;     // the URI's path, percent-decoded (RFC 3986), relative to the glTF's folder
  uint64_t byteLength = 0;
};

// Refuses, with `<JSON pointer>: <why>` in *error:
//   - asset.version other than 2.x, asset.minVersion above 2.0 (glTF 2.0 §3.2: a loader must
//     not load an asset whose minVersion it does not support);
//   - extensionsRequired naming an extension other than KHR_mesh_quantization and
//     KHR_texture_transform (§3.12: a loader must not load a file requiring one it does not support);
//   - a bufferView byteStride present but outside 4..252 or not a multiple of 4 (§5.11; tinygltf
//     ignores 0 and negative values);
//   - buffer URIs that tinygltf would read as another file than RFC 3986 says (a NUL or %00
//     cuts the path short; malformed %-escapes; other schemes; queries and fragments), data:
//     URIs other than base64 application/octet-stream or application/gltf-buffer, a buffer
//     without a URI except a .glb's first (tinygltf gives each a copy of the BIN chunk), a
//     byteLength that is not a whole number of at least 1.
// Returns the buffers to read from files, in the order tinygltf asks for them.
// The path a relative URI reference names (RFC 3986 §2.1: %XX is the byte XX); "" with *why set
// when it is refused: empty, another scheme, a NUL or %00, a query or fragment, a malformed escape.
std::string uriPath(const std::string& uri, std::string* why);

std::optional<std::vector<ExternalBuffer>> checkDocument(const nlohmann::json& document, bool binary,
                                                         std::string* error);

}  // namespace facet::runtime::gltf
