#include "test_compile.h"

#include <gtest/gtest.h>

#include "facet/ir/check.h"
#include "facet/package/package.h"
#include "test_support.h"

namespace facet::test {

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
  EXPECT_TRUE(
      package::writeFile(dir + "/" + built->package.material.name + ".matpkg", package::write(built->package), &error))
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

}  // namespace facet::test
