// The instruction counts of mobile_cost.h (InstructionCounts: what `matc info` prints and lint's
// budgets read), on shaders whose answer is known by construction; counted by the same walk as
// the model's op classes.
#include <gtest/gtest.h>

#include "facet/compiler/glslang_backend.h"
#include "facet/compiler/mobile_cost.h"

namespace {

facet::compiler::SpirvStages compile(const std::string& fragmentBody) {
  facet::compiler::StageSources s;
  s.vertex = R"(#version 310 es
layout(location = 0) in highp vec4 a_position;
layout(location = 0) out highp vec2 v_uv;
layout(location = 1) out mediump vec3 v_n;
void main() { v_uv = a_position.xy; v_n = a_position.xyz; gl_Position = a_position; }
)";
  s.fragment =
      "#version 310 es\nprecision mediump float;\nlayout(location = 0) in highp vec2 v_uv;\n"
      "layout(location = 1) in mediump vec3 v_n;\nlayout(location = 0) out vec4 o;\n" +
      fragmentBody;
  facet::compiler::SpirvStages out;
  std::string log;
  EXPECT_TRUE(facet::compiler::compileToSpirv(s, &out, &log)) << log;
  return out;
}

facet::compiler::InstructionCounts countsOf(const std::vector<uint32_t>& words) {
  facet::compiler::OpClassCounts counts;
  std::string error;
  EXPECT_TRUE(facet::compiler::countOpClasses(words, &counts, &error)) << error;
  return counts.instructions;
}

}  // namespace

TEST(InstructionCounts, CountsDivisionsTranscendentalsAndVaryings) {
  auto spirv = compile(R"(void main() {
    float a = v_uv.x / v_uv.y;
    float b = pow(a, 3.1);
    o = vec4(a / b, sin(b), normalize(v_n).x, 1.0);
})");
  facet::compiler::InstructionCounts cost = countsOf(spirv.fragment);
  EXPECT_EQ(cost.divisions, 2u);
  EXPECT_EQ(cost.transcendentalOps, 3u);  // pow, sin, normalize
  EXPECT_EQ(cost.varyingComponents, 5u);  // vec2 + vec3
  EXPECT_EQ(cost.textureSamples, 0u);
}

TEST(InstructionCounts, MediumpArithmeticIsCountedAsRelaxed) {
  auto mediump = compile("void main() { mediump float a = v_n.x * v_n.y + v_n.z; o = vec4(a); }");
  auto highp = compile("void main() { highp float a = v_uv.x * v_uv.y + v_uv.x; o = vec4(a); }");
  facet::compiler::InstructionCounts m = countsOf(mediump.fragment), h = countsOf(highp.fragment);
  EXPECT_GT(m.relaxedPercent(), 99.0);
  EXPECT_LT(h.relaxedPercent(), 1.0);
  EXPECT_EQ(m.aluOps, 2u);  // one multiply, one add
}

TEST(InstructionCounts, VertexInputsAreCountedAsVaryingComponentsToo) {
  // Lint's baseline records the vertex stage's attribute components under the same name.
  auto spirv = compile("void main() { o = vec4(v_uv, 0.0, 1.0); }");
  EXPECT_EQ(countsOf(spirv.vertex).varyingComponents, 4u);  // a_position
}

// matc info analyses SPIR-V read from a package file: an instruction cut short (a string without
// its NUL, a type without its operands) is read within its own words, never past them (ASan
// checks this in the sanitizer suite).
TEST(InstructionCounts, ShortInstructionsAreReadWithinTheirWords) {
  const uint32_t magic = 0x07230203, version = 0x00010000;
  const uint32_t glsl = 0x4c534c47;  // "GLSL" with no terminating NUL
  std::vector<uint32_t> words = {magic,
                                 version,
                                 0,
                                 10,
                                 0,
                                 (3u << 16) | 11u,
                                 1,
                                 glsl,  // OpExtInstImport %1 "GLSL…
                                 (2u << 16) | 23u,
                                 2};  // OpTypeVector %2 (component type and count missing)
  facet::compiler::OpClassCounts counts;
  std::string error;
  EXPECT_TRUE(facet::compiler::countOpClasses(words, &counts, &error)) << error;
  words.push_back((9u << 16) | 71u);  // an instruction claiming more words than remain
  EXPECT_FALSE(facet::compiler::countOpClasses(words, &counts, &error));
  EXPECT_NE(error.find("truncated instruction at word 10"), std::string::npos) << error;
}
