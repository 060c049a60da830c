#include "test_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace facet::test {

namespace fs = std::filesystem;

std::string sourceDir() { return FACET_SOURCE_DIR; }
std::string binaryDir() { return FACET_BINARY_DIR; }

std::vector<std::string> exampleScenes() {
  std::vector<std::string> scenes;
  for (const auto& entry : fs::directory_iterator(examplePath("scenes")))
    if (entry.path().extension() == ".json") scenes.push_back(entry.path().string());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> exampleMaterials() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(examplePath("materials")))
    if (entry.path().extension() == ".mat") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> exampleTunedMaterials() {
  const std::string suffix = ".tuning.json";
  std::vector<std::string> stems;
  for (const auto& entry : fs::directory_iterator(examplePath("materials"))) {
    const std::string file = entry.path().filename().string();
    if (file.size() > suffix.size() && file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0)
      stems.push_back(file.substr(0, file.size() - suffix.size()));
  }
  std::sort(stems.begin(), stems.end());
  return stems;
}

std::string scratchDir(const std::string& name) {
  // ctest runs test cases as parallel processes: the pid keeps their folders apart.
  fs::path dir = fs::path(binaryDir()) / "test-scratch" / (name + "." + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

CommandResult run(const std::string& command) {
  // matc caches compiled variants under $XDG_CACHE_HOME; tests never touch the user's cache.
  setenv("XDG_CACHE_HOME", (binaryDir() + "/test-cache").c_str(), 1);
  std::string errFile = scratchDir("run-stderr") + "/stderr.txt";
  CommandResult r;
  FILE* pipe = popen((command + " 2>" + errFile).c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) r.out.append(buf, n);
  int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = readText(errFile);
  return r;
}

namespace {

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

}  // namespace

std::string unifiedDiff(const std::string& expected, const std::string& actual, const std::string& expectedName,
                        const std::string& actualName) {
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
  std::string out = "--- " + expectedName + "\n+++ " + actualName + "\n";
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

}  // namespace facet::test
