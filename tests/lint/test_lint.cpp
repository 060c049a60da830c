// matc lint: each rule fires on a material written to break it, at the line that broke it, and
// stays silent on the example materials; budgets, baselines and the report formats.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "facet/compiler/glslang_backend.h"
#include "facet/compiler/spirv_tools_backend.h"
#include "facet/lint/lint.h"
#include "facet/lint/report.h"
#include "test_support.h"

namespace {

using facet::ir::Severity;
using facet::lint::LintOptions;
using facet::lint::MaterialLint;

MaterialLint lintText(const std::string& text, LintOptions options = {}) {
  facet::ir::SourceFile file{"test.mat", text};
  if (options.tiers == facet::permutations::supportedTiers()) options.tiers = {facet::permutations::Tier::High};
  return facet::lint::lintMaterial(file, options);
}

// "line:col rule" of every finding, for compact assertions.
std::vector<std::string> where(const MaterialLint& r) {
  std::vector<std::string> out;
  for (const auto& d : r.diagnostics)
    out.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " + d.code);
  return out;
}

bool has(const MaterialLint& r, const std::string& at) {
  auto w = where(r);
  return std::find(w.begin(), w.end(), at) != w.end();
}

// Line 1 is `material m {`, the parameters follow, then `surface {` and the statements.
std::string material(const std::string& params, const std::string& surface) {
  return "material m {\n" + params + "    surface {\n" + surface + "    }\n}\n";
}

const std::string kRoughness = "    param roughness: float = 0.5 in [0, 1]\n";

std::string dump(const MaterialLint& r) {
  std::string s;
  for (const auto& w : where(r)) s += w + "\n";
  for (const auto& d : r.diagnostics) s += d.message + "\n";
  return s;
}

}  // namespace

TEST(Lint, ExampleMaterialsHaveNoFindingsOnAnyTier) {
  for (const std::string& path : facet::test::exampleMaterials()) {
    SCOPED_TRACE(path);
    facet::ir::SourceFile file{path, facet::test::readText(path)};
    MaterialLint r = facet::lint::lintMaterial(file, LintOptions{});
    EXPECT_TRUE(r.diagnostics.empty()) << dump(r);
    EXPECT_EQ(r.variants.size(), 8u);  // 4 tiers × dir0/dir1
  }
}

TEST(Lint, ConstantsOutsideFp16NormalRangeInMediumpExpressionsAreFlagged) {
  // 1e-5 and 7.7e-6 flush to 0, 110000 overflows.
  MaterialLint r = lintText(material(kRoughness,
                                     "        let a = params.roughness * 1e-5\n"
                                     "        let b = params.roughness + 7.7e-6\n"
                                     "        let c = min(params.roughness * 110000.0, 1.0)\n"
                                     "        roughness = a + b + c\n"));
  EXPECT_TRUE(has(r, "4:36 fp16-constant")) << dump(r);
  EXPECT_TRUE(has(r, "5:36 fp16-constant")) << dump(r);
  // 0.5 × 110000 stays below 65504·2: the product's range [0, 110000] is proven beyond fp16, so
  // the policy computes it in highp: the constant is not in a mediump expression.
  EXPECT_FALSE(has(r, "6:40 fp16-constant")) << dump(r);
  // The reference tier is highp: no fp16 rule applies.
  LintOptions highp;
  highp.tiers = {facet::permutations::Tier::Reference};
  EXPECT_TRUE(
      lintText(material(kRoughness, "        roughness = params.roughness * 1e-5\n"), highp).diagnostics.empty());
}

TEST(Lint, OutputsBeyondFp16AreFlaggedEvenWhenComputedInHighp) {
  MaterialLint r =
      lintText(material("    param sun: float = 1.0 in [0, 100000]\n", "        emissive = vec3(params.sun)\n"));
  EXPECT_TRUE(has(r, "4:20 fp16-overflow")) << dump(r);
}

TEST(Lint, UnrangedFloatParametersAreFlaggedAtTheirDeclaration) {
  MaterialLint r = lintText(material("    param gain: float = 2.0\n    param tint: color = vec3(1.0)\n",
                                     "        baseColor = params.tint * params.gain\n"));
  EXPECT_TRUE(has(r, "2:11 unranged-param")) << dump(r);
  EXPECT_EQ(where(r).size(), 1u) << "a colour is [0, 1] by definition: " << dump(r);
}

