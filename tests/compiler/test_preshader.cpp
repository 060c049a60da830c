// The preshader (compiler/preshader.h, runtime/preshader.h, package section PRSH): inputs that
// depend only on parameters leave the fragment stage and are computed on the CPU. What the
// interpreter does with each op and with hostile programs, what the package keeps, what the
// compiler preshades per example material, and what is left in red_plastic's fragment stage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "facet/abi/shader_abi.h"
#include "facet/compiler/preshader.h"
#include "facet/compiler/spirv_tools_backend.h"
#include "facet/package/package.h"
#include "facet/runtime/preshader.h"
#include "test_compile.h"
#include "test_diagnostics.h"
#include "test_support.h"

namespace {

namespace pkg = facet::package;
using pkg::PreshaderOp;
using pkg::PreshaderOpcode;
using Op = PreshaderOpcode;

std::vector<uint8_t> blockOf(std::vector<float> floats) {
  std::vector<uint8_t> bytes(floats.size() * 4);
  std::memcpy(bytes.data(), floats.data(), bytes.size());
  return bytes;
}

std::vector<float> floatsOf(const std::vector<uint8_t>& bytes) {
  std::vector<float> out(bytes.size() / 4);
  std::memcpy(out.data(), bytes.data(), out.size() * 4);
  return out;
}

// Runs `ops` over a 32-byte block whose first 16 bytes are the parameters `params`; returns the
// derived 16 bytes.
std::vector<float> run(const std::vector<PreshaderOp>& ops, std::vector<float> params) {
  params.resize(8, 0.0f);
  std::vector<uint8_t> block = blockOf(params);
  std::string error;
  EXPECT_TRUE(facet::runtime::runPreshader(ops, 16, block, &error)) << error;
  std::vector<float> all = floatsOf(block);
  return {all.begin() + 4, all.end()};
}

PreshaderOp op(Op code, uint8_t dst, uint8_t a = 0, uint8_t b = 0, uint32_t offset = 0, uint32_t count = 0,
               std::array<float, 4> k = {}) {
  return {code, dst, a, b, offset, count, k};
}
PreshaderOp store(uint8_t reg, uint32_t offset = 16, uint32_t count = 4) {
  return op(Op::Store, 0, reg, 0, offset, count);
}

}  // namespace

TEST(PreshaderInterpreter, LoadParamReadsComponentsAndBroadcastsAScalar) {
  EXPECT_EQ(run({op(Op::LoadParam, 0, 0, 0, 4, 3), store(0)}, {9, 1, 2, 3}), (std::vector<float>{1, 2, 3, 0}));
  EXPECT_EQ(run({op(Op::LoadParam, 0, 0, 0, 8, 1), store(0)}, {9, 1, 2, 3}), (std::vector<float>{2, 2, 2, 2}));
}

TEST(PreshaderInterpreter, ArithmeticIsPerComponent) {
  const auto k = [](float a, float b, float c, float d) { return op(Op::Constant, 0, 0, 0, 0, 0, {a, b, c, d}); };
  PreshaderOp x = k(1, 2, 3, 4), y = k(0.5f, -1, 10, 0);
  y.dst = 1;
  EXPECT_EQ(run({x, store(0)}, {}), (std::vector<float>{1, 2, 3, 4}));
  EXPECT_EQ(run({x, y, op(Op::Add, 2, 0, 1), store(2)}, {}), (std::vector<float>{1.5f, 1, 13, 4}));
  EXPECT_EQ(run({x, y, op(Op::Sub, 2, 0, 1), store(2)}, {}), (std::vector<float>{0.5f, 3, -7, 4}));
  EXPECT_EQ(run({x, y, op(Op::Mul, 2, 0, 1), store(2)}, {}), (std::vector<float>{0.5f, -2, 30, 0}));
  // The destination may be an operand.
  EXPECT_EQ(run({x, op(Op::Mul, 0, 0, 0), store(0)}, {}), (std::vector<float>{1, 4, 9, 16}));
  // Selector lanes 2 bits each: .wzyx.
  EXPECT_EQ(run({x, op(Op::Swizzle, 1, 0, 0, 3 | 2 << 2 | 1 << 4 | 0 << 6), store(1)}, {}),
            (std::vector<float>{4, 3, 2, 1}));
}

TEST(PreshaderInterpreter, ClampBoundsEveryComponentAndTurnsNanIntoTheLowerBound) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(run({op(Op::LoadParam, 0, 0, 0, 0, 4), op(Op::Clamp, 1, 0, 0, 0, 0, {0.089f, 1, 0, 0}), store(1)},
                {nan, -inf, inf, 0.5f}),
            (std::vector<float>{0.089f, 0.089f, 1, 0.5f}));
}

