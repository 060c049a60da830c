// A glTF file and its buffers read into tinygltf's model, with everything that must be checked
// before tinygltf sees the bytes: sizes, the .glb container, the JSON's depth and cost, the spec
// rules tinygltf does not enforce, and which files may be read (runtime/gltf_mesh.h lists them).
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <optional>
#include <string>

namespace facet::runtime::gltf {

struct SourceOptions {
  std::string assetRoot;   // the folder buffers may come from; "": the file's own folder
  uint64_t fileBytes = 0;  // what the file and its buffers may take together
  // Keep the encoded bytes of embedded images (data: URIs, bufferViews) in Image::image, for
  // the material path (gltf_materials.cpp); image files are never opened either way.
  bool keepImageBytes = false;
};

// The model, and in *bytesRead what was read from files. *error is a whole message:
// `<path>:<line>:<col>: error: ...` or `<path>: error: <JSON pointer or place>: ...`.
std::optional<tinygltf::Model> readSource(const std::string& path, const SourceOptions& options, uint64_t* bytesRead,
                                          std::string* error);

}  // namespace facet::runtime::gltf
