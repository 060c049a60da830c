// gpu_stats (matc lint/eval --gpu): the GPU list, and what happens when the compilers or the tool
// are missing. Needs no Mesa build; the real compile is tests/gpu_stats/test_gpu_figures.py (skipped, exit
// 77, where scripts/build-mesa-shader-compilers.sh has not run).
#include <gtest/gtest.h>

#include "facet/gpu_stats/mesa_compile.h"
#include "facet/gpu_stats/report.h"

namespace {

using facet::gpu_stats::GpuStats;
using facet::gpu_stats::MesaTool;

const std::vector<facet::gpu_stats::ShaderPair> kPair = {
    {"p", "#version 300 es\nvoid main() { gl_Position = vec4(0.0); }\n",
     "#version 300 es\nprecision mediump float;\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n"}};

TEST(GpuList, KeepsOrderDropsRepeatsAndEmptyItems) {
  std::vector<std::string> gpus;
  std::string error;
  ASSERT_TRUE(facet::gpu_stats::parseGpuList("adreno-630,,mali-g52,adreno-630", &gpus, &error)) << error;
  EXPECT_EQ(gpus, (std::vector<std::string>{"adreno-630", "mali-g52"}));
}

TEST(GpuList, NamesTheUnknownGpuAndTheKnownOnes) {
  std::vector<std::string> gpus;
  std::string error;
  EXPECT_FALSE(facet::gpu_stats::parseGpuList("mali-g57,mali-g76", &gpus, &error));
  EXPECT_NE(error.find("unknown GPU 'mali-g76'"), std::string::npos) << error;
  EXPECT_NE(error.find("mali-g52, mali-g57, adreno-630"), std::string::npos) << error;
  EXPECT_FALSE(facet::gpu_stats::parseGpuList(",", &gpus, &error));
  EXPECT_NE(error.find("no GPU"), std::string::npos) << error;
}

TEST(Measure, CompilersAbsentEveryGpuSaysWhy) {
  MesaTool tool;
  tool.prefix = "/nonexistent/facet-mesa";
  std::vector<GpuStats> got = facet::gpu_stats::measure(kPair, {"mali-g57", "adreno-630"}, tool);
  ASSERT_EQ(got.size(), 2u);
  for (const GpuStats& g : got) {
    EXPECT_NE(g.unavailable.find("no Mesa build at /nonexistent/facet-mesa"), std::string::npos) << g.unavailable;
    EXPECT_TRUE(g.shaders.empty());
  }
  EXPECT_EQ(got[0].gpu, "mali-g57");
  std::string note = facet::gpu_stats::sourceNote(got);
  EXPECT_NE(note.find("mobile cost model"), std::string::npos) << note;
  EXPECT_NE(note.find("mali-g57 not measured: no Mesa build"), std::string::npos) << note;
  EXPECT_EQ(note.find("per-GPU figures"), std::string::npos) << note;
}

TEST(Measure, ToolAbsentSaysWhereItLooked) {
  MesaTool tool;
  tool.script = "/nonexistent/mesa_compile.py";
  std::vector<GpuStats> got = facet::gpu_stats::measure(kPair, {"mali-g52"}, tool);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_NE(got[0].unavailable.find("no mesa_compile.py at /nonexistent/mesa_compile.py"), std::string::npos)
      << got[0].unavailable;
}

TEST(Measure, PythonAbsentIsAMessageNotACrash) {
  MesaTool tool;
  tool.python = "/nonexistent/python3";
  std::vector<GpuStats> got = facet::gpu_stats::measure(kPair, {"mali-g52"}, tool);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_NE(got[0].unavailable.find("cannot run /nonexistent/python3"), std::string::npos) << got[0].unavailable;
}

TEST(Report, DescribesMaliAndAdrenoStages) {
  facet::gpu_stats::StageStats mali{"fragment", 270, 2.421875, "fma", 2, std::nullopt, 0};
  EXPECT_EQ(facet::gpu_stats::describe(mali), "2.42 cycles (fma), 270 instructions, 2 threads");
  facet::gpu_stats::StageStats adreno{"fragment", 230, std::nullopt, "", std::nullopt, 16, std::nullopt};
  EXPECT_EQ(facet::gpu_stats::describe(adreno), "230 instructions, 16 waves");
  GpuStats g{"mali-g57", "Mali-G57 (Panfrost)", "", {{"high.dir1", {mali}}}};
  nlohmann::json j = facet::gpu_stats::toJson(g);
  EXPECT_EQ(j["shaders"]["high.dir1"]["fragment"]["bound"], "fma");
  EXPECT_FALSE(j.contains("unavailable"));
  EXPECT_EQ(facet::gpu_stats::sourceNote({g}).find("per-GPU figures: Mesa 22.3's compilers on drm-shim (mali-g57)") !=
                std::string::npos,
            true);
}

}  // namespace

