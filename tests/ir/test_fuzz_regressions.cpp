// Replays every input the fuzzer ever crashed or hung on (tests/fuzz/regressions/) and the
// fuzzer's seed corpus (tests/fuzz/corpus/) through the front end exactly as
// tests/fuzz/fuzz_material.cpp does: compileSource, the formatted diagnostics, and emitSurface
// when the material checks. Runs in both test configurations, so the ASan + UBSan build checks
// these inputs on every test run, without clang or libFuzzer. See scripts/fuzz.sh.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "facet/ir/check.h"
#include "facet/ir/emit_glsl.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;

// Every input file under tests/fuzz/<folder>/ (READMEs excepted), as "<folder>/<file>".
std::vector<std::string> inputs() {
  std::vector<std::string> out;
  for (const char* folder : {"regressions", "corpus"}) {
    fs::path dir = fs::path(facet::test::sourceDir()) / "tests/fuzz" / folder;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file() && entry.path().filename() != "README.md")
        out.push_back(std::string(folder) + "/" + entry.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Checks one input the way the fuzzer does.
void replay(const std::string& relative) {
  const std::string path = facet::test::sourceDir() + "/tests/fuzz/" + relative;
  facet::ir::SourceFile file{relative, facet::test::readText(path)};
  facet::ir::Diagnostics diags(file);
  std::optional<facet::ir::Material> material = facet::ir::compileSource(file, diags);
  std::string text = diags.format();
  if (material) {
    EXPECT_FALSE(diags.hasErrors()) << text;
    facet::ir::SurfaceGlsl glsl = facet::ir::emitSurface(*material);
    (void)glsl;
  } else {
    EXPECT_TRUE(diags.hasErrors()) << "rejected without an error";
  }
  for (const facet::ir::Diagnostic& d : diags.all()) {
    EXPECT_GE(d.loc.line, 1u) << d.message;
    EXPECT_GE(d.loc.column, 1u) << d.message;
    EXPECT_LE(d.loc.offset, file.text.size()) << d.message;
  }
  // Hangs are the fuzzer's to find (5 s per input); here ctest's --timeout stops a stuck run.
}

}  // namespace

// One test over both folders (not one per file), so that an input added counts at once,
// without rebuilding the test for ctest to rediscover it.
TEST(FuzzInputs, EveryInputCompilesOrFailsWithErrorsWithoutCrashing) {
  for (const std::string& input : inputs()) {
    SCOPED_TRACE("tests/fuzz/" + input);
    replay(input);
  }
}

TEST(FuzzInputs, SeedCorpusIsPresent) {
  auto all = inputs();
  EXPECT_GE(std::count_if(all.begin(), all.end(), [](const std::string& s) { return s.rfind("corpus/", 0) == 0; }), 10);
}

// Found by reading, not by the fuzzer (its inputs are a few KiB): formatting looked up each
// diagnostic's whole source line, so N errors on one long line cost O(N * line length); a 4 MiB
// line of bad characters took hours. Two fixes keep the work bounded by construction, not by a
// timer: lines over 200 bytes are not scanned or quoted (ir/src/diagnostics.cpp, lineAt), and
// the lexer stops after kMaxErrors errors.
TEST(FuzzInputs, ManyErrorsOnOneLongLineStopAtTheErrorLimit) {
  facet::ir::SourceFile file{"long-line.mat", std::string(300000, '@')};
  facet::ir::Diagnostics diags(file);
  EXPECT_FALSE(facet::ir::compileSource(file, diags).has_value());
  std::string text = diags.format();
  EXPECT_EQ(diags.errorCount(), facet::ir::kMaxErrors);
  EXPECT_EQ(diags.all().size(), facet::ir::kMaxErrors);
  EXPECT_NE(text.find("long-line.mat: error: too many errors; stopped after 100"), std::string::npos);
  EXPECT_EQ(text.find("\n    @@@"), std::string::npos) << "a line over 200 bytes is not quoted";
}

// Found by reading, not by the fuzzer (it needs more input than the fuzzer writes): each let
// may use the previous one, so the value graph is as deep as the file is long, and GLSL emission
// walked it recursively: 20000 chained lets overflowed the stack (ir/src/emit_glsl.cpp, use).
TEST(FuzzInputs, LongChainOfLetsEmitsWithoutDeepRecursion) {
  const int n = 50000;
  std::string text = "material m {\n  surface {\n    let a0 = vertex.uv0.x\n";
  for (int i = 1; i < n; ++i)
    text += "    let a" + std::to_string(i) + " = a" + std::to_string(i - 1) + " * a" + std::to_string(i - 1) + "\n";
  text += "    roughness = a" + std::to_string(n - 1) + "\n    alpha = a" + std::to_string(n - 1) +
          " > 0.5 ? 1.0 : 0.0\n  }\n}\n";
  facet::ir::SourceFile file{"chain.mat", text};
  facet::ir::Diagnostics diags(file);
  auto material = facet::ir::compileSource(file, diags);
  ASSERT_TRUE(material.has_value()) << diags.format().substr(0, 2000);
  std::string body = facet::ir::emitSurface(*material).body;
  EXPECT_NE(body.find("highp float m_a" + std::to_string(n - 1) + " = m_a" + std::to_string(n - 2)), std::string::npos);
}

// Found by reading: every parameter was compared with every earlier one (duplicates) and with
// all of them again for each misspelt use ("did you mean"), so 40 000 parameters took seconds.
// A material has at most kMaxParams: past it, one error, and the rest are known by name only.
TEST(FuzzInputs, ThousandsOfParametersStopAtTheLimitWithOneError) {
  std::string text = "material m {\n";
  for (int i = 0; i < 40000; ++i) text += "  param p" + std::to_string(i) + ": float = 0.5\n";
  text += "  surface { roughness = params.p39999 + params.q }\n}\n";
  facet::ir::SourceFile file{"params.mat", text};
  facet::ir::Diagnostics diags(file);
  EXPECT_FALSE(facet::ir::compileSource(file, diags).has_value());
  std::string out = diags.format();
  EXPECT_EQ(diags.errorCount(), 2u) << out.substr(0, 2000);
  EXPECT_NE(out.find("params.mat:258:9: error: a material has at most 256 parameters [limit]"), std::string::npos)
      << out.substr(0, 2000);
  EXPECT_NE(out.find("unknown parameter 'q'"), std::string::npos) << out.substr(0, 2000);
}
