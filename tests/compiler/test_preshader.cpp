// The preshader (compiler/preshader.h, runtime/preshader.h, package section PRSH): inputs that
// depend only on parameters leave the fragment stage and are computed on the CPU. What the
// interpreter does with each op and with hostile programs, what the package keeps, what the
// compiler preshades per example material, and what is left in red_plastic's fragment stage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
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

// Division and square root are IEEE fp32, as the shaders' highp: no input makes them undefined.
TEST(PreshaderInterpreter, DivAndSqrtAreIeeePerComponent) {
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<PreshaderOp> load = {op(Op::LoadParam, 0, 0, 0, 0, 4),
                                         op(Op::Constant, 1, 0, 0, 0, 0, {2, 4, 0, -1})};
  std::vector<PreshaderOp> div = load;
  div.insert(div.end(), {op(Op::Div, 2, 0, 1), store(2)});
  EXPECT_EQ(run(div, {1, 2, 3, 4}), (std::vector<float>{0.5f, 0.5f, inf, -4}));
  std::vector<float> roots = run({op(Op::LoadParam, 0, 0, 0, 0, 4), op(Op::Sqrt, 1, 0), store(1)}, {4, 0.25f, 2, -1});
  EXPECT_EQ((std::vector<float>{roots[0], roots[1], roots[2]}), (std::vector<float>{2, 0.5f, std::sqrt(2.0f)}));
  EXPECT_TRUE(std::isnan(roots[3]));
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
  EXPECT_EQ(p.preshader.blockSize, 80u)
      << "32 bytes of parameters, then diffuse + roughness, f0 + alpha, the lod + 2^12 alpha + Zioma's factor";
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

namespace {

// What the fragment stage still computes from the material block alone. An id is parameter-only
// when its operands are block loads, constants or other parameter-only ids; `raw` taints only the
// parameters' own members (std140 offset below the parameter block's size), not the derived ones.
struct ParameterOnlyWork {
  int ops = 0;              // parameter-only results of anything but a load or a move
  int environmentLods = 0;  // explicit-lod reads whose lod is such a result (arithmetic, not a load)
};

ParameterOnlyWork parameterOnlyWork(const std::vector<uint8_t>& spirv, uint32_t paramBlockSize, bool raw) {
  std::vector<uint32_t> words(spirv.size() / 4);
  std::memcpy(words.data(), spirv.data(), words.size() * 4);
  std::istringstream text(facet::compiler::disassembleSpirv(words));
  std::map<std::string, std::map<std::string, std::string>> decorations;  // id -> decoration -> value
  std::map<std::string, std::map<std::string, uint32_t>> memberOffsets;   // struct -> member -> offset
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(text, line);) {
    std::istringstream fields(line);
    std::vector<std::string> f;
    for (std::string w; fields >> w;) f.push_back(w);
    if (f.size() >= 4 && f[0] == "OpDecorate") decorations[f[1]][f[2]] = f[3];
    if (f.size() >= 5 && f[0] == "OpMemberDecorate" && f[3] == "Offset")
      memberOffsets[f[1]][f[2]] = uint32_t(std::stoul(f[4]));
    lines.push_back(std::move(f));
  }
  std::string block;
  for (const auto& [id, d] : decorations)
    if (d.count("Binding") && d.at("Binding") == std::to_string(facet::abi::kMaterialBinding) &&
        d.count("DescriptorSet") && d.at("DescriptorSet") == std::to_string(facet::abi::kMaterialBlock.set))
      block = id;
  EXPECT_FALSE(block.empty()) << "the material block";
  std::map<std::string, std::string> pointee, constants;  // pointer type -> type; constant -> value
  std::string blockStruct;
  std::set<std::string> neutral;  // types, constants, the extended instruction set
  for (const auto& f : lines) {
    if (f.size() < 3 || f[1] != "=") continue;
    if (f[2].rfind("OpType", 0) == 0 || f[2].rfind("OpConstant", 0) == 0 || f[2] == "OpExtInstImport" ||
        f[2] == "OpUndef")
      neutral.insert(f[0]);
    if (f[2] == "OpTypePointer" && f.size() >= 5) pointee[f[0]] = f[4];
    if (f[2] == "OpConstant" && f.size() >= 5) constants[f[0]] = f[4];
    if (f[2] == "OpVariable" && f[0] == block) blockStruct = pointee[f[3]];
  }
  const std::set<std::string> moves = {"OpLoad",       "OpCompositeExtract", "OpVectorShuffle", "OpCompositeConstruct",
                                       "OpCopyObject", "OpFConvert"};
  std::set<std::string> loaded, computed;  // parameter-only ids: moved from the block only, or computed
  ParameterOnlyWork work;
  for (const auto& f : lines) {  // SSA: definitions precede uses within a function
    if (f.size() < 4 || f[1] != "=") continue;
    if ((f[2] == "OpAccessChain" || f[2] == "OpInBoundsAccessChain") && f.size() >= 6 && f[4] == block) {
      const std::string& member = constants[f[5]];
      if (!raw || memberOffsets[blockStruct][member] < paramBlockSize) loaded.insert(f[0]);
      continue;
    }
    if (f[2] == "OpImageSampleExplicitLod") {
      for (size_t i = 4; i + 1 < f.size(); ++i)
        if (f[i] == "Lod" && computed.count(f[i + 1])) ++work.environmentLods;
      continue;
    }
    bool any = false, all = true, anyComputed = false;
    for (size_t i = 3; i < f.size(); ++i) {
      if (f[i].empty() || f[i][0] != '%') continue;  // literals, extended instruction names
      if (loaded.count(f[i]) || computed.count(f[i])) {
        any = true;
        anyComputed = anyComputed || computed.count(f[i]) > 0;
      } else if (!neutral.count(f[i])) {
        all = false;
      }
    }
    if (!any || !all) continue;
    if (moves.count(f[2]) && !anyComputed) {
      loaded.insert(f[0]);
    } else {
      computed.insert(f[0]);
      if (!moves.count(f[2])) ++work.ops;
    }
  }
  return work;
}

// The derived members a variant's GLSL declares ("facet_x;  // @offset, preshaded"), and the
// defines it was assembled with.
struct EmittedPreshade {
  std::map<std::string, uint32_t> offsets;
  std::set<std::string> defines;
};

EmittedPreshade emittedPreshade(const facet::compiler::BuildResult& built, const std::string& fileName) {
  EmittedPreshade e;
  for (const auto& f : built.sources) {
    if (f.name != fileName) continue;
    std::istringstream lines(f.text);
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("#define FACET_PRESHADED_", 0) == 0) e.defines.insert(line.substr(8, line.find(' ', 8) - 8));
      const size_t at = line.find(";  // @");
      if (at == std::string::npos || line.find(", preshaded") == std::string::npos) continue;
      const size_t name = line.rfind(' ', at) + 1;
      e.offsets[line.substr(name, at - name)] = uint32_t(std::stoul(line.substr(at + 7)));
    }
  }
  EXPECT_FALSE(e.offsets.empty()) << fileName;
  return e;
}

}  // namespace

