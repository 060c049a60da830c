// The mobile cost model (compiler/mobile_cost.h): op classes counted on shaders whose answer is
// known by construction, the weights table applied as documented, and the example tiers ordered
// as the Mali-G57 measurements order them (docs/eval.md, "The mobile cost model").
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "facet/compiler/cost_figures.h"
#include "facet/compiler/glslang_backend.h"
#include "facet/compiler/mobile_cost.h"
#include "facet/compiler/spirv_tools_backend.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using facet::compiler::MobileCostWeights;
using facet::compiler::MobileStageCost;
using facet::compiler::OpClass;

// An optimised fragment stage (as packages hold) whose body is `body`; v_hi is highp, v_med mediump.
std::vector<uint32_t> fragment(const std::string& body) {
  facet::compiler::StageSources s;
  s.vertex = R"(#version 310 es
layout(location = 0) in highp vec4 a_position;
layout(location = 0) out highp vec4 v_hi;
layout(location = 1) out mediump vec3 v_med;
void main() { v_hi = a_position; v_med = a_position.xyz; gl_Position = a_position; }
)";
  s.fragment =
      "#version 310 es\nprecision highp float;\nlayout(location = 0) in highp vec4 v_hi;\n"
      "layout(location = 1) in mediump vec3 v_med;\nlayout(location = 0) out vec4 o;\n" +
      body;
  facet::compiler::SpirvStages out;
  std::string log;
  EXPECT_TRUE(facet::compiler::compileToSpirv(s, &out, &log)) << log;
  EXPECT_TRUE(facet::compiler::optimizeSpirv(&out.fragment, &log)) << log;
  return out.fragment;
}

MobileStageCost costOf(const std::vector<uint32_t>& words, const MobileCostWeights& weights = {}) {
  MobileStageCost cost;
  std::string error;
  EXPECT_TRUE(facet::compiler::estimateMobileCost(words, &cost, &error, weights)) << error;
  return cost;
}

}  // namespace

// Enough arithmetic that the stage is bound by it, not by its varyings.
std::string arithmeticBody(const std::string& extra) {
  std::string body = "void main() {\n    highp vec3 a = v_hi.xyz;\n";
  for (int i = 0; i < 12; ++i) body += "    a = a * a.yzx + vec3(" + std::to_string(i) + ".5) * a.zxy;\n";
  return body + "    o = vec4(a, " + extra + ");\n}\n";
}

TEST(MobileCost, AnAtanCostsItsPolynomialAndAnSfuOp) {
  auto plain = costOf(fragment(arithmeticBody("v_hi.w")));
  auto withAtan = costOf(fragment(arithmeticBody("atan(v_hi.w)")));
  EXPECT_EQ(plain.bound(), std::string("arithmetic"));
  EXPECT_EQ(withAtan.counts[OpClass::InverseTrig], 1);
  MobileCostWeights w;
  EXPECT_DOUBLE_EQ(withAtan.fmaSlots - plain.fmaSlots, w.inverseTrig.fma);
  EXPECT_DOUBLE_EQ(withAtan.sfuOps - plain.sfuOps, w.inverseTrig.sfu);
  EXPECT_GT(withAtan.cycles, plain.cycles);
  // In a small stage the varyings bound the cycles, but the arithmetic still grows.
  auto small = costOf(fragment("void main() { o = vec4(v_hi.x * v_hi.y + v_hi.z); }"));
  auto smallAtan = costOf(fragment("void main() { o = vec4(atan(v_hi.x * v_hi.y + v_hi.z)); }"));
  EXPECT_GT(smallAtan.arithmeticCycles, small.arithmeticCycles);
  // atan(y, x) and acos are counted too (the equirect lookup has both).
  auto equirect = costOf(fragment("void main() { o = vec4(atan(v_hi.z, v_hi.x), acos(v_hi.y), 0.0, 1.0); }"));
  EXPECT_EQ(equirect.counts[OpClass::Atan2], 1);
  EXPECT_EQ(equirect.counts[OpClass::InverseTrig], 1);
}

TEST(MobileCost, DivisionIsAReciprocalOnTheSfuAndAMultiply) {
  auto divided = costOf(fragment("void main() { o = vec4(v_hi.x / v_hi.y); }"));
  EXPECT_EQ(divided.counts[OpClass::Division], 1);
  EXPECT_EQ(divided.divisions(), 1);
  EXPECT_EQ(divided.sfuOps, 1);    // rcp
  EXPECT_EQ(divided.fmaSlots, 1);  // mul
  // By a constant: a multiply by the reciprocal, no SFU op.
  auto byConstant = costOf(fragment("void main() { o = vec4(v_hi.x / 3.0); }"));
  EXPECT_EQ(byConstant.counts[OpClass::Division], 0);
  EXPECT_EQ(byConstant.sfuOps, 0);
  // A vec3 division is three reciprocals.
  auto vec3 = costOf(fragment("void main() { o = vec4(v_hi.xyz / v_hi.w, 1.0); }"));
  EXPECT_EQ(vec3.counts[OpClass::Division], 3);
}