TEST(Lint, SpecularAntiAliasingThatFiltersNothingIsFlaggedAtItsItem) {
  const std::string surface = "        roughness = params.roughness\n";
  for (const char* item :
       {"    specularAntiAliasing { variance 0 }\n", "    specularAntiAliasing { threshold 0.0 }\n"}) {
    MaterialLint r = lintText(material(item + kRoughness, surface));
    EXPECT_TRUE(has(r, "2:5 specular-aa-inert")) << item << dump(r);
  }
  MaterialLint r =
      lintText(material("    specularAntiAliasing { variance 0.15 threshold 0.2 }\n" + kRoughness, surface));
  EXPECT_FALSE(has(r, "2:5 specular-aa-inert")) << dump(r);
}

TEST(Lint, DivisionNeedsAProvenLowerBound) {
  MaterialLint r = lintText(
      material(kRoughness + "    param size: float = 1.0 in [0, 10]\n    param safe: float = 1.0 in [0.5, 10]\n",
               "        roughness = params.roughness / params.size\n"
               "        metallic = params.roughness / params.safe\n"));
  EXPECT_TRUE(has(r, "6:38 division-bound")) << dump(r);
  EXPECT_FALSE(has(r, "7:37 division-bound")) << dump(r);
  // In mediump, a divisor proven positive but below 2^-14 still flushes to 0.
  MaterialLint tiny =
      lintText(material("    param s: float = 0.001 in [0.00001, 1]\n", "        roughness = 1.0 / params.s\n"));
  EXPECT_TRUE(has(tiny, "4:25 division-bound")) << dump(tiny);
}

TEST(Lint, SqrtAndLogOutsideTheirDomainAreFlagged) {
  MaterialLint r = lintText(material(kRoughness,
                                     "        let a = sqrt(-1.0)\n"
                                     "        let b = sqrt(params.roughness - 0.5)\n"
                                     "        let c = log2(params.roughness)\n"
                                     "        roughness = a + b + c\n"));
  EXPECT_TRUE(has(r, "4:17 domain")) << dump(r);
  EXPECT_TRUE(has(r, "5:17 domain")) << dump(r);
  EXPECT_TRUE(has(r, "6:17 domain")) << dump(r);
  // sqrt(-1.0) is NaN wherever it runs: an error, the others warnings.
  EXPECT_TRUE(r.hasErrors());
  for (const auto& d : r.diagnostics)
    EXPECT_EQ(d.severity, d.loc.line == 4 ? Severity::Error : Severity::Warning) << d.message;
}