// The clear coat's, anisotropy's and the sheen's inputs of the example materials that write them
// from parameters leave the fragment stage in every tier: nothing is computed there from the
// parameters alone (their clamps, α_c, the lods, (α_t, α_b)); built without the preshader the same
// variants compute them per pixel. The environment's lods formed from parameters per pixel are the
// base specular's alone (red_plastic's count: the standard model's lod is not preshaded); the
// cloth model has none.
namespace {

// The block the runtime uploads for an instance: the parameters (their defaults, or `overrides` by
// name; linear colours, as the runtime writes them), then the package's first program run over it.
std::optional<std::vector<uint8_t>> preshadedBlock(const pkg::Package& p, const std::map<std::string, float>& overrides,
                                                   std::string* error) {
  std::vector<uint8_t> block(p.preshader.blockSize, 0);
  for (const pkg::Param& param : p.material.params)
    for (size_t i = 0; i < param.defaultValue.size() && param.size != 0; ++i) {
      const float v = overrides.count(param.name) ? overrides.at(param.name) : float(param.defaultValue[i]);
      std::memcpy(block.data() + param.offset + 4 * i, &v, 4);
    }
  if (!facet::runtime::runPreshader(p.preshader.programs[0].ops, p.material.paramBlockSize, block, error))
    return std::nullopt;
  return block;
}

}  // namespace

