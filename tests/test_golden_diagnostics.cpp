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

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) {
      lines.push_back(text.substr(begin) + "\\ no newline at end");
      break;
    }
    lines.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return lines;
}

// A unified diff (3 lines of context) from `expected` to `actual`, by longest common subsequence.
std::string unifiedDiff(const std::string& expected, const std::string& actual, const std::string& name) {
  std::vector<std::string> a = splitLines(expected), b = splitLines(actual);
  std::vector<std::vector<size_t>> lcs(a.size() + 1, std::vector<size_t>(b.size() + 1, 0));
  for (size_t i = a.size(); i-- > 0;)
    for (size_t j = b.size(); j-- > 0;)
      lcs[i][j] = a[i] == b[j] ? lcs[i + 1][j + 1] + 1 : std::max(lcs[i + 1][j], lcs[i][j + 1]);
  struct Line {
    char tag;  // ' ', '-', '+'
    size_t aLine, bLine;
    const std::string* text;
  };
  std::vector<Line> ops;
  size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (i < a.size() && j < b.size() && a[i] == b[j]) {
      ops.push_back({' ', i, j, &a[i]});
      ++i, ++j;
    } else if (i < a.size() && (j == b.size() || lcs[i + 1][j] >= lcs[i][j + 1])) {
      ops.push_back({'-', i, j, &a[i]});
      ++i;
    } else {
      ops.push_back({'+', i, j, &b[j]});
      ++j;
    }
  }
  const size_t context = 3;
  std::string out = "--- " + name + ".expected\n+++ " + name + " (actual)\n";
  size_t k = 0;
  while (k < ops.size()) {
    if (ops[k].tag == ' ') {
      ++k;
      continue;
    }
    size_t start = k >= context ? k - context : 0;
    size_t end = k;  // extend while changes are within 2*context of each other
    for (size_t gap = 0; end < ops.size() && gap <= 2 * context; ++end) gap = ops[end].tag == ' ' ? gap + 1 : 0;
    while (end > k && ops[end - 1].tag == ' ') --end;
    end = std::min(ops.size(), end + context);
    size_t aCount = 0, bCount = 0;
    for (size_t m = start; m < end; ++m) {
      if (ops[m].tag != '+') ++aCount;
      if (ops[m].tag != '-') ++bCount;
    }
    out += "@@ -" + std::to_string(ops[start].aLine + 1) + "," + std::to_string(aCount) + " +" +
           std::to_string(ops[start].bLine + 1) + "," + std::to_string(bCount) + " @@\n";
    for (size_t m = start; m < end; ++m) out += std::string(1, ops[m].tag) + *ops[m].text + "\n";
    k = end;
  }
  return out;
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

    EXPECT_TRUE(actual == expected) << unifiedDiff(expected, actual, kFolder + "/" + name)
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
