// Golden tests of what users read: for every tests/golden/diagnostics/<name>.mat, the exact
// stderr and exit code of `matc compile tests/golden/diagnostics/<name>.mat`, run from the
// source root so paths in the text are relative, must equal <name>.expected:
//
//   exit: <code>
//   <stderr, byte for byte>
//
// Expectations are never edited by hand: scripts/update-goldens.sh regenerates them all from
// the current matc (see docs/testing.md), and the diff is reviewed like any other change.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "test_support.h"

namespace {

namespace fs = std::filesystem;

const std::string kMatc = FACET_MATC;
const std::string kFolder = "tests/golden/diagnostics";  // relative to the source root

std::vector<std::string> goldenCases() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(facet::test::sourceDir() + "/" + kFolder))
    if (entry.path().extension() == ".mat") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

// One test over the whole folder (not one per file), so that a case added or removed counts
// at once, without rebuilding the test for ctest to rediscover it.
TEST(GoldenDiagnostics, EveryCaseMatchesItsExpectation) {
  std::vector<std::string> names = goldenCases();
  EXPECT_GE(names.size(), 20u);
  for (const std::string& name : names) {
    SCOPED_TRACE(kFolder + "/" + name + ".mat");
    const std::string expectedPath = facet::test::sourceDir() + "/" + kFolder + "/" + name + ".expected";
    if (!fs::exists(expectedPath)) {
      ADD_FAILURE() << name << ".expected is missing; run scripts/update-goldens.sh";
      continue;
    }
    std::string expected = facet::test::readText(expectedPath);

    std::string out = facet::test::scratchDir("golden") + "/out.matpkg";
    std::string command = "cd '" + facet::test::sourceDir() + "' && '" + kMatc + "' compile '" + kFolder + "/" + name +
                          ".mat' -o '" + out + "'";
    facet::test::CommandResult r = facet::test::run("(" + command + ")");
    std::string actual = "exit: " + std::to_string(r.exitCode) + "\n" + r.err;

    EXPECT_TRUE(actual == expected) << facet::test::unifiedDiff(expected, actual, kFolder + "/" + name + ".expected",
                                                                kFolder + "/" + name + " (actual)")
                                    << "If the new text is intended, regenerate every expectation with\n"
                                    << "  scripts/update-goldens.sh " << kMatc << "\n"
                                    << "and review the diff (docs/testing.md, Goldens).";
  }
}

TEST(GoldenDiagnostics, EveryExpectationHasAnInput) {
  for (const auto& entry : fs::directory_iterator(facet::test::sourceDir() + "/" + kFolder)) {
    if (entry.path().extension() != ".expected") continue;
    fs::path input = entry.path();
    input.replace_extension(".mat");
    EXPECT_TRUE(fs::exists(input)) << entry.path().filename().string()
                                   << " has no .mat: delete it (scripts/update-goldens.sh removes stale ones)";
  }
}
