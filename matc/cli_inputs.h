// Inputs every matc command reads the same way: material files and --tiers lists.
#pragma once

#include <string>
#include <vector>

#include "facet/ir/diagnostics.h"
#include "facet/permutations/variant_key.h"

namespace facet::matc {

// Reads a material file, refusing non-regular files and files over the language's size limit
// before reading them. Prints the error and returns false on failure.
bool readSource(const std::string& path, ir::SourceFile* out);

// False (after printing why) when writing `output` would destroy `input`: the same file, by
// path or through a link (`matc compile x.mat -o x.mat`, or a source named x.matpkg with no -o).
bool outputSparesInput(const std::string& input, const std::string& output);

// --tiers names -> tiers this compiler builds; an empty list keeps *tiers as it is. Prints the
// error and returns 2 (usage) on an unknown or unsupported name, else 0.
int parseTiers(const std::vector<std::string>& names, std::vector<permutations::Tier>* tiers);

}  // namespace facet::matc
