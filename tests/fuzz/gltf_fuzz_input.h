// How fuzz_gltf, and the test replaying its inputs (tests/runtime/test_gltf_hostile.cpp), turn one input
// into glTF files: the bytes before the first "--bin--" are the glTF file, m.glb when they start
// with the GLB magic "glTF" and m.gltf otherwise; the bytes after it, when it is there, are b.bin
// beside it (the external buffer the seeds name). So one input drives the JSON, the container
// and an external buffer together. And what both then ask of a mesh that loads
// (packsAfterLoading).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "facet/runtime/mesh.h"
#include "facet/runtime/mesh_optimize.h"
#include "facet/runtime/vertex_packing.h"

namespace facet::fuzz {

// Writes the files of `input` into `dir` (an existing folder, emptied of earlier inputs' files);
// returns the glTF file's path.
inline std::string writeGltfFuzzInput(std::string_view input, const std::string& dir) {
  constexpr std::string_view kSeparator = "--bin--";
  const size_t split = input.find(kSeparator);
  const std::string_view main = input.substr(0, split);
  const std::string path = dir + (main.substr(0, 4) == "glTF" ? "/m.glb" : "/m.gltf");
  std::error_code ec;
  for (const char* name : {"/m.glb", "/m.gltf", "/b.bin"}) std::filesystem::remove(dir + name, ec);
  std::ofstream(path, std::ios::binary).write(main.data(), std::streamsize(main.size()));
  if (split != std::string_view::npos) {
    const std::string_view bin = input.substr(split + kSeparator.size());
    std::ofstream(dir + "/b.bin", std::ios::binary).write(bin.data(), std::streamsize(bin.size()));
  }
  return path;
}

// What a scene does with a loaded mesh next: reorders it for the vertex cache and packs it for
// upload. A loaded mesh holds only finite values, so packing may fail only on UV bounds too far
// apart for a finite scale; false, with *error, on any other failure.
inline bool packsAfterLoading(runtime::Mesh& mesh, std::string* error) {
  runtime::optimizeMesh(&mesh);
  runtime::PackedMesh packed;
  return runtime::packMesh(mesh, runtime::VertexPacking::Packed, &packed, error) ||
         error->find(" spans ") != std::string::npos;
}

}  // namespace facet::fuzz
