// Reading a material file and reporting its problems the way every matc command does.
#pragma once

#include <optional>
#include <string>

#include "facet/ir/diagnostics.h"
#include "facet/ir/module.h"

namespace facet::matc {

// Reads, parses and checks a material file. Prints the diagnostics (warnings too) to stderr;
// nullopt when the file cannot be read or has errors (the command then exits 1).
std::optional<ir::Material> loadMaterial(const std::string& path, ir::SourceFile* source);

// A build failure: at the material's line when it traces back to one, else "matc: error: ...".
void printBuildError(const ir::SourceFile& source, const std::string& message, const std::optional<ir::SourceLoc>& loc);

}  // namespace facet::matc
