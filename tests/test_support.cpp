#include "test_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "facet/eval/metrics.h"

namespace facet::test {

namespace fs = std::filesystem;

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

std::optional<compiler::BuildResult> buildFile(const std::string& path, const compiler::BuildOptions& options) {
  return buildText(readText(path), path, options);
}

std::optional<compiler::BuildResult> buildText(const std::string& text, const std::string& path,
                                               const compiler::BuildOptions& options) {
  ir::SourceFile file{path, text};
  ir::Diagnostics diags(file);
  auto material = ir::compileSource(file, diags);
  EXPECT_TRUE(material.has_value()) << diags.format();
  if (!material) return std::nullopt;
  compiler::BuildError error;
  auto built = compiler::buildMaterial(*material, options, &error);
  EXPECT_TRUE(built.has_value()) << error.message;
  return built;
}

namespace {

void writePackage(const std::string& dir, const std::optional<compiler::BuildResult>& built) {
  if (!built) return;
  std::string error;
  EXPECT_TRUE(package::writeFile(dir + "/" + built->package.material.name + ".matpkg", package::write(built->package),
                                 &error))
      << error;
}

}  // namespace

std::string writePackagesFromTexts(const std::string& scratchName, const std::vector<std::string>& materialTexts,
                                   const compiler::BuildOptions& options) {
  std::string dir = scratchDir(scratchName);
  for (const std::string& text : materialTexts) writePackage(dir, buildText(text, "test.mat", options));
  return dir;
}

std::string writeExamplePackages(const std::string& scratchName, const compiler::BuildOptions& options) {
  std::string dir = scratchDir(scratchName);
  for (const std::string& path : exampleMaterials()) writePackage(dir, buildFile(path, options));
  return dir;
}

double psnr(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  EXPECT_EQ(a.size(), b.size());
  return std::min(eval::psnr8(a, b), 99.0);
}

std::string diagnosticsFor(const std::string& text, const std::string& path) {
  ir::SourceFile file{path, text};
  ir::Diagnostics diags(file);
  ir::compileSource(file, diags);
  return diags.format();
}

std::string scratchDir(const std::string& name) {
  // ctest runs test cases as parallel processes: the pid keeps their folders apart.
  fs::path dir = fs::path(FACET_BINARY_DIR) / "test-scratch" / (name + "." + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

CommandResult run(const std::string& command) {
  // matc caches compiled variants under $XDG_CACHE_HOME; tests never touch the user's cache.
  setenv("XDG_CACHE_HOME", (std::string(FACET_BINARY_DIR) + "/test-cache").c_str(), 1);
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

}  // namespace facet::test
