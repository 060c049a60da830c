// Materials compiled through the library for tests, and their packages written as matc writes
// them: what a test links the compiler for. Each fails the current test on any error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/compiler/build.h"

namespace facet::test {

// Parses, checks and builds a material file (every supported tier unless `options` says
// otherwise).
std::optional<compiler::BuildResult> buildFile(const std::string& path, const compiler::BuildOptions& options = {});

// The same for material text held in memory.
std::optional<compiler::BuildResult> buildText(const std::string& text, const std::string& path = "test.mat",
                                               const compiler::BuildOptions& options = {});

// Builds each material and writes <scratch dir>/<material name>.matpkg, as matc does; returns
// the folder.
std::string writePackagesFromTexts(const std::string& scratchName, const std::vector<std::string>& materialTexts,
                                   const compiler::BuildOptions& options = {});

// The same for every examples/materials/*.mat.
std::string writeExamplePackages(const std::string& scratchName, const compiler::BuildOptions& options = {});

}  // namespace facet::test
