// Inputs Facet's command-line programs (matc, facet-eval) read the same way — material files,
// --tiers lists — and how they report errors and a material that does not compile.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/ir/diagnostics.h"
#include "facet/ir/module.h"
#include "facet/permutations/variant_key.h"

namespace facet::cli {

// Prints "<program>: error: <message>" to stderr: "matc: error: ..." unless setProgramName says
// otherwise (facet-eval run on its own: "facet-eval: error: ...").
void printError(const std::string& message);
void setProgramName(const std::string& name);

// Reads a material file, refusing non-regular files and files over the language's size limit
// before reading them. Prints the error and returns false on failure.
bool readSource(const std::string& path, ir::SourceFile* out);

// Reads, parses and checks a material file. Prints the diagnostics (warnings too) to stderr;
// nullopt when the file cannot be read or has errors (the command then exits 1).
std::optional<ir::Material> loadMaterial(const std::string& path, ir::SourceFile* source);

// A build failure: at the material's line when it traces back to one, else as printError.
void printBuildError(const ir::SourceFile& source, const std::string& message, const std::optional<ir::SourceLoc>& loc);

// --tiers names -> tiers this compiler builds; an empty list keeps *tiers as it is. Prints the
// error and returns 2 (usage) on an unknown or unsupported name, else 0.
int parseTiers(const std::vector<std::string>& names, std::vector<permutations::Tier>* tiers);

}  // namespace facet::cli