// The directions the shaders normalize in mediump (normal_mapping.glsl's tangent_to_world for
// `normal` and `clearCoatNormal`, anisotropy_frame.glsl for `anisotropyDirection`, and the
// material's own normalize): x · x flushes to 0 below 2^-14 (NaN) and is +inf above 65504. A normal
// map's sample counts as a unit vector; anisotropyDirection may be short (the frame's fallback).
TEST(Lint, DirectionsTheShadersNormalizeKeepALengthFp16Holds) {
  const std::string params =
      "    param bump: float = 0.5 in [0, 1]\n"
      "    param relief: texture(normal) = vec4(0.5, 0.5, 1.0, 1.0)\n"
      "    param big: float = 1.0 in [0, 1000]\n";
  MaterialLint r = lintText(material(params,
                                     "        clearCoat = 1.0\n"
                                     "        clearCoatNormal = vec3(0.0, 0.0, params.bump)\n"
                                     "        normal = sample(params.relief, vertex.uv0) * 0.005\n"
                                     "        anisotropy = 0.5\n"
                                     "        anisotropyDirection = vec3(params.big, 0.0, 0.0)\n"
                                     "        baseColor = normalize(vec3(params.bump, 0.0, 0.0))\n"));
  EXPECT_TRUE(has(r, "7:27 direction-length")) << dump(r);   // clearCoatNormal: z reaches 0
  EXPECT_TRUE(has(r, "8:52 direction-length")) << dump(r);   // normal: always 0.005 long
  EXPECT_TRUE(has(r, "10:31 direction-length")) << dump(r);  // anisotropyDirection: up to 1000 long
  EXPECT_TRUE(has(r, "11:21 direction-length")) << dump(r);  // normalize of a vector that can be 0
  EXPECT_EQ(where(r).size(), 4u) << dump(r);
  for (const auto& d : r.diagnostics)
    EXPECT_EQ(d.severity, d.loc.line == 8 ? Severity::Error : Severity::Warning) << d.message;

  // The same outputs within fp16's reach: a unit map scaled by [0.5, 1.5], a z of at least 0.5, a
  // short anisotropyDirection (the frame replaces it), a normalized map: no finding.
  const std::string safeParams = params.substr(0, params.rfind("    param big"));
  MaterialLint safe = lintText(material(safeParams,
                                        "        clearCoat = 1.0\n"
                                        "        clearCoatNormal = vec3(0.0, params.bump, 0.5 + params.bump)\n"
                                        "        normal = sample(params.relief, vertex.uv0) * (0.5 + params.bump)\n"
                                        "        anisotropy = 0.5\n"
                                        "        anisotropyDirection = vec3(params.bump, 0.0, 0.0)\n"
                                        "        baseColor = normalize(-sample(params.relief, vertex.uv0))\n"));
  EXPECT_TRUE(safe.diagnostics.empty()) << dump(safe);

  // The zero vector is NaN in every precision; the reference tier alone (highp) has no fp16 rule.
  MaterialLint zero = lintText(material("", "        normal = vec3(0.0)\n"));
  ASSERT_EQ(where(zero), std::vector<std::string>{"3:18 direction-length"}) << dump(zero);
  EXPECT_NE(zero.diagnostics[0].message.find("always the zero vector"), std::string::npos);
  LintOptions highp;
  highp.tiers = {facet::permutations::Tier::Reference};
  const std::string bump = "    param bump: float = 0.5 in [0, 1]\n";
  EXPECT_TRUE(has(lintText(material(bump, "        normal = vec3(0.0, 0.0, params.bump)\n")), "4:18 direction-length"));
  EXPECT_TRUE(lintText(material(bump, "        normal = vec3(0.0, 0.0, params.bump)\n"), highp).diagnostics.empty());
}

TEST(Lint, ReservedNamesAreLanguageErrors) {
  MaterialLint r =
      lintText(material("    param discard: float = 0.5 in [0, 1]\n", "        roughness = params.discard\n"));
  EXPECT_TRUE(has(r, "2:11 reserved-name")) << dump(r);
  EXPECT_TRUE(r.variants.empty());
}

TEST(Lint, VariantBeyondGles30UniformVectorsIsAnError) {
  // 200 vec4 parameters: 200 vectors of MaterialParams on top of the frame and object blocks
  // exceed the 224 fragment uniform vectors GLES 3.0 guarantees.
  std::string params, sum = "vec4(0.0)";
  for (int i = 0; i < 200; ++i) {
    params += "    param p" + std::to_string(i) + ": vec4 = vec4(0.5) in [0, 1]\n";
    sum = "(" + sum + " + params.p" + std::to_string(i) + ")";
  }
  MaterialLint r = lintText(material(params, "        baseColor = " + sum + ".xyz\n"));
  bool found = false;
  for (const auto& d : r.diagnostics)
    found = found || (d.code == "gles-limit" && d.severity == Severity::Error &&
                      d.message.find("fragment stage uses") != std::string::npos &&
                      d.message.find("uniform vectors; GLES 3.0 guarantees only 224") != std::string::npos);
  EXPECT_TRUE(found) << dump(r);
}

