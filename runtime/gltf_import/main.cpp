// facet-gltf-import: `matc import` (docs/gltf.md) as a program of its own, so that matc links
// neither tinygltf nor the runtime's glTF reader. matc runs it as "<matc> import"
// (matc/run_helper_program.cpp): its usage and messages then read as matc's.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

#include "facet/cli/command_line.h"
#include "facet/cli/inputs.h"
#include "facet/package/atomic_file.h"
#include "facet/runtime/gltf_materials.h"

int main(int argc, char** argv) {
  facet::removeTemporaryFilesOnSignals();
  facet::cli::setProgramName(std::string_view(argv[0]).ends_with(" import") ? "matc" : "facet-gltf-import");
  CLI::App app{"write a glTF 2.0 file's materials as .mat files and a scene drawing it with them (docs/gltf.md)"};
  std::string input, output, assetRoot;
  app.add_option("input", input, "glTF file (.gltf or .glb)")->required();
  app.add_option("-o,--output", output, "folder to write into; it must contain the glTF file and its images")
      ->required();
  app.add_option("--asset-root", assetRoot,
                 "the folder the scene will read files from (facet-view --asset-root); default: the output folder");
  if (std::optional<int> exit = facet::cli::parseCommandLine(app, argc, argv)) return *exit;
  facet::runtime::GltfImport imported;
  std::string error;
  if (!facet::runtime::importGltf(input, output, assetRoot, &imported, &error)) {
    std::fprintf(stderr, "%s\n", error.c_str());  // already `<file>: error: <where>: ...`
    return 1;
  }
  for (const std::string& note : imported.notes) std::fprintf(stderr, "%s: note: %s\n", input.c_str(), note.c_str());
  std::printf("%s: %zu materials, %zu images; compile the materials with `matc compile`, then render the scene\n",
              imported.scene.c_str(), imported.materials.size(), imported.images.size());
  for (const std::string& material : imported.materials) std::printf("  %s\n", material.c_str());
  return 0;
}
