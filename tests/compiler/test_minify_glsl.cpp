// The shipped GLSL ES text (compiler/minify_glsl.h): smaller, and the same program.
#include <gtest/gtest.h>

#include "facet/compiler/build.h"
#include "facet/compiler/minify_glsl.h"
#include "test_compile.h"
#include "test_support.h"

using facet::compiler::minifyPreprocessedGlsl;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(MinifyGlsl, DropsFunctionsAndConstantsMainNeverReaches) {
  std::string out = minifyPreprocessedGlsl(R"(#version 300 es
precision mediump float;
const float USED = 2.0;
const float UNUSED = 3.0;
float leaf(float x) { return x * USED; }
float caller(float x) { return leaf(x); }
float orphan(float x) { return x * UNUSED; }
out vec4 color;
void main() { color = vec4(caller(1.0)); }
)");
  EXPECT_TRUE(has(out, "float leaf(")) << out;
  EXPECT_TRUE(has(out, "float caller(")) << out;
  EXPECT_TRUE(has(out, "const float USED=2.0;")) << out;
  EXPECT_FALSE(has(out, "orphan")) << out;
  EXPECT_FALSE(has(out, "UNUSED")) << out;
  EXPECT_EQ(out.rfind("#version 300 es\n", 0), 0u) << out;
}

TEST(MinifyGlsl, KeepsInterfaceDeclarationsTheProgramDoesNotRead) {
  std::string out = minifyPreprocessedGlsl(R"(#version 300 es
precision highp int;
struct Light { vec4 color; };
layout(std140) uniform Frame { Light lights[2]; vec4 unused; } frame;
uniform mediump sampler2D tex;
in vec3 v_normal;
void main() {}
)");
  for (const char* part :
       {"precision highp int;", "struct Light{", "uniform Frame{", "sampler2D tex;", "in vec3 v_normal;"})
    EXPECT_TRUE(has(out, part)) << part << "\n" << out;
}

TEST(MinifyGlsl, KeepsOverloadsAndPrototypesOfAReachedName) {
  std::string out = minifyPreprocessedGlsl(R"(#version 300 es
float f(float x);
float f(float x) { return x; }
vec2 f(vec2 x) { return x; }
void main() { f(1.0); }
)");
  EXPECT_TRUE(has(out, "float f(float x);")) << out;
  EXPECT_TRUE(has(out, "vec2 f(vec2 x){")) << out;
}

TEST(MinifyGlsl, RemovesCommentsAndIndentationButNeverJoinsOperatorsOrNumbers) {
  std::string out = minifyPreprocessedGlsl(R"(#version 300 es
// a comment
/* a block
   comment */
void main() {
    float a = 1.0e-4 - -.5;   // minus minus, not decrement
    float b = a + +a;
    float c = a / *&a;
    int i = 0x1e-1;
    for (int k = 0; k < 2; ++k) { a += 1.0; }
}
)");
  EXPECT_FALSE(has(out, "comment")) << out;
  EXPECT_FALSE(has(out, "    ")) << out;
  EXPECT_TRUE(has(out, "float a=1.0e-4- -.5;")) << out;
  EXPECT_TRUE(has(out, "float b=a+ +a;")) << out;
  EXPECT_TRUE(has(out, "int i=0x1e-1;")) << out;
  EXPECT_TRUE(has(out, "for(int k=0;k<2;++k){")) << out;
}

// The shipped text's size goal: at most 8 KB of GLSL ES per fragment variant, with nothing a driver
// skips (a phone's driver parses every byte the package ships at each load).
TEST(MinifyGlsl, ExampleFragmentVariantsShipAtMostEightKilobytesWithoutComments) {
  for (const std::string& path : facet::test::exampleMaterials()) {
    auto built = facet::test::buildFile(path);
    ASSERT_TRUE(built) << path;
    for (const auto& variant : built->package.variants) {
      for (const auto& shader : variant.shaders) {
        if (shader.target != facet::package::Target::GlslEs300) continue;
        std::string text(shader.code.begin(), shader.code.end());
        SCOPED_TRACE(path + " " + variant.key);
        if (shader.stage == facet::package::Stage::Fragment) {
          EXPECT_LE(text.size(), 8192u);
        }
        EXPECT_FALSE(has(text, "//")) << text;
        EXPECT_FALSE(has(text, "\n\n")) << text;
      }
    }
  }
}