TEST(Lint, BudgetNamesMaterialVariantFigureAndLimit) {
  std::string error;
  auto budgets = facet::lint::parseBudgets(
      "b.json", R"({"tiers": {"high": {"fragment": {"alu": 10, "min_relaxed_percent": 99}}}})", &error);
  ASSERT_TRUE(budgets) << error;
  LintOptions options;
  options.budgets = &*budgets;
  MaterialLint r = lintText(material(kRoughness, "        roughness = params.roughness\n"), options);
  bool alu = false, relaxed = false;
  for (const auto& d : r.diagnostics) {
    alu = alu || (d.code == "budget" && d.message.find("material 'm' variant high.dir1 fragment stage: alu ") == 0 &&
                  d.message.find("exceeds the high budget 10") != std::string::npos);
    relaxed = relaxed || (d.code == "budget" && d.message.find("below the high budget's 99 %") != std::string::npos);
  }
  EXPECT_TRUE(alu) << dump(r);
  EXPECT_TRUE(relaxed) << dump(r);
}

TEST(Lint, BaselineFailsOnGrowthBeyondToleranceAndRoundTrips) {
  const std::string text = material(kRoughness, "        roughness = params.roughness\n");
  MaterialLint first = lintText(text);
  ASSERT_FALSE(first.variants.empty());
  facet::lint::Baseline baseline;
  for (const auto& v : first.variants)
    for (auto [stage, f] : {std::pair{"vertex", &v.vertex}, {"fragment", &v.fragment}})
      for (const auto& [name, value] : facet::lint::namedFigures(*f))
        baseline.materials["m"][v.key][stage][name] = value;
  std::string error;
  auto reread = facet::lint::parseBaseline("base.json", facet::lint::writeBaseline(baseline), &error);
  ASSERT_TRUE(reread) << error;

  LintOptions options;
  options.baseline = &*reread;
  EXPECT_TRUE(lintText(text, options).diagnostics.empty()) << dump(lintText(text, options));

  // A heavier surface program grows the fragment stage's ALU count past 5 %.
  MaterialLint heavier = lintText(material(kRoughness,
                                           "        roughness = sqrt(params.roughness) * sin(params.roughness) + "
                                           "cos(params.roughness * 3.0) * exp2(params.roughness)\n"),
                                  options);
  bool grew = false;
  for (const auto& d : heavier.diagnostics)
    grew = grew || (d.code == "baseline-regression" && d.severity == Severity::Error);
  EXPECT_TRUE(grew) << dump(heavier);

  options.tiers = {facet::permutations::Tier::Mid};  // not recorded: a warning, not a failure
  MaterialLint missing = lintText(text, options);
  EXPECT_FALSE(missing.hasErrors());
  EXPECT_FALSE(missing.diagnostics.empty());
  EXPECT_EQ(missing.diagnostics[0].code, "baseline-missing");
}

TEST(Lint, BudgetAndBaselineFilesReportTheirJsonPointer) {
  std::string error;
  EXPECT_FALSE(facet::lint::parseBudgets("b.json", R"({"tiers": {"high": {"fragmnt": {}}}})", &error));
  EXPECT_EQ(error, "b.json: error: /tiers/high/fragmnt: expected \"vertex\" or \"fragment\"");
  EXPECT_FALSE(facet::lint::parseBudgets("b.json", R"({"tiers": {"high": {"fragment": {"alu": -1}}}})", &error));
  EXPECT_EQ(error, "b.json: error: /tiers/high/fragment/alu: expected a finite number ≥ 0");
  EXPECT_FALSE(facet::lint::parseBaseline("base.json", "{\n  \"materials\": [1,\n", &error));
  EXPECT_EQ(error.rfind("base.json:3:1: error: invalid JSON", 0), 0u) << error;
}

