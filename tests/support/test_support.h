// Helpers shared by Facet's tests that need none of Facet's libraries: where the sources and
// examples are, reading files, scratch folders, running the command-line tools, diffs. Compiling
// materials: test_compile.h; diagnostics of material text: test_diagnostics.h; image error:
// test_images.h.
#pragma once

#include <string>
#include <vector>

namespace facet::test {

// The source tree and the build tree this test was built from.
std::string sourceDir();
std::string binaryDir();
inline std::string examplePath(const std::string& relative) { return sourceDir() + "/examples/" + relative; }
// Every examples/scenes/*.json, sorted.
std::vector<std::string> exampleScenes();

std::string readText(const std::string& path);

// Every examples/materials/*.mat, sorted.
std::vector<std::string> exampleMaterials();
// The stems of every examples/materials/<stem>.tuning.json (the committed tuning files), sorted.
std::vector<std::string> exampleTunedMaterials();

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
