// Whole-file reads, shared by package::readFile and PackageReader::openFile.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::package::detail {

// The file's bytes, refused before allocating when larger than kMaxFileSize. false with `error`
// naming the path on any I/O failure.
bool readWholeFile(const std::string& path, std::vector<uint8_t>& bytes, std::string& error);

}  // namespace facet::package::detail