TEST(MobileCost, TranscendentalsExpandAsTheFactsSay) {
  // sqrt and pow: two SFU ops each; normalize: dot + inversesqrt + scale; exp2: one SFU op.
  auto sqrtCost = costOf(fragment("void main() { o = vec4(sqrt(v_hi.x)); }"));
  EXPECT_EQ(sqrtCost.sfuOps, 2);
  auto powCost = costOf(fragment("void main() { o = vec4(pow(v_hi.x, v_hi.y)); }"));
  EXPECT_EQ(powCost.sfuOps, 2);
  auto normalizeCost = costOf(fragment("void main() { o = vec4(normalize(v_hi.xyz), 1.0); }"));
  EXPECT_EQ(normalizeCost.sfuOps, 1);
  EXPECT_EQ(normalizeCost.counts[OpClass::Sfu], 1);
  EXPECT_EQ(normalizeCost.fmaSlots, 6);  // dot3 + three multiplies
  auto exp2Cost = costOf(fragment("void main() { o = vec4(exp2(v_hi.x)); }"));
  EXPECT_EQ(exp2Cost.sfuOps, 1);
  EXPECT_EQ(exp2Cost.transcendentals(), 1);
}

TEST(MobileCost, MultiplyAddFusesAndSaturateIsFree) {
  // glslang contracts a scalar a·b + c into Fma itself: one slot.
  EXPECT_EQ(costOf(fragment("void main() { o = vec4(v_hi.x * v_hi.y + v_hi.z); }")).fmaSlots, 1);
  // A vector multiply stays separate in the SPIR-V; the add that uses it once folds into it.
  auto fused = costOf(fragment("void main() { o = vec4(v_hi.xyz * v_hi.w + v_hi.zxy, 1.0); }"));
  EXPECT_EQ(fused.counts[OpClass::Fma], 3);
  EXPECT_EQ(fused.counts[OpClass::FusedAdd], 3);
  EXPECT_EQ(fused.fmaSlots, 3);
  // A product used twice stays a multiply: neither add absorbs it.
  auto shared =
      costOf(fragment("void main() { vec3 p = v_hi.xyz * v_hi.w; vec3 a = p + v_hi.zxy; vec3 b = p - v_hi.yzx; o = "
                      "vec4(a * b, 1.0); }"));
  EXPECT_EQ(shared.counts[OpClass::FusedAdd], 0);
  EXPECT_EQ(shared.counts[OpClass::Fma], 12);
  auto saturate = costOf(fragment("void main() { o = vec4(clamp(v_hi.x * v_hi.y, 0.0, 1.0)); }"));
  EXPECT_EQ(saturate.counts[OpClass::Modifier], 1);
  EXPECT_EQ(saturate.fmaSlots, 1);
  auto clamp = costOf(fragment("void main() { o = vec4(clamp(v_hi.x * v_hi.y, 0.25, 4.0)); }"));
  EXPECT_EQ(clamp.fmaSlots, 3);  // the multiply, min and max
}

TEST(MobileCost, VaryingsAreCountedInSixteenBitChannels) {
  auto cost = costOf(fragment("void main() { o = vec4(v_hi.xyz + v_med, v_hi.w); }"));
  EXPECT_EQ(cost.counts.varyingComponents, 4u);         // highp vec4
  EXPECT_EQ(cost.counts.varyingComponentsRelaxed, 3u);  // mediump vec3
  EXPECT_EQ(cost.varyingChannels, 2 * 4 + 3);
  MobileCostWeights w;
  EXPECT_DOUBLE_EQ(cost.varyingCycles, 11 / w.varyingChannelsPerCycle);
}