// A name lint does not know would switch its check off without a word (a budget on "alus" limits
// nothing, a baseline entry for "hgh.dir1" is never compared): unknown figures, tiers, variant
// keys and top-level keys are errors at their JSON pointer, with the names lint knows.
TEST(Lint, UnknownNamesInBudgetAndBaselineFilesAreErrors) {
  const std::string figures =
      "cycles, alu, scalar_alu, transcendental, divisions, textures, varying_components, "
      "input_vectors, output_vectors, uniform_vectors, samplers";
  std::string error;
  EXPECT_FALSE(facet::lint::parseBudgets("b.json", R"({"tiers": {"high": {"fragment": {"alus": 10}}}})", &error));
  EXPECT_EQ(error, "b.json: error: /tiers/high/fragment/alus: unknown figure 'alus' (known: " + figures +
                       ", min_relaxed_percent)");
  EXPECT_FALSE(facet::lint::parseBudgets("b.json", R"({"tiers": {"hgh": {"fragment": {"alu": 10}}}})", &error));
  EXPECT_EQ(error, "b.json: error: /tiers/hgh: unknown tier 'hgh' (known: reference, high, mid, low)");
  EXPECT_FALSE(facet::lint::parseBudgets("b.json", R"({"tiers": {"a/b~": {}}})", &error));
  EXPECT_EQ(error, "b.json: error: /tiers/a~1b~0: unknown tier 'a/b~' (known: reference, high, mid, low)");
  EXPECT_FALSE(facet::lint::parseBudgets("b.json", R"({"tiers": {}, "teirs": {"high": {}}})", &error));
  EXPECT_EQ(error, "b.json: error: /teirs: unknown key 'teirs' (expected only \"tiers\")");

  EXPECT_FALSE(facet::lint::parseBaseline("base.json",
                                          R"({"materials": {"m": {"high.dir1": {"fragment": {"alus": 1}}}}})", &error));
  EXPECT_EQ(error,
            "base.json: error: /materials/m/high.dir1/fragment/alus: unknown figure 'alus' (known: " + figures + ")");
  EXPECT_FALSE(facet::lint::parseBaseline("base.json", R"({"materials": {"m": {"hgh.dir1": {}}}})", &error));
  EXPECT_EQ(error,
            "base.json: error: /materials/m/hgh.dir1: 'hgh.dir1' is not a variant key "
            "(<tier>.dir<0|1>[.pt<1|2|4>], tiers: reference, high, mid, low)");
  EXPECT_FALSE(facet::lint::parseBaseline("base.json", R"({"materials": {}, "material": {}})", &error));
  EXPECT_EQ(error, "base.json: error: /material: unknown key 'material' (expected only \"materials\")");

  for (const char* file : {"lint/budgets.json", "lint/baseline.json"}) {  // the project's own files still parse
    const std::string path = facet::test::examplePath(file), text = facet::test::readText(path);
    EXPECT_TRUE(std::string(file) == "lint/budgets.json" ? bool(facet::lint::parseBudgets(path, text, &error))
                                                         : bool(facet::lint::parseBaseline(path, text, &error)))
        << error;
  }
}

TEST(Lint, JsonAndSarifReportsCarryEveryFindingWithItsLocation) {
  facet::lint::LintedFile f{{"materials/test file.mat", material("", "        roughness = sqrt(-1.0)\n")}, {}};
  LintOptions options;
  options.tiers = {facet::permutations::Tier::High};
  f.result = facet::lint::lintMaterial(f.file, options);
  ASSERT_FALSE(f.result.diagnostics.empty());

  auto json = nlohmann::json::parse(facet::lint::formatJson({f}));
  EXPECT_EQ(json["errors"], 1);
  EXPECT_EQ(json["files"][0]["diagnostics"][0]["rule"], "domain");
  EXPECT_EQ(json["files"][0]["diagnostics"][0]["line"], 3);  // material() puts the statement on line 3
  EXPECT_EQ(json["files"][0]["variants"].size(), 2u);

  auto sarif = nlohmann::json::parse(facet::lint::formatSarif({f}, "facet-matc test"));
  EXPECT_EQ(sarif["version"], "2.1.0");
  const auto& result = sarif["runs"][0]["results"][0];
  EXPECT_EQ(result["ruleId"], "domain");
  EXPECT_EQ(result["level"], "error");
  EXPECT_EQ(result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"], "materials/test%20file.mat");
  EXPECT_EQ(result["locations"][0]["physicalLocation"]["region"]["startLine"], 3);
  EXPECT_EQ(result["locations"][0]["physicalLocation"]["region"]["startColumn"], 21);
}

TEST(Lint, PositionsAndUvsReadInMediumpAreErrors) {
  facet::lint::VariantFigures figures;
  figures.key = "high.dir1";
  figures.fragment.interface.relaxedInputs = {"v_normal", "v_uv0"};
  std::vector<facet::ir::Diagnostic> found;
  facet::lint::lintVariant("m", figures, LintOptions{}, &found);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].code, "highp-required");
  EXPECT_EQ(found[0].message,
            "material 'm' variant high.dir1 fragment stage reads 'v_uv0' in mediump; positions and UVs need highp");
}

