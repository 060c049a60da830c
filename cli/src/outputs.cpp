#include "facet/cli/outputs.h"

#include <sys/stat.h>

#include <filesystem>
#include <optional>

#include "facet/cli/inputs.h"

namespace facet::cli {
namespace {

namespace fs = std::filesystem;

// What a path names: the file's device and inode, or, for a path that does not exist yet, the
// nearest existing folder above it and the names below that folder (two outputs `out/a` that
// will both be created are the same file).
struct Identity {
  dev_t device = 0;
  ino_t inode = 0;
  std::string below;
  bool operator==(const Identity&) const = default;
};

std::optional<Identity> identify(const std::string& path) {
  if (path.empty()) return std::nullopt;
  std::error_code ec;
  fs::path at = fs::absolute(path, ec);
  if (ec) return std::nullopt;
  fs::path below;
  for (;;) {
    struct stat st {};
    if (stat(at.c_str(), &st) == 0) {
      std::string rest = below.lexically_normal().generic_string();
      return Identity{st.st_dev, st.st_ino, rest == "." ? "" : rest};
    }
    if (!at.has_relative_path()) return std::nullopt;
    below = at.filename() / below;
    at = at.parent_path();
  }
}

}  // namespace

bool outputsSpareInputs(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) {
  // An input that does not exist cannot be lost (reading it fails with its own error).
  auto identities = [](const std::vector<NamedFile>& files, bool existing) {
    std::vector<std::optional<Identity>> ids;
    for (const NamedFile& f : files) {
      ids.push_back(identify(f.path));
      if (existing && ids.back() && !ids.back()->below.empty()) ids.back().reset();
    }
    return ids;
  };
  const std::vector<std::optional<Identity>> in = identities(inputs, true), out = identities(outputs, false);
  for (size_t o = 0; o < outputs.size(); ++o) {
    if (!out[o]) continue;  // no folder of it exists: writing it fails with its own error
    const NamedFile& output = outputs[o];
    for (size_t i = 0; i < inputs.size(); ++i) {
      if (!in[i] || in[i] != out[o]) continue;
      printError("the output '" + output.path + "' (" + output.role + ") is " + inputs[i].role + " '" + inputs[i].path +
                 "'; name another file");
      return false;
    }
    for (size_t e = 0; e < o; ++e) {
      if (out[e] != out[o]) continue;
      printError("the outputs '" + outputs[e].path + "' (" + outputs[e].role + ") and '" + output.path + "' (" +
                 output.role + ") are the same file; name two different files");
      return false;
    }
  }
  return true;
}

bool writeOutputs(const std::vector<std::string>& folders, const std::vector<package::OutputFile>& files) {
  for (const std::string& folder : folders) {
    std::error_code ec;
    if (!folder.empty()) fs::create_directories(folder, ec);
    if (ec) {
      printError("cannot create '" + folder + "': " + ec.message());
      return false;
    }
  }
  std::string error;
  if (package::writeFiles(files, &error)) return true;
  printError(error);
  return false;
}

}  // namespace facet::cli