// Every field of the table is what the cycles are made of: change one, the estimate follows.
TEST(MobileCost, TheWeightsTableIsWhatTheCyclesAreMadeOf) {
  auto words = fragment(R"(void main() {
    highp float a = v_hi.x / v_hi.y;
    o = vec4(sqrt(a), exp2(v_hi.z), atan(v_hi.w), 1.0);
  })");
  MobileCostWeights w;
  auto base = costOf(words, w);
  EXPECT_DOUBLE_EQ(base.arithmeticCycles, std::max(base.fmaSlots, w.sfuFmaSlots * base.sfuOps) / w.fmaPerCycle);

  MobileCostWeights shared = w;
  shared.pipes = facet::compiler::ArithmeticPipes::Shared;
  auto sum = costOf(words, shared);
  EXPECT_DOUBLE_EQ(sum.arithmeticCycles, (sum.fmaSlots + w.sfuFmaSlots * sum.sfuOps) / w.fmaPerCycle);
  EXPECT_GT(sum.cycles, base.cycles);

  MobileCostWeights slowSfu = shared;
  slowSfu.sfuFmaSlots = 8;
  EXPECT_GT(costOf(words, slowSfu).cycles, sum.cycles);
  MobileCostWeights cheapTrig = shared;
  cheapTrig.inverseTrig = {5, 1};
  EXPECT_DOUBLE_EQ(costOf(words, cheapTrig).fmaSlots, sum.fmaSlots - (w.inverseTrig.fma - 5));
  MobileCostWeights cheapSqrt = shared;
  cheapSqrt.sqrt = {0, 1};
  EXPECT_DOUBLE_EQ(costOf(words, cheapSqrt).sfuOps, sum.sfuOps - 1);
  MobileCostWeights slowDivision = shared;
  slowDivision.division = {2, 2};
  EXPECT_DOUBLE_EQ(costOf(words, slowDivision).sfuOps, sum.sfuOps + 1);
  // Counting does not depend on the weights; weighing the same counts again gives the same cost.
  EXPECT_DOUBLE_EQ(facet::compiler::weighMobileCost(sum.counts, shared).cycles, sum.cycles);
}

TEST(MobileCost, MediumpArithmeticWeighsHalfASlot) {
  auto mediump = costOf(fragment("void main() { mediump vec3 a = v_med * v_med.zxy; o = vec4(a, 1.0); }"));
  EXPECT_EQ(mediump.counts.fmaRelaxed, 3);
  EXPECT_DOUBLE_EQ(mediump.fmaSlots, 1.5);
  MobileCostWeights unpaired;
  unpaired.relaxedFmaWeight = 1;
  EXPECT_DOUBLE_EQ(
      costOf(fragment("void main() { mediump vec3 a = v_med * v_med.zxy; o = vec4(a, 1.0); }"), unpaired).fmaSlots, 3);
}

TEST(MobileCost, MalformedModulesAreErrorsNotCrashes) {
  MobileStageCost cost;
  std::string error;
  EXPECT_FALSE(facet::compiler::estimateMobileCost({1, 2, 3}, &cost, &error));
  EXPECT_FALSE(facet::compiler::estimateMobileCost({0x07230203, 0x10000, 0, 10, 0, 0xffff0001}, &cost, &error));
  EXPECT_NE(error.find("truncated"), std::string::npos);
  // An instruction shorter than its opcode wants (an FAdd with no operands) is read within its words.
  std::vector<uint32_t> words = {
      0x07230203, 0x10000, 0, 10, 0, (2u << 16) | 54u, 1, (1u << 16) | 56u, (2u << 16) | 129u, 3, (1u << 16) | 56u};
  EXPECT_TRUE(facet::compiler::estimateMobileCost(words, &cost, &error)) << error;
}

// The example material's tiers, as the Mali-G57 measurements rank them (docs/eval.md quotes the
// figures next to the model's): reference > high > mid > low with a sun. With ambient light only,
// mid and low are the same shader (per-vertex SH diffuse, split-sum specular) bound by their
// varyings, as on Mali (0.81 cycles each, the v pipe); high is above them there (0.95) but not in
// the model (0.69 < 0.75): since the cube map took the environment lookup's arithmetic away, the
// model's known under-count of arithmetic (0.72–0.80 of Mesa's figures, docs/eval.md) puts an
// arithmetic-bound stage below a varying-bound one that Mali ranks above it. The figures are
// printed for the record.
TEST(MobileCost, RedPlasticTiersRankAsOnMali) {
  auto built = facet::test::buildFile(facet::test::examplePath("materials/red_plastic.mat"));
  ASSERT_TRUE(built);
  auto fragmentCost = [&](const std::string& key) {
    for (const auto& v : built->package.variants) {
      if (v.key != key) continue;
      for (const auto& s : v.shaders) {
        if (s.stage != facet::package::Stage::Fragment || s.target != facet::package::Target::Spirv) continue;
        std::vector<uint32_t> w(s.code.size() / 4);
        std::memcpy(w.data(), s.code.data(), w.size() * 4);
        return costOf(w);
      }
    }
    ADD_FAILURE() << "no " << key;
    return MobileStageCost{};
  };
  auto cycles = [&](const std::string& key) { return fragmentCost(key).cycles; };
  for (const char* d : {"dir1", "dir0"})
    std::printf("red_plastic %s fragment cycles: reference %.2f, high %.2f, mid %.2f, low %.2f\n", d,
                cycles(std::string("reference.") + d), cycles(std::string("high.") + d),
                cycles(std::string("mid.") + d), cycles(std::string("low.") + d));
  EXPECT_GT(cycles("reference.dir1"), cycles("high.dir1"));
  EXPECT_GT(cycles("high.dir1"), cycles("mid.dir1"));
  EXPECT_GT(cycles("mid.dir1"), cycles("low.dir1"));
  EXPECT_EQ(cycles("mid.dir0"), cycles("low.dir0"));
  for (const char* key : {"mid.dir0", "low.dir0"}) EXPECT_STREQ(fragmentCost(key).bound(), "varying") << key;
}