// What the GLES-limit and highp rules read: SPIRV-Cross reflection of the compiled stage.
TEST(Lint, InterfaceFiguresComeFromTheCompiledStage) {
  facet::ir::SourceFile file{"painted_tiles.mat",
                             facet::test::readText(facet::test::examplePath("materials/painted_tiles.mat"))};
  LintOptions options;
  options.tiers = {facet::permutations::Tier::High};
  MaterialLint r = facet::lint::lintMaterial(file, options);
  ASSERT_EQ(r.variants.size(), 2u);
  const auto& f = r.variants[1].fragment.interface;  // high.dir1
  EXPECT_EQ(r.variants[1].key, "high.dir1");
  // albedo + relief + the DFG table + the environment
  EXPECT_EQ(f.samplers, 4u);
  // Mediump varyings exist (the normal, the tangent); none is a position or UV.
  EXPECT_FALSE(f.relaxedInputs.empty());
  for (const std::string& name : f.relaxedInputs) EXPECT_TRUE(name != "v_uv0" && name != "v_worldPosition") << name;
}

namespace {
namespace shadow {

// A hand-made receiver, the shape of templates/forward.vert.glsl and chunks/shadow_sun.glsl:
// the vertex stage offsets the position along the mediump normal and writes the sun-frame
// position; the fragment stage scales it into the atlas and compares. Each case below turns one
// value on that way mediump.
std::string block(const std::string& depth) {
  return "layout(set = 0, binding = 4, std140) uniform ShadowUniforms {\n"
         "  highp mat4 lightView; highp vec4 scale; " +
         depth + " vec4 depthScaleOffset;\n} shadow;\n";
}

std::string vertexStage(const std::string& shadowPosition = "highp", const std::string& light = "highp",
                        const std::string& depth = "highp") {
  return std::string("#version 310 es\nprecision highp float;\n") + block(depth) +
         "layout(location = 0) in highp vec3 a_position;\n"
         "layout(location = 1) in highp vec3 a_normal;\n"
         "layout(location = 0) out mediump vec3 v_normal;\n"
         "layout(location = 1) out " +
         shadowPosition +
         " vec4 v_shadowPosition;\n"
         "void main() {\n"
         "  v_normal = normalize(a_normal);\n"
         "  highp vec3 offsetPosition = a_position + v_normal * shadow.scale.w;\n"
         "  " +
         light +
         " vec3 light = (shadow.lightView * vec4(offsetPosition, 1.0)).xyz;\n"
         "  v_shadowPosition = vec4(light, 1.0);\n"
         "  gl_Position = vec4(a_position, 1.0);\n"
         "}\n";
}

std::string fragmentStage(const std::string& shadowPosition = "highp", const std::string& depth = "highp") {
  return std::string("#version 310 es\nprecision mediump float;\n") + block(depth) +
         "layout(set = 1, binding = 3) uniform highp sampler2DShadow facet_shadowAtlas;\n"
         "layout(location = 0) in mediump vec3 v_normal;\n"
         "layout(location = 1) in " +
         shadowPosition +
         " vec4 v_shadowPosition;\n"
         "layout(location = 0) out vec4 fragColor;\n"
         "void main() {\n"
         "  highp vec2 coord = v_shadowPosition.xy * shadow.scale.xy;\n"
         "  highp float reference = v_shadowPosition.z * shadow.depthScaleOffset.x + shadow.depthScaleOffset.y;\n"
         "  float lit = texture(facet_shadowAtlas, vec3(coord, reference));\n"
         "  fragColor = vec4(v_normal * lit, 1.0);\n"
         "}\n";
}

// A spot receiver's fragment stage (chunks/shadow_spot.glsl): the perspective divide, at `divide`
// precision, then the compare.
std::string spotFragmentStage(const std::string& divide) {
  return std::string("#version 310 es\nprecision mediump float;\n") + block("highp") +
         "layout(set = 1, binding = 3) uniform highp sampler2DShadow facet_shadowAtlas;\n"
         "layout(location = 0) in mediump vec3 v_normal;\n"
         "layout(location = 1) in highp vec4 v_shadowPosition;\n"
         "layout(location = 0) out vec4 fragColor;\n"
         "void main() {\n"
         "  " +
         divide + " vec4 light = v_shadowPosition;\n  " + divide +
         " vec3 projected = light.xyz / max(light.w, 1e-6);\n"
         "  float lit = texture(facet_shadowAtlas, projected);\n"
         "  fragColor = vec4(v_normal * lit, 1.0);\n"
         "}\n";
}

// Compiled and optimised as matc builds a variant's SPIR-V, then analysed and linted.
facet::lint::VariantFigures lintReceiver(const std::string& vertex, const std::string& fragment,
                                         std::vector<facet::ir::Diagnostic>* found) {
  facet::compiler::StageSources sources;
  sources.vertex = vertex;
  sources.fragment = fragment;
  facet::compiler::SpirvStages spirv;
  std::string log;
  facet::lint::VariantFigures figures;
  figures.key = "low.dir1.sh1";
  EXPECT_TRUE(facet::compiler::compileToSpirv(sources, &spirv, &log)) << log;
  EXPECT_TRUE(facet::compiler::optimizeSpirv(&spirv.vertex, &log)) << log;
  EXPECT_TRUE(facet::compiler::optimizeSpirv(&spirv.fragment, &log)) << log;
  EXPECT_TRUE(facet::lint::analyseShadowPrecision(spirv.vertex, spirv.fragment, &figures.shadow, &log)) << log;
  facet::lint::lintVariant("m", figures, LintOptions{}, found);
  return figures;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace shadow
}  // namespace

TEST(Lint, MediumpShadowCoordinatesAndCompareDepthsAreErrors) {
  using namespace shadow;
  {
    SCOPED_TRACE("highp on the whole way; the normal offset's mediump direction is allowed");
    std::vector<facet::ir::Diagnostic> found;
    const auto figures = lintReceiver(vertexStage(), fragmentStage(), &found);
    EXPECT_EQ(figures.shadow.compares, 1u);
    EXPECT_GT(figures.shadow.feeding, 5u);
    EXPECT_TRUE(figures.shadow.vertexRelaxed.empty()) << figures.shadow.vertexRelaxed.front();
    EXPECT_TRUE(figures.shadow.fragmentRelaxed.empty()) << figures.shadow.fragmentRelaxed.front();
    EXPECT_TRUE(found.empty()) << found.front().message;
  }
  {
    SCOPED_TRACE("the fragment stage reads the shadow position in mediump");
    std::vector<facet::ir::Diagnostic> found;
    const auto figures = lintReceiver(vertexStage(), fragmentStage("mediump"), &found);
    EXPECT_TRUE(contains(figures.shadow.fragmentRelaxed, "v_shadowPosition"));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].code, "shadow-precision");
    EXPECT_EQ(found[0].severity, Severity::Error);
    EXPECT_EQ(found[0].message.rfind("material 'm' variant low.dir1.sh1 fragment stage computes a shadow coordinate "
                                     "or compare depth in mediump (",
                                     0),
              0u)
        << found[0].message;
    EXPECT_NE(found[0].message.find("v_shadowPosition"), std::string::npos) << found[0].message;
  }
  {
    SCOPED_TRACE("the vertex stage writes it in mediump");
    std::vector<facet::ir::Diagnostic> found;
    const auto figures = lintReceiver(vertexStage("mediump"), fragmentStage(), &found);
    EXPECT_TRUE(contains(figures.shadow.vertexRelaxed, "v_shadowPosition"));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_NE(found[0].message.find("vertex stage"), std::string::npos) << found[0].message;
  }
  {
    SCOPED_TRACE("the vertex stage computes the sun-frame position in mediump, into a highp output");
    std::vector<facet::ir::Diagnostic> found;
    const auto figures = lintReceiver(vertexStage("highp", "mediump"), fragmentStage(), &found);
    EXPECT_FALSE(figures.shadow.vertexRelaxed.empty());
    EXPECT_TRUE(figures.shadow.fragmentRelaxed.empty());
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].code, "shadow-precision");
  }
  {
    SCOPED_TRACE("the compare depth computed from a mediump scale and offset");
    std::vector<facet::ir::Diagnostic> found;
    const auto figures =
        lintReceiver(vertexStage("highp", "highp", "mediump"), fragmentStage("highp", "mediump"), &found);
    EXPECT_FALSE(figures.shadow.fragmentRelaxed.empty());
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].code, "shadow-precision");
  }
  {
    SCOPED_TRACE("a spot's perspective divide in highp passes, in mediump it is an error");
    std::vector<facet::ir::Diagnostic> found;
    auto figures = lintReceiver(vertexStage(), spotFragmentStage("highp"), &found);
    EXPECT_TRUE(figures.shadow.fragmentRelaxed.empty()) << figures.shadow.fragmentRelaxed.front();
    EXPECT_TRUE(found.empty()) << found.front().message;
    figures = lintReceiver(vertexStage(), spotFragmentStage("mediump"), &found);
    EXPECT_FALSE(figures.shadow.fragmentRelaxed.empty());
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].code, "shadow-precision");
  }
}