TEST(PreshaderInterpreter, StoreWritesOnlyItsComponents) {
  std::vector<uint8_t> block = blockOf({1, 2, 3, 4, 7, 7, 7, 7});
  std::string error;
  ASSERT_TRUE(facet::runtime::runPreshader({{op(Op::LoadParam, 0, 0, 0, 0, 4), store(0, 20, 2)}}, 16, block, &error))
      << error;
  EXPECT_EQ(floatsOf(block), (std::vector<float>{1, 2, 3, 4, 7, 1, 2, 7}));
}

// Each program names what is wrong, and the block is left as it was.
TEST(PreshaderInterpreter, HostileProgramsAreRefusedBeforeAnyOpRuns) {
  const std::vector<std::pair<std::vector<PreshaderOp>, std::string>> cases = {
      {{store(0, 12, 1)}, "outside the derived members"},               // over a parameter
      {{store(0, 28, 2)}, "outside the derived members"},               // past the block
      {{store(0, 0xfffffffcu, 4)}, "outside the derived members"},      // offset + size wraps in 32 bits
      {{op(Op::LoadParam, 0, 0, 0, 12, 2)}, "outside the parameters"},  // reads a derived member
      {{op(Op::LoadParam, 0, 0, 0, 2, 1)}, "not a multiple of 4"},
      {{op(Op::LoadParam, 0, 0, 0, 0, 0)}, "components (1..4)"},
      {{op(Op::LoadParam, 0, 0, 0, 0, 5)}, "components (1..4)"},
      {{op(Op::Add, uint8_t(pkg::kPreshaderRegisters), 0, 0)}, "beyond r63"},
      {{op(Op::Mul, 0, 0, 200)}, "beyond r63"},
      {{op(PreshaderOpcode(99), 0)}, "unknown opcode 99"},
      {{op(Op::Constant, 0, 0, 0, 0, 0, {std::numeric_limits<float>::infinity(), 0, 0, 0})}, "not finite"},
      {{op(Op::Swizzle, 0, 0, 0, 256)}, "selector 256"},
      {std::vector<PreshaderOp>(pkg::kMaxPreshaderOps + 1, op(Op::Constant, 0)), "the limit is 256"},
  };
  for (const auto& [ops, message] : cases) {
    std::vector<uint8_t> block = blockOf({1, 2, 3, 4, 5, 6, 7, 8});
    const std::vector<uint8_t> before = block;
    std::string error;
    EXPECT_FALSE(facet::runtime::runPreshader({ops.data(), ops.size()}, 16, block, &error)) << message;
    EXPECT_NE(error.find(message), std::string::npos) << error;
    EXPECT_EQ(block, before);
  }
}

namespace {

pkg::Package preshadedPackage(std::vector<PreshaderOp> ops, std::vector<uint32_t> variants = {0}) {
  pkg::Package p;
  p.compilerVersion = "matc test";
  p.material = {"brick", "lit", "opaque", false, {{"roughness", pkg::ParamType::Float, {0.5}, 0.0, 1.0, 0, 4}}, 16};
  const std::string glsl = "#version 300 es\nvoid main() {}\n";
  p.variants.push_back({"high.dir1", {{pkg::Stage::Fragment, pkg::Target::GlslEs300, {glsl.begin(), glsl.end()}}}});
  p.preshader.blockSize = 32;
  p.preshader.programs.push_back({std::move(variants), std::move(ops)});
  return p;
}

}  // namespace

TEST(PreshaderPackage, ProgramsRoundTripAndStampFormat13) {
  pkg::Package p = preshadedPackage({op(Op::LoadParam, 0, 0, 0, 0, 1), op(Op::Clamp, 1, 0, 0, 0, 0, {0.089f, 1, 0, 0}),
                                     op(Op::Mul, 2, 1, 1), store(2, 16, 1)});
  p.material.shading = "unlit";  // a lit package is 1.4 whatever else it holds (Package.LitPackagesAreStampedOneFour)
  const pkg::ReadResult r = pkg::read(pkg::write(p));
  ASSERT_TRUE(r.package) << r.error;
  EXPECT_EQ(*r.package, p);
  EXPECT_EQ(r.formatMinor, 3);
  pkg::Package without = p;
  without.preshader = {};
  EXPECT_LT(pkg::read(pkg::write(without)).formatMinor, 3) << "no preshader: the file stays readable by 1.2 readers";
}

