// Whole-file reads and atomic writes.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "facet/package/atomic_file.h"
#include "facet/package/package.h"
#include "file_io.h"
#include "format.h"

namespace facet::package {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

}  // namespace

namespace detail {

bool readWholeFile(const std::string& path, std::vector<uint8_t>& bytes, std::string& error) {
  std::error_code ec;
  // Ask for the size first, so an oversized file is refused before anything is allocated.
  uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) {
    error = "cannot read '" + path + "': " + ec.message();
    return false;
  }
  if (size > kMaxFileSize) {
    error = "cannot read '" + path + "': " + std::to_string(size) + " bytes is larger than the package limit of " +
            std::to_string(kMaxFileSize) + " bytes";
    return false;
  }
  File f(std::fopen(path.c_str(), "rb"));
  if (!f) {
    error = "cannot open '" + path + "': " + std::strerror(errno);
    return false;
  }
  bytes.assign(size, 0);
  size_t got = bytes.empty() ? 0 : std::fread(bytes.data(), 1, bytes.size(), f.get());
  // A file that changed size since file_size() is reported rather than half-read.
  if (got != bytes.size() || std::fgetc(f.get()) != EOF) {
    error = "cannot read '" + path + "': the file changed size while being read";
    return false;
  }
  return true;
}

}  // namespace detail

ReadResult readFile(const std::string& path) {
  ReadResult result;
  std::vector<uint8_t> bytes;
  if (!detail::readWholeFile(path, bytes, result.error)) return result;
  // Callers name the file in their messages ("<path>: error: ..."), so the reader's message
  // stays about the content.
  return read(bytes);
}

bool writeFile(const std::string& path, std::span<const uint8_t> bytes, std::string* error) {
  std::string message;
  AtomicFile file;
  if (file.open(path, &message) && file.write(bytes, &message) && file.commit(&message)) return true;
  if (error) *error = message;
  return false;
}

bool writeFiles(const std::vector<OutputFile>& files, std::string* error) {
  std::string message;
  std::vector<std::unique_ptr<AtomicFile>> staged;  // each removes its temporary file unless committed
  bool ok = true;
  for (const OutputFile& f : files) {
    staged.push_back(std::make_unique<AtomicFile>());
    AtomicFile& file = *staged.back();
    if (!(ok = file.open(f.path, &message) && file.write(f.bytes, &message) && file.finish(&message))) break;
  }
  for (size_t i = 0; ok && i < staged.size(); ++i) ok = staged[i]->commit(&message);
  if (!ok && error) *error = message;
  return ok;
}

}  // namespace facet::package
