#include "facet/cli/inputs.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "facet/ir/check.h"
#include "facet/ir/lexer.h"

namespace facet::cli {

namespace fs = std::filesystem;

namespace {
std::string programName = "matc";
}  // namespace

void printError(const std::string& message) {
  std::fprintf(stderr, "%s: error: %s\n", programName.c_str(), message.c_str());
}

void setProgramName(const std::string& name) { programName = name; }

bool readSource(const std::string& path, ir::SourceFile* out) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    printError("cannot read '" + path + "': " + (fs::exists(path, ec) ? "not a regular file" : "no such file"));
    return false;
  }
  uintmax_t size = fs::file_size(path, ec);
  if (ec || size > ir::kMaxSourceBytes) {
    printError("'" + path + "' is " + std::to_string(size) + " bytes; material files are limited to " +
               std::to_string(ir::kMaxSourceBytes) + " bytes");
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) {
    printError("cannot read '" + path + "'");
    return false;
  }
  out->path = path;
  out->text = text.str();
  return true;
}

std::optional<ir::Material> loadMaterial(const std::string& path, ir::SourceFile* source) {
  if (!readSource(path, source)) return std::nullopt;
  ir::Diagnostics diags(*source);
  std::optional<ir::Material> material = ir::compileSource(*source, diags);
  std::fputs(diags.format().c_str(), stderr);
  if (!material)
    std::fprintf(stderr, "%zu error%s generated.\n", diags.errorCount(), diags.errorCount() == 1 ? "" : "s");
  return material;
}

void printBuildError(const ir::SourceFile& source, const std::string& message,
                     const std::optional<ir::SourceLoc>& loc) {
  if (loc) {
    std::fputs(ir::formatDiagnostic(source, {ir::Severity::Error, *loc, message, "backend"}).c_str(), stderr);
  } else {
    printError(message);
  }
}

int parseTiers(const std::vector<std::string>& names, std::vector<permutations::Tier>* tiers) {
  if (names.empty()) return 0;
  const auto& supported = permutations::supportedTiers();
  tiers->clear();
  for (const std::string& name : names) {
    auto tier = permutations::tierFromString(name);
    if (!tier) {
      printError("unknown tier '" + name + "' (reference, high, mid, low)");
      return 2;
    }
    if (std::find(supported.begin(), supported.end(), *tier) == supported.end()) {
      std::string list;
      for (permutations::Tier t : supported)
        list += (list.empty() ? "" : ", ") + std::string(permutations::toString(t));
      printError("tier '" + name + "' is not built by this compiler version (supported: " + list + ")");
      return 2;
    }
    tiers->push_back(*tier);
  }
  return 0;
}

}  // namespace facet::cli