TEST(PreshaderCompiler, NoParameterOnlyWorkLeftInTheModelsFragmentStages) {
  for (const std::string name : {"red_plastic", "car_paint", "brushed_metal", "satin_plastic", "velvet"}) {
    const std::string path = facet::test::examplePath("materials/" + name + ".mat");
    auto preshaded = facet::test::buildFile(path);
    facet::compiler::BuildOptions perPixelOptions;
    perPixelOptions.preshader = false;
    auto perPixel = facet::test::buildFile(path, perPixelOptions);
    ASSERT_TRUE(preshaded && perPixel);
    const uint32_t params = preshaded->package.material.paramBlockSize;
    for (const char* key : {"reference.dir1", "high.dir0", "high.dir1", "mid.dir1", "low.dir1"}) {
      SCOPED_TRACE(name + " " + key);
      const ParameterOnlyWork on = parameterOnlyWork(fragmentSpirv(preshaded->package, key), params, true);
      EXPECT_EQ(on.ops, 0);
      EXPECT_GT(parameterOnlyWork(fragmentSpirv(perPixel->package, key), params, true).ops, 0) << "the check sees them";
      // Every environment read's lod is a preshaded member (the base's, the coat's, the sheen's).
      EXPECT_EQ(parameterOnlyWork(fragmentSpirv(preshaded->package, key), params, false).environmentLods, 0);
      EXPECT_GT(parameterOnlyWork(fragmentSpirv(perPixel->package, key), params, false).environmentLods, 0)
          << "the check sees them";
    }
  }
}

// What `matc import` writes for KHR_materials_anisotropy's factors (docs/gltf.md, "Anisotropy"):
// roughness and anisotropy from the extension's two alphas through mix, max, a square root and a
// division, all of parameters. The preshader forms them and the models' members from them, so
// the fragment stage computes nothing from the parameters; the image test beside the import
// (GltfMaterials.AnisotropyExtensionDrawsTheExtensionsLobe) draws the same lobe.
TEST(PreshaderCompiler, TheGltfAnisotropyMappingOfParametersIsPreshaded) {
  const std::string text = R"(material mapped {
    shading lit
    param roughnessFactor: float = 0.4 in [0, 1]
    param anisotropyStrength: float = 0.6 in [0, 1]
    param anisotropyRotation: vec2 = vec2(1.0, 0.0) in [-1, 1]
    surface {
        baseColor = vec3(0.9, 0.6, 0.3)
        metallic = 1.0
        let gltfAlpha = params.roughnessFactor * params.roughnessFactor
        let alphaAcross = max(gltfAlpha, 0.007921)
        let alphaAlong = max(mix(gltfAlpha, 1.0, params.anisotropyStrength * params.anisotropyStrength), 0.007921)
        roughness = sqrt(0.5 * (alphaAlong + alphaAcross))
        anisotropy = (alphaAlong - alphaAcross) / (alphaAlong + alphaAcross)
        anisotropyDirection = vec3(params.anisotropyRotation, 0.0)
    }
}
)";
  auto preshaded = facet::test::buildText(text);
  facet::compiler::BuildOptions perPixelOptions;
  perPixelOptions.preshader = false;
  auto perPixel = facet::test::buildText(text, "test.mat", perPixelOptions);
  ASSERT_TRUE(preshaded && perPixel);
  const uint32_t params = preshaded->package.material.paramBlockSize;
  for (const char* key : {"reference.dir1", "high.dir1", "mid.dir1", "low.dir1"}) {
    SCOPED_TRACE(key);
    EXPECT_EQ(parameterOnlyWork(fragmentSpirv(preshaded->package, key), params, true).ops, 0);
    EXPECT_GT(parameterOnlyWork(fragmentSpirv(perPixel->package, key), params, true).ops, 0) << "the check sees them";
  }
  // The program run on the defaults gives back the extension's two alphas as (α_t, α_b) = r'² (1 ± k):
  // α_along = mix(0.16, 1, 0.36) and α_across = 0.16.
  std::string error;
  ASSERT_FALSE(preshaded->package.preshader.programs.empty());
  const auto block = preshadedBlock(preshaded->package, {}, &error);
  ASSERT_TRUE(block) << error;
  const std::vector<float> all = floatsOf(*block);
  const std::vector<float> derived(all.begin() + params / 4, all.end());
  const auto holds = [&](float expected) {
    return std::any_of(derived.begin(), derived.end(), [&](float m) { return std::abs(m - expected) < 1e-6f; });
  };
  EXPECT_TRUE(holds(0.16f + 0.84f * 0.36f)) << "α_along among the derived members";
  EXPECT_TRUE(holds(0.16f)) << "α_across among the derived members";
}

