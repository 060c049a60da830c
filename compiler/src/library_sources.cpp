#include "facet/compiler/library_sources.h"

#include <filesystem>

namespace facet::compiler {

std::string librarySourcePath(const std::string& name) {
  for (const char* folder : {"/templates/", "/chunks/"}) {
    std::string path = std::string(FACET_GLSL_SOURCE_DIR) + folder + name;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return path;
  }
  return "";
}

}  // namespace facet::compiler