// The same paths through matc and eval's report, still without a Mesa build.
#include "facet/eval/evaluate.h"
#include "facet/eval/report.h"
#include "test_support.h"

namespace {

std::string matc() { return facet::test::binaryDir() + "/matc/matc"; }
std::string material() { return facet::test::sourceDir() + "/examples/materials/red_plastic.mat"; }

TEST(GpuOption, AnUnknownGpuIsAUsageErrorInLintAndEval) {
  for (const char* command : {"lint", "eval"}) {
    facet::test::CommandResult r =
        facet::test::run(matc() + " " + command + " " + material() + " --gpu mali-g57,mali-t880");
    EXPECT_EQ(r.exitCode, 2) << command << r.err;
    EXPECT_NE(r.err.find("--gpu: unknown GPU 'mali-t880'"), std::string::npos) << command << r.err;
  }
}

TEST(GpuOption, LintWithoutTheCompilersFallsBackToTheCostModelAndSaysSo) {
  facet::test::CommandResult r = facet::test::run(matc() + " lint " + material() +
                                                  " --tiers high --gpu mali-g52 --mesa-prefix /nonexistent/facet-mesa");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("cycles: the mobile cost model"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mali-g52 not measured: no Mesa build at /nonexistent/facet-mesa"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mali-g52: calibrated estimate of fragment cycles from the op counts instead"),
            std::string::npos)
      << r.out;
  facet::test::CommandResult j =
      facet::test::run(matc() + " lint " + material() +
                       " --tiers high --gpu mali-g52 --mesa-prefix /nonexistent/facet-mesa --format json");
  ASSERT_EQ(j.exitCode, 0) << j.err;
  const nlohmann::json gpu = nlohmann::json::parse(j.out)["files"][0]["gpus"][0];
  EXPECT_EQ(gpu["calibrated_estimate"]["measure"], "fragment cycles");
  EXPECT_GT(gpu["calibrated_estimate"]["variants"]["high.dir1"].get<double>(),
            gpu["calibrated_estimate"]["variants"]["high.dir0"].get<double>());  // a sun costs more than none
}

TEST(GpuOption, EvalReportWithoutTheCompilersSaysWhichFiguresItUsed) {
  facet::eval::EvalReport report;
  report.material = "m";
  facet::eval::ConfigurationResult c;
  c.configuration.name = "high";
  c.variantKey = "high.dir1";
  c.glslEs = kPair;
  c.fragment.counts[facet::compiler::OpClass::Fma] = 100;
  c.fragment.counts.fmaRelaxed = 100;
  report.results.push_back(c);
  MesaTool tool;
  tool.prefix = "/nonexistent/facet-mesa";
  facet::eval::addGpuFigures(&report, {"mali-g57"}, tool);
  ASSERT_EQ(report.gpuStats.size(), 1u);
  std::string md = facet::eval::reportMarkdown(report);
  EXPECT_NE(md.find("mali-g57 not measured: no Mesa build at /nonexistent/facet-mesa"), std::string::npos) << md;
  EXPECT_EQ(md.find("| configuration | variant | mali-g57 |"), std::string::npos) << md;  // no measured column
  EXPECT_NE(md.find("| configuration | variant | mali-g57 (estimate) |"), std::string::npos) << md;
  char cell[64];
  std::snprintf(
      cell, sizeof cell, "| high | high.dir1 | %.2f |",
      facet::compiler::calibratedEstimate(c.fragment.counts, *facet::compiler::findGpuCalibration("mali-g57")));
  EXPECT_NE(md.find(cell), std::string::npos) << md;
  EXPECT_NE(std::string(cell), "| high | high.dir1 | 0.00 |");
  EXPECT_EQ(facet::eval::reportJson(report)["gpus"][0]["unavailable"].get<std::string>().rfind("no Mesa build", 0), 0u);
}

}  // namespace