// Each derived member holds its chunk's per-pixel formula of the default parameters (the
// preshader's program run as the runtime runs it), and the defines say which are read.
TEST(PreshaderCompiler, TheModelsMembersHoldTheirChunksFormulas) {
  const float rMin = facet::compiler::minPerceptualRoughness();
  EXPECT_FLOAT_EQ(facet::compiler::anisotropyAlphaMin(), rMin * rMin);
  const float maxLod = float(facet::abi::kEnvironmentLevels - 1);
  auto lod = [&](float r) { return r * (maxLod * (2.0f - r)); };  // ibl_prefiltered.glsl
  struct Expected {
    const char* material;
    std::set<std::string> defines;
    std::map<std::string, std::vector<float>> members;
    std::map<std::string, float> params;  // instead of the defaults
  };
  const float alphaMetal = 0.35f * 0.35f;
  // specular_zioma.glsl's X factor 4π (p α + q), p = ZIOMA_ROUGH_SCALE, q = ZIOMA_ROUGH_BIAS.
  auto zioma = [](float alpha) { return float(4.0 * 3.14159265358979) * (-0.3125f * alpha + 1.0082f); };
  const float alphaPlastic = 0.35f * 0.35f, alphaRough = 0.8f * 0.8f;
  const std::set<std::string> standard = {"FACET_PRESHADED_DIFFUSE_COLOR", "FACET_PRESHADED_F0",
                                          "FACET_PRESHADED_ROUGHNESS"};
  const std::vector<Expected> cases = {
      {"red_plastic",
       standard,
       {{"facet_perceptualRoughness", {0.35f}},
        {"facet_alpha", {alphaPlastic}},
        {"facet_environmentLod", {lod(0.35f)}},
        {"facet_ggxAlphaScaled", {4096.0f * alphaPlastic}},
        {"facet_ziomaRoughnessFactor", {zioma(alphaPlastic)}}}},
      {"red_plastic",
       standard,
       {{"facet_environmentLod", {lod(0.8f)}},
        {"facet_ggxAlphaScaled", {4096.0f * alphaRough}},
        {"facet_ziomaRoughnessFactor", {zioma(alphaRough)}}},
       {{"roughness", 0.8f}}},
      {"car_paint",
       {"FACET_PRESHADED_F0", "FACET_PRESHADED_ROUGHNESS", "FACET_PRESHADED_CLEAR_COAT",
        "FACET_PRESHADED_CLEAR_COAT_ROUGHNESS"},
       {{"facet_clearCoat", {1.0f}}, {"facet_clearCoatAlpha", {rMin * rMin}}, {"facet_clearCoatLod", {lod(rMin)}}}},
      {"brushed_metal",
       {"FACET_PRESHADED_F0", "FACET_PRESHADED_ROUGHNESS", "FACET_PRESHADED_ANISOTROPY"},
       {{"facet_anisotropy", {0.8f}},
        {"facet_anisotropicBend", {0.8f}},  // min(0.8 · clamp(5 · 0.35, 0, 1), 1 − 2^-7)
        {"facet_anisotropicAlpha", {alphaMetal * 1.8f, alphaMetal * 0.2f}}}},
      // k < 0, the bend faded (5 r < 1) and α_t at ANISOTROPY_ALPHA_MIN.
      {"brushed_metal",
       {"FACET_PRESHADED_F0", "FACET_PRESHADED_ROUGHNESS", "FACET_PRESHADED_ANISOTROPY"},
       {{"facet_anisotropy", {-0.6f}},
        {"facet_anisotropicBend", {0.6f * (5.0f * 0.1f)}},
        {"facet_anisotropicAlpha", {facet::compiler::anisotropyAlphaMin(), (0.1f * 0.1f) * 1.6f}}},
       {{"roughness", 0.1f}, {"anisotropy", -0.6f}}},
      {"car_paint",
       {"FACET_PRESHADED_F0", "FACET_PRESHADED_ROUGHNESS", "FACET_PRESHADED_CLEAR_COAT",
        "FACET_PRESHADED_CLEAR_COAT_ROUGHNESS"},
       {{"facet_clearCoat", {0.3f}}, {"facet_clearCoatAlpha", {0.5f * 0.5f}}, {"facet_clearCoatLod", {lod(0.5f)}}},
       {{"coat", 0.3f}, {"coatRoughness", 0.5f}}},
      {"satin_plastic",
       {"FACET_PRESHADED_DIFFUSE_COLOR", "FACET_PRESHADED_F0", "FACET_PRESHADED_ROUGHNESS",
        "FACET_PRESHADED_SHEEN_COLOR", "FACET_PRESHADED_SHEEN_ROUGHNESS"},
       {{"facet_sheenRoughness", {0.45f}}, {"facet_sheenAlpha", {0.45f * 0.45f}}, {"facet_sheenLod", {lod(0.45f)}}}},
      {"velvet",
       {"FACET_PRESHADED_DIFFUSE_COLOR", "FACET_PRESHADED_ROUGHNESS", "FACET_PRESHADED_SHEEN_COLOR",
        "FACET_PRESHADED_SHEEN_ROUGHNESS"},
       {{"facet_sheenLod", {lod(0.55f)}}}},
  };
  for (const Expected& c : cases) {
    SCOPED_TRACE(c.material);
    facet::compiler::BuildOptions options;
    options.tiers = {facet::permutations::Tier::High};
    options.emitSources = true;
    auto built =
        facet::test::buildFile(facet::test::examplePath(std::string("materials/") + c.material + ".mat"), options);
    ASSERT_TRUE(built);
    const pkg::Package& p = built->package;
    const EmittedPreshade e = emittedPreshade(*built, std::string(c.material) + ".high.dir1.frag.vulkan.glsl");
    EXPECT_EQ(e.defines, c.defines);
    ASSERT_EQ(p.preshader.programs.size(), 1u);
    std::string error;
    const auto preshadedBytes = preshadedBlock(p, c.params, &error);
    ASSERT_TRUE(preshadedBytes) << error;
    const std::vector<uint8_t>& block = *preshadedBytes;
    for (const auto& [member, values] : c.members) {
      ASSERT_TRUE(e.offsets.count(member)) << member;
      for (size_t i = 0; i < values.size(); ++i) {
        float v;
        std::memcpy(&v, block.data() + e.offsets.at(member) + 4 * i, 4);
        EXPECT_FLOAT_EQ(v, values[i]) << member << "[" << i << "]";
      }
    }
    if (e.offsets.count("facet_sheenColor")) {
      float sheen[3], param[3];
      std::memcpy(sheen, block.data() + e.offsets.at("facet_sheenColor"), 12);
      for (const pkg::Param& q : p.material.params)
        if (q.name == "sheen") std::memcpy(param, block.data() + q.offset, 12);
      for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(sheen[i], param[i]) << "the sheen's linear colour, clamped";
    }
  }
}

