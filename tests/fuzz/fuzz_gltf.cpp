// libFuzzer target for the glTF loader (runtime::loadGltfMesh, and runtime::readGltfMaterials, the
// material path of `matc import`, with MikkTSpace's tangents): the .gltf JSON, the .glb container
// and an external buffer, from one input split as tests/fuzz/gltf_fuzz_input.h says. Any bytes end
// in a mesh or an error naming the file, never a crash, a hang, a sanitizer report or an
// allocation past the loader's limits. tinygltf is compiled in (tinygltf_impl.cpp) with the same
// instrumentation, so its parser is guided and checked too. Seeds: tests/fuzz/gltf_corpus/.
//
// Reproduce a finding:  build/fuzz/tests/fuzz/fuzz_gltf path/to/input
#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "facet/runtime/gltf_materials.h"
#include "facet/runtime/gltf_mesh.h"
#include "gltf_fuzz_input.h"

namespace {

// A folder of this process's own for the files of each input, removed when the process exits
// (the name is never destroyed: the exit handler runs after static destructors would).
const std::string& workFolder() {
  static const std::string* dir = [] {
    auto* d =
        new std::string((std::filesystem::temp_directory_path() / ("fuzz_gltf." + std::to_string(getpid()))).string());
    std::filesystem::create_directories(*d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(workFolder(), ec);
    });
    return d;
  }();
  return *dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = facet::fuzz::writeGltfFuzzInput({reinterpret_cast<const char*>(data), size}, workFolder());
  std::string error;
  auto mesh = facet::runtime::loadGltfMesh(path, &error);
  if (!mesh && error.rfind(path + ":", 0) != 0) {
    std::fprintf(stderr, "fuzz_gltf: rejected without naming the file: %.300s\n", error.c_str());
    std::abort();
  }
  if (!mesh) return 0;
  // The material path (matc import's reader and the .mat text it writes) on files whose meshes
  // load (it reads the meshes first and fails where loadGltfMesh does): one read of the others.
  if (auto materials = facet::runtime::readGltfMaterials(path, &error)) {
    for (const auto& m : materials->materials) (void)facet::runtime::gltfMaterialSource(m.features);
  } else if (error.rfind(path + ":", 0) != 0) {
    std::fprintf(stderr, "fuzz_gltf: materials rejected without naming the file: %.300s\n", error.c_str());
    std::abort();
  }
  const size_t vertices = mesh->vertices.size() / facet::abi::kVertexFloats;
  bool valid = !mesh->indices.empty() && mesh->indices.size() % 3 == 0 &&
               mesh->vertices.size() % facet::abi::kVertexFloats == 0 &&
               vertices <= facet::runtime::GltfBudget::kMaxVertices &&
               mesh->indices.size() <= facet::runtime::GltfBudget::kMaxIndices;
  for (uint32_t index : mesh->indices) valid = valid && index < vertices;
  if (!valid) {
    std::fprintf(stderr, "fuzz_gltf: a mesh of %zu indices, %zu floats\n", mesh->indices.size(), mesh->vertices.size());
    std::abort();
  }
  if (!facet::fuzz::packsAfterLoading(*mesh, &error)) {
    std::fprintf(stderr, "fuzz_gltf: a loaded mesh did not pack: %.300s\n", error.c_str());
    std::abort();
  }
  return 0;
}