// Light-space coordinates stay highp in every tier (docs/shadows.md): what the compiler writes for
// every receiver passes the rule, whose analysis finds each compare and the values feeding it.
TEST(Lint, ShadowCoordinatesStayHighpInEveryTier) {
  facet::ir::SourceFile file{"red_plastic.mat",
                             facet::test::readText(facet::test::examplePath("materials/red_plastic.mat"))};
  LintOptions options;
  options.shadowCascadeCounts = {0, 1, 4};
  MaterialLint r = facet::lint::lintMaterial(file, options);
  EXPECT_FALSE(r.hasErrors());
  size_t receivers = 0;
  for (const auto& v : r.variants) {
    SCOPED_TRACE(v.key);
    const bool receiver = v.key.find(".sh") != std::string::npos;
    const bool oneTap = v.key.rfind("low", 0) == 0 || v.key.rfind("mid", 0) == 0;
    EXPECT_EQ(v.shadow.compares, receiver ? (oneTap ? 1u : 4u) : 0u);
    if (!receiver) continue;
    ++receivers;
    EXPECT_GT(v.shadow.feeding, 5u);
    EXPECT_TRUE(v.shadow.vertexRelaxed.empty());
    EXPECT_TRUE(v.shadow.fragmentRelaxed.empty());
  }
  EXPECT_EQ(receivers, 8u);  // dir1 of four tiers, .sh1 and .sh4
}

