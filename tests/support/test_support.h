// Helpers shared by Facet's tests: compiling example materials through the library, reading
// files, running the command-line tools.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "facet/compiler/build.h"
#include "facet/ir/check.h"

namespace facet::test {

inline std::string sourceDir() { return FACET_SOURCE_DIR; }
inline std::string examplePath(const std::string& relative) { return sourceDir() + "/examples/" + relative; }
// Every examples/scenes/*.json, sorted.
std::vector<std::string> exampleScenes();

std::string readText(const std::string& path);

// Every examples/materials/*.mat, sorted.
std::vector<std::string> exampleMaterials();

// Parses, checks and builds a material file (every supported tier unless `options` says
// otherwise); fails the current test on any error.
std::optional<compiler::BuildResult> buildFile(const std::string& path, const compiler::BuildOptions& options = {});

// The same for material text held in memory.
std::optional<compiler::BuildResult> buildText(const std::string& text, const std::string& path = "test.mat",
                                               const compiler::BuildOptions& options = {});

// Builds each material and writes <scratch dir>/<material name>.matpkg, as matc does; returns
// the folder. Fails the current test on any error.
std::string writePackagesFromTexts(const std::string& scratchName, const std::vector<std::string>& materialTexts,
                                   const compiler::BuildOptions& options = {});
// 8-bit PSNR between two RGBA8 images of the same size, over RGB (99 dB when identical):
// facet::eval::psnr8, capped.
double psnr(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b);

// The same for every examples/materials/*.mat.
std::string writeExamplePackages(const std::string& scratchName, const compiler::BuildOptions& options = {});

// Parses and checks material text; returns the diagnostics as formatted text.
std::string diagnosticsFor(const std::string& text, const std::string& path = "test.mat");

// A fresh, empty folder under the build tree, removed at the start of each use.
std::string scratchDir(const std::string& name);

struct CommandResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};
// Runs a shell command with stdout and stderr captured separately.
CommandResult run(const std::string& command);

// A unified diff (3 lines of context) from `expected` to `actual`, by longest common subsequence,
// headed `--- expectedName` / `+++ actualName`; a last line without '\n' is marked.
std::string unifiedDiff(const std::string& expected, const std::string& actual, const std::string& expectedName,
                        const std::string& actualName);

}  // namespace facet::test
