// Golden tests of the generated shaders: the shipped GLSL ES and MSL of every variant the examples
// build, committed under tests/golden/shaders (layout: scripts/update-goldens.sh), must equal what
// this build's matc generates. The test regenerates them with that script into a scratch folder
// and compares file by file, so a change to a chunk, a template or the assembly fails here with
// the text diff a reviewer then reads in `git diff tests/golden` (docs/testing.md, "Goldens").
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "test_support.h"

namespace {

namespace fs = std::filesystem;

const std::string kMatc = FACET_MATC;
const std::string kFolder = "tests/golden/shaders";  // relative to the source root

// Every file under `root`, as sorted paths relative to it.
std::vector<std::string> filesUnder(const std::string& root) {
  std::vector<std::string> files;
  if (!fs::is_directory(root)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), root).generic_string());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> minus(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  std::vector<std::string> out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

// "heading (n):" and the first few names, so a change to a shared chunk (every variant's file)
// stays a readable message.
std::string listing(const std::string& heading, const std::vector<std::string>& files) {
  const size_t shown = 10;
  if (files.empty()) return "";
  std::string out = heading + " (" + std::to_string(files.size()) + "):\n";
  for (size_t i = 0; i < files.size() && i < shown; ++i) out += "  " + kFolder + "/" + files[i] + "\n";
  if (files.size() > shown) out += "  ... and " + std::to_string(files.size() - shown) + " more\n";
  return out;
}

// The first `maxLines` lines of `text`, then how many were left out.
std::string firstLines(const std::string& text, size_t maxLines) {
  size_t end = 0;
  for (size_t n = 0; n < maxLines && end != std::string::npos; ++n) {
    end = text.find('\n', end);
    if (end != std::string::npos) ++end;
  }
  if (end == std::string::npos || end >= text.size()) return text;
  size_t rest = static_cast<size_t>(std::count(text.begin() + static_cast<std::ptrdiff_t>(end), text.end(), '\n'));
  return text.substr(0, end) + "... (" + std::to_string(rest) + " more lines)\n";
}

}  // namespace

// One test over the whole folder: a variant added or dropped, or a shader changed, fails it
// without ctest having to rediscover anything.
TEST(GoldenShaders, EveryShippedShaderMatchesItsGolden) {
  const std::string committed = facet::test::sourceDir() + "/" + kFolder;
  const std::string fresh = facet::test::scratchDir("golden-shaders") + "/shaders";
  facet::test::CommandResult r =
      facet::test::run("bash '" + facet::test::sourceDir() + "/scripts/update-goldens.sh' --shaders-into '" + fresh +
                       "' '" + kMatc + "'");
  ASSERT_EQ(r.exitCode, 0) << r.err;

  // The script's own output covers every example material and the post pass, so an empty or
  // partial regeneration cannot pass against an equally empty folder.
  for (const std::string& material : facet::test::exampleMaterials()) {
    const std::string name = fs::path(material).stem().string();
    EXPECT_FALSE(filesUnder(fresh + "/materials/" + name).empty()) << "no shader generated for " << material;
  }
  EXPECT_FALSE(filesUnder(fresh + "/post").empty()) << "no post-pass shader generated";

  const std::vector<std::string> expected = filesUnder(committed), actual = filesUnder(fresh);
  std::vector<std::string> both, changed;
  std::set_intersection(expected.begin(), expected.end(), actual.begin(), actual.end(), std::back_inserter(both));
  for (const std::string& file : both)
    if (facet::test::readText(committed + "/" + file) != facet::test::readText(fresh + "/" + file))
      changed.push_back(file);
  const std::vector<std::string> added = minus(actual, expected), gone = minus(expected, actual);
  if (changed.empty() && added.empty() && gone.empty()) return;

  std::string message = kFolder + " is not what this matc generates:\n" + listing("changed", changed) +
                        listing("new, not committed", added) + listing("committed, no longer generated", gone);
  if (!changed.empty()) {
    const std::string& file = changed.front();
    message += "\n" + firstLines(facet::test::unifiedDiff(facet::test::readText(committed + "/" + file),
                                                          facet::test::readText(fresh + "/" + file),
                                                          kFolder + "/" + file, kFolder + "/" + file + " (generated)"),
                                 60);
  }
  message += "\nIf the change is intended, regenerate every golden with\n  scripts/update-goldens.sh " + kMatc +
             "\nand review `git diff tests/golden` (docs/testing.md, Goldens).";
  ADD_FAILURE() << message;
}