// The section's bytes (counts, variant indices, block size) are the reader's; whether the
// programs stay inside the block is meaning, which the loader checks (semanticError) before any
// program runs.
TEST(PreshaderPackage, HostileSectionsAreRefused) {
  EXPECT_NE(
      pkg::read(pkg::write(preshadedPackage({}, {1}))).error.find("lists variant 1 but the package has 1 variants"),
      std::string::npos);
  pkg::Package p = preshadedPackage({});
  p.preshader.blockSize = 24;
  EXPECT_NE(pkg::read(pkg::write(p)).error.find("a multiple of 16"), std::string::npos);
  p = preshadedPackage({});
  p.preshader.programs.push_back({{0}, {}});
  EXPECT_NE(pkg::read(pkg::write(p)).error.find("lists variant 0, which has a program"), std::string::npos);

  auto meaning = [](const pkg::Package& hostile) {
    const pkg::ReadResult r = pkg::read(pkg::write(hostile));
    EXPECT_TRUE(r.package) << r.error;
    return r.package ? pkg::semanticError(*r.package) : r.error;
  };
  EXPECT_NE(meaning(preshadedPackage({store(0, 8, 1)}))
                .find("preshader program 0: preshader op 0 (store) writes bytes 8..12"),
            std::string::npos);
  p = preshadedPackage({});
  p.preshader.blockSize = 16;  // no room for derived members
  EXPECT_NE(meaning(p).find("the preshaded block is 16 bytes, not above the parameter block's 16"), std::string::npos);
  EXPECT_EQ(meaning(preshadedPackage({store(0, 16, 4)})), "");
}

// Which inputs each example material preshades follows from what its surface program reads:
// parameters only (red_plastic: everything; brushed_gold: all but its diffuse colour, constant 0),
// a texture for the base colour
// (painted_tiles: roughness only), world position for all (banded_ceramic: nothing).
TEST(PreshaderCompiler, ExampleMaterialsPreshadeExactlyTheirUniformInputs) {
  std::map<std::string, std::string> defines;
  for (const std::string name : {"red_plastic", "brushed_gold", "painted_tiles", "banded_ceramic"}) {
    facet::compiler::BuildOptions options;
    options.tiers = {facet::permutations::Tier::High};
    options.emitSources = true;
    auto built = facet::test::buildFile(facet::test::examplePath("materials/" + name + ".mat"), options);
    ASSERT_TRUE(built);
    for (const auto& f : built->sources) {
      if (f.name != name + ".high.dir1.frag.vulkan.glsl") continue;
      for (const char* d : {"FACET_PRESHADED_DIFFUSE_COLOR", "FACET_PRESHADED_F0", "FACET_PRESHADED_ROUGHNESS"})
        if (f.text.find(std::string("#define ") + d) != std::string::npos) defines[name] += std::string(d) + " ";
    }
    EXPECT_EQ(built->package.preshader.programs.empty(), name == "banded_ceramic") << name;
  }
  const std::string all = "FACET_PRESHADED_DIFFUSE_COLOR FACET_PRESHADED_F0 FACET_PRESHADED_ROUGHNESS ";
  EXPECT_EQ(defines["red_plastic"], all);
  // metallic = 1.0: the diffuse colour is the constant 0, which the shader compiler folds away.
  EXPECT_EQ(defines["brushed_gold"], "FACET_PRESHADED_F0 FACET_PRESHADED_ROUGHNESS ");
  EXPECT_EQ(defines["painted_tiles"], "FACET_PRESHADED_ROUGHNESS ");
  EXPECT_EQ(defines["banded_ceramic"], "");
}

// Linear tiers share one program (every preset is linear: one program for the whole package);
// the gamma hack's f0 is another (low built with it, as `matc eval`'s colour-space swap does).
TEST(PreshaderCompiler, TheGammaHackGetsItsOwnF0Program) {
  auto linear = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"));
  ASSERT_TRUE(linear);
  EXPECT_EQ(linear->package.preshader.programs.size(), 1u);
  facet::compiler::BuildOptions options;
  options.adjustTier = [](facet::permutations::Tier tier, facet::permutations::TierConfig* config) {
    if (tier == facet::permutations::Tier::Low) config->colorSpace = facet::permutations::ColorSpace::GammaHack;
  };
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"), options);
  ASSERT_TRUE(built);
  const pkg::Package& p = built->package;
  ASSERT_EQ(p.preshader.programs.size(), 2u);
  for (const pkg::PreshaderProgram& program : p.preshader.programs) {
    const bool low = p.variants[program.variants[0]].key.rfind("low.", 0) == 0;
    for (uint32_t v : program.variants) EXPECT_EQ(p.variants[v].key.rfind("low.", 0) == 0, low) << p.variants[v].key;
  }
  EXPECT_EQ(p.preshader.blockSize, 64u) << "32 bytes of parameters, then diffuse + roughness, f0 + alpha";
  EXPECT_FLOAT_EQ(facet::compiler::minPerceptualRoughness(), 0.089f);
}