// An input that is not parameter-only keeps the per-pixel path; the model's other inputs are
// still preshaded.
TEST(PreshaderCompiler, ATexturedModelInputStaysPerPixel) {
  facet::compiler::BuildOptions options;
  options.tiers = {facet::permutations::Tier::High};
  options.emitSources = true;
  auto built = facet::test::buildText(
      "material textured_coat { shading lit\n"
      " param coat: float = 1.0 in [0, 1]\n param grain: texture(linear) = vec4(0.3, 0.3, 0.3, 1.0)\n"
      " param aniso: float = 0.5 in [-1, 1]\n"
      " surface { clearCoat = params.coat\n clearCoatRoughness = sample(params.grain, vertex.uv0).r\n"
      " anisotropy = params.aniso\n roughness = sample(params.grain, vertex.uv0).g } }",
      "textured_coat.mat", options);
  ASSERT_TRUE(built);
  const EmittedPreshade e = emittedPreshade(*built, "textured_coat.high.dir1.frag.vulkan.glsl");
  EXPECT_EQ(e.defines, (std::set<std::string>{"FACET_PRESHADED_CLEAR_COAT"}));
  EXPECT_EQ(e.offsets.count("facet_clearCoatLod"), 0u);
  EXPECT_EQ(e.offsets.count("facet_anisotropicAlpha"), 0u) << "α_t, α_b need the textured roughness";
}