// The spot's receiver (chunks/shadow_spot.glsl): its perspective coordinate and divide stay highp
// too, alone and beside the sun's; a variant receiving both compares twice as often.
TEST(Lint, SpotShadowCoordinatesStayHighpInEveryTier) {
  facet::ir::SourceFile file{"red_plastic.mat",
                             facet::test::readText(facet::test::examplePath("materials/red_plastic.mat"))};
  LintOptions options;
  options.shadowCascadeCounts = {0, 2};
  options.pointLightCounts = {1};
  options.spotShadows = true;
  MaterialLint r = facet::lint::lintMaterial(file, options);
  EXPECT_FALSE(r.hasErrors());
  size_t receivers = 0;
  for (const auto& v : r.variants) {
    SCOPED_TRACE(v.key);
    const unsigned lights =
        (v.key.find(".sp1") != std::string::npos ? 1u : 0u) + (v.key.find(".sh") != std::string::npos ? 1u : 0u);
    const bool oneTap = v.key.rfind("low", 0) == 0 || v.key.rfind("mid", 0) == 0;
    EXPECT_EQ(v.shadow.compares, lights * (oneTap ? 1u : 4u));
    if (v.key.find(".sp1") == std::string::npos) continue;
    ++receivers;
    EXPECT_GT(v.shadow.feeding, 5u);
    EXPECT_TRUE(v.shadow.vertexRelaxed.empty());
    EXPECT_TRUE(v.shadow.fragmentRelaxed.empty());
  }
  EXPECT_EQ(receivers, 12u);  // four tiers: dir0.pt1, dir1.pt1, dir1.sh2.pt1
}