TEST(PreshaderCompiler, ParameterNamesOfTheCompilersOwnUniformsAreRefused) {
  EXPECT_NE(facet::test::diagnosticsFor("material m { shading lit\n param facet_f0: float = 0.5\n"
                                        " surface { roughness = params.facet_f0 } }")
                .find("names starting with 'facet_' are reserved"),
            std::string::npos);
}

namespace {

// FClamp/NClamp instructions of a fragment stage whose operand is a value loaded from the
// material block (directly, or moved by extract/shuffle/construct/copy/convert only).
int clampsOfParameters(const std::vector<uint8_t>& spirv) {
  std::vector<uint32_t> words(spirv.size() / 4);
  std::memcpy(words.data(), spirv.data(), words.size() * 4);
  std::istringstream text(facet::compiler::disassembleSpirv(words));
  std::map<std::string, std::map<std::string, std::string>> decorations;  // id -> decoration -> value
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(text, line);) {
    std::istringstream fields(line);
    std::vector<std::string> f;
    for (std::string w; fields >> w;) f.push_back(w);
    if (f.size() >= 4 && f[0] == "OpDecorate") decorations[f[1]][f[2]] = f[3];
    lines.push_back(std::move(f));
  }
  std::set<std::string> tainted;
  for (const auto& [id, d] : decorations)
    if (d.count("Binding") && d.at("Binding") == std::to_string(facet::abi::kMaterialBinding) &&
        d.count("DescriptorSet") && d.at("DescriptorSet") == std::to_string(facet::abi::kMaterialBlock.set))
      tainted.insert(id);
  EXPECT_EQ(tainted.size(), 1u) << "the material block";
  const std::set<std::string> moves = {"OpAccessChain",   "OpInBoundsAccessChain", "OpLoad",       "OpCompositeExtract",
                                       "OpVectorShuffle", "OpCompositeConstruct",  "OpCopyObject", "OpFConvert"};
  int clamps = 0;
  for (const auto& f : lines) {  // SSA: definitions precede uses within a function
    if (f.size() < 4 || f[1] != "=") continue;
    auto readsTainted = [&](size_t from) {
      for (size_t i = from; i < f.size(); ++i)
        if (tainted.count(f[i])) return true;
      return false;
    };
    if (moves.count(f[2]) && readsTainted(3)) tainted.insert(f[0]);
    if (f[2] == "OpExtInst" && f.size() > 5 && (f[5] == "FClamp" || f[5] == "NClamp") && readsTainted(6)) ++clamps;
  }
  return clamps;
}

const std::vector<uint8_t>& fragmentSpirv(const pkg::Package& p, const std::string& key) {
  for (const pkg::Variant& v : p.variants)
    if (v.key == key)
      for (const pkg::Shader& s : v.shaders)
        if (s.stage == pkg::Stage::Fragment && s.target == pkg::Target::Spirv) return s.code;
  ADD_FAILURE() << "no variant " << key;
  static const std::vector<uint8_t> none;
  return none;
}

}  // namespace

// What the preshader is for: no parameter clamp is left in the fragment stage of red_plastic's
// optimised SPIR-V,
// in any tier; the same variants built without the preshader clamp baseColor, metallic,
// reflectance and roughness per pixel.
TEST(PreshaderCompiler, NoParameterClampLeftInRedPlasticsFragmentStage) {
  const std::string path = facet::test::examplePath("materials/red_plastic.mat");
  auto preshaded = facet::test::buildFile(path);
  facet::compiler::BuildOptions perPixelOptions;
  perPixelOptions.preshader = false;
  auto perPixel = facet::test::buildFile(path, perPixelOptions);
  ASSERT_TRUE(preshaded && perPixel);
  for (const char* key : {"reference.dir1", "high.dir0", "high.dir1", "mid.dir1", "low.dir1"}) {
    EXPECT_EQ(clampsOfParameters(fragmentSpirv(preshaded->package, key)), 0) << key;
    EXPECT_GT(clampsOfParameters(fragmentSpirv(perPixel->package, key)), 0) << key << ": the check sees clamps";
  }
}