// Specular anti-aliasing widens the roughness per pixel (chunks/specular_antialiasing.glsl): the
// terms derived from it, anisotropy's (α_t, α_b) and bend and a cloth's environment lod, stay per
// pixel; k and the sheen's colour, which do not depend on it, are still preshaded.
TEST(PreshaderCompiler, SpecularAntiAliasingKeepsTheWidenedRoughnessTermsPerPixel) {
  facet::compiler::BuildOptions options;
  options.tiers = {facet::permutations::Tier::High};
  auto fragment = [](const facet::compiler::BuildResult& built) {
    for (const pkg::Variant& v : built.package.variants)
      if (v.key == "high.dir1")
        for (const pkg::Shader& s : v.shaders)
          if (s.stage == pkg::Stage::Fragment && s.target == pkg::Target::GlslEs300)
            return std::string(s.code.begin(), s.code.end());
    ADD_FAILURE() << "no high.dir1";
    return std::string();
  };
  auto brushed = facet::test::buildText(
      "material brushed { shading lit\n specularAntiAliasing { variance 0.02 threshold 0.2 }\n"
      " param rough: float = 0.3 in [0, 1]\n param k: float = 0.8 in [-1, 1]\n"
      " surface { metallic = 1.0\n roughness = params.rough\n anisotropy = params.k } }",
      "brushed.mat", options);
  auto cloth = facet::test::buildText(
      "material felt { shading cloth\n specularAntiAliasing { variance 0.02 threshold 0.2 }\n"
      " param rough: float = 0.6 in [0, 1]\n param sheen: color = vec3(0.5, 0.5, 0.5)\n"
      " surface { roughness = params.rough\n sheenColor = params.sheen } }",
      "felt.mat", options);
  ASSERT_TRUE(brushed && cloth);
  const std::string b = fragment(*brushed), c = fragment(*cloth);
  EXPECT_NE(b.find("params.facet_anisotropy;"), std::string::npos) << b;
  EXPECT_EQ(b.find("params.facet_anisotropicAlpha"), std::string::npos);
  EXPECT_EQ(b.find("params.facet_anisotropicBend"), std::string::npos);
  EXPECT_NE(b.find("clamp(alpha*vec2(1.0+k,1.0-k)"), std::string::npos);
  EXPECT_NE(c.find("params.facet_sheenColor"), std::string::npos) << c;
  EXPECT_EQ(c.find("params.facet_sheenLod"), std::string::npos);
}