// The C++ side of the calibration (compiler/src/mesa_calibration.cpp) gives what fit.py's fit
// gives, for every example variant of the committed data on every GPU: the same features, in
// the same order, and weights as committed. (tests/gpu_stats/test_mesa_calibration.py checks that the
// file is what fit.py generates.)
TEST(MobileCost, CalibratedEstimateIsTheCommittedFit) {
  auto load = [](const std::string& name) {
    std::ifstream in(facet::test::sourceDir() + "/tools/calibration/" + name);
    return nlohmann::json::parse(in);
  };
  const nlohmann::json stats = load("mesa-stats.json"), fits = load("mesa-fit.json")["fits"];
  ASSERT_EQ(facet::compiler::gpuCalibrations().size(), fits.size());
  size_t checked = 0;
  for (const auto& [gpu, fit] : fits.items()) {
    const facet::compiler::GpuCalibration* calibration = facet::compiler::findGpuCalibration(gpu);
    ASSERT_NE(calibration, nullptr) << gpu;
    EXPECT_DOUBLE_EQ(calibration->crossValidatedMaxError, fit["cross_validated"]["max_abs_relative"].get<double>());
    for (const auto& [variant, figures] : fit["per_variant"].items()) {
      const nlohmann::json& ops = stats["variants"][variant]["op_counts"]["fragment"];
      facet::compiler::OpClassCounts counts;
      for (size_t k = 0; k < facet::compiler::kOpClassCount; ++k)
        counts.ops[k] = ops.at(facet::compiler::toString(OpClass(k))).get<double>();
      counts.fmaRelaxed = ops.at("fma_relaxed").get<double>();
      const double want = figures["after"].get<double>();
      EXPECT_NEAR(facet::compiler::calibratedEstimate(counts, *calibration), want, 1e-3 * want)
          << gpu << " " << variant;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 3u * 32u);
  EXPECT_EQ(facet::compiler::findGpuCalibration("mali-t880"), nullptr);
}

// The figure table (compiler/cost_figures.h) is the one place reports take a figure's name from:
// two figures under one name, or one heading for two columns, would make a report, budget or
// baseline say one figure and mean another.
TEST(CostFigures, EachNameAndHeadingBelongsToOneFigure) {
  std::set<std::string> names, headings;
  for (const facet::compiler::CostFigure& f : facet::compiler::costFigures()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    if (*f.column) {
      EXPECT_TRUE(headings.insert(f.column).second) << f.column;
    }
    const facet::compiler::CostFigure* found = facet::compiler::findCostFigure(f.name);
    ASSERT_NE(found, nullptr) << f.name;
    EXPECT_EQ(found->figure, f.figure) << f.name;
    EXPECT_NE(f.value == nullptr, f.text == nullptr) << f.name;  // a number or a word, never both
  }
  EXPECT_EQ(facet::compiler::findCostFigure("alus"), nullptr);
}

// Cells as `matc info` and `matc lint` print them, and the values baselines compare.
TEST(CostFigures, CellsAndReportedValuesKeepTheTablesPrecision) {
  using facet::compiler::Figure;
  facet::compiler::StageFigures s;
  s.mobile.cycles = 1.2345;
  s.mobile.counts.instructions.aluOps = 3;
  s.mobile.counts.instructions.relaxedOps = 2;
  const auto& cycles = facet::compiler::costFigure(Figure::Cycles);
  const auto& relaxed = facet::compiler::costFigure(Figure::RelaxedPercent);
  EXPECT_EQ(facet::compiler::formatFigure(cycles, cycles.value(s)), "1.23");
  EXPECT_EQ(facet::compiler::formatFigure(relaxed, relaxed.value(s)), "67%");
  EXPECT_DOUBLE_EQ(facet::compiler::reportedValue(cycles, s), 1.23);
  const facet::compiler::FigureColumn columns[] = {{Figure::Alu, 4}, {Figure::RelaxedPercent, 8}, {Figure::Cycles, 6}};
  EXPECT_EQ(facet::compiler::figureTableHeading(columns), "  variant            stage     alu  mediump cycles\n");
  EXPECT_EQ(facet::compiler::figureTableRow("high.dir1", "fragment", columns, s),
            "  high.dir1          fragment    3      67%   1.23\n");
}
