// matc builds a material's tuned tiers (docs/tune.md, "The tuning file"): `matc compile` reads
// `<stem>.tuning.json` beside the material (or --tuning FILE; --no-tuning for the presets), and
// `matc lint` and `matc eval`'s tiers as shipped agree with it; a bad tuning file fails the build
// at its JSON pointer with no package written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "facet/ir/check.h"
#include "facet/package/package.h"
#include "facet/permutations/tiers.h"
#include "facet/tune/choices.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using facet::test::run;

const std::string kMatc = FACET_MATC;

std::string write(const std::string& dir, const std::string& name, const std::string& text) {
  std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A copy of red_plastic and its committed tuning file in `dir`.
std::string copyTunedRedPlastic(const std::string& dir) {
  for (const char* name : {"red_plastic.mat", "red_plastic.tuning.json"})
    fs::copy_file(facet::test::examplePath(std::string("materials/") + name), dir + "/" + name,
                  fs::copy_options::overwrite_existing);
  return dir + "/red_plastic.mat";
}

facet::package::Package readPackage(const std::string& path) {
  const std::string text = facet::test::readText(path);
  facet::package::ReadResult r = facet::package::read({reinterpret_cast<const uint8_t*>(text.data()), text.size()});
  EXPECT_TRUE(r.package) << path << ": " << r.error;
  return r.package.value_or(facet::package::Package{});
}

std::map<std::string, facet::package::Variant> variantsByKey(const facet::package::Package& p) {
  std::map<std::string, facet::package::Variant> out;
  for (const facet::package::Variant& v : p.variants) out[v.key] = v;
  return out;
}

std::map<facet::permutations::Tier, facet::permutations::TierConfig> tunedTiersOf(const std::string& materialPath) {
  facet::ir::SourceFile file{materialPath, facet::test::readText(materialPath)};
  facet::ir::Diagnostics diags(file);
  std::optional<facet::ir::Material> material = facet::ir::compileSource(file, diags);
  EXPECT_TRUE(material) << diags.format();
  std::string error;
  std::optional<facet::tune::ShippedTuning> tuning =
      facet::tune::shippedTuning(materialPath, "", false, *material, &error);
  EXPECT_TRUE(tuning && tuning->choices) << error;
  return tuning && tuning->choices ? facet::tune::tunedTiers(*tuning->choices)
                                   : std::map<facet::permutations::Tier, facet::permutations::TierConfig>{};
}

}  // namespace

// The package is the tuned tiers' build: the same bytes as the library builds from the file's
// configurations; reference (never tuned) as the presets build it, every tuned tier different.
TEST(MatcTuning, CompileBuildsTheTiersOfTheTuningFileBesideTheMaterial) {
  const std::string dir = facet::test::scratchDir("matc-tuning-compile");
  const std::string red = copyTunedRedPlastic(dir);
  auto tuned = run(kMatc + " compile " + red + " -o " + dir + "/tuned.matpkg --no-cache --depfile " + dir + "/t.d");
  ASSERT_EQ(tuned.exitCode, 0) << tuned.err;
  EXPECT_NE(tuned.out.find("tiers tuned by " + dir + "/red_plastic.tuning.json"), std::string::npos) << tuned.out;
  EXPECT_NE(facet::test::readText(dir + "/t.d").find(dir + "/red_plastic.tuning.json"), std::string::npos);
  auto presets = run(kMatc + " compile " + red + " -o " + dir + "/presets.matpkg --no-cache --no-tuning");
  ASSERT_EQ(presets.exitCode, 0) << presets.err;
  EXPECT_EQ(presets.out.find("tuned"), std::string::npos) << presets.out;

  facet::compiler::BuildOptions options;
  options.tunedTiers = tunedTiersOf(red);
  ASSERT_EQ(options.tunedTiers.size(), 3u);
  EXPECT_EQ(options.tunedTiers[facet::permutations::Tier::High].specular, facet::permutations::SpecularModel::GgxFastV);
  std::optional<facet::compiler::BuildResult> built = facet::test::buildFile(red, options);
  ASSERT_TRUE(built);
  EXPECT_TRUE(facet::package::write(built->package) ==
              std::vector<uint8_t>(std::istreambuf_iterator<char>(std::ifstream(dir + "/tuned.matpkg").rdbuf()), {}));

  auto withTuning = variantsByKey(readPackage(dir + "/tuned.matpkg"));
  auto withPresets = variantsByKey(readPackage(dir + "/presets.matpkg"));
  ASSERT_EQ(withTuning.size(), 8u);
  for (const auto& [key, variant] : withTuning) {
    ASSERT_TRUE(withPresets.count(key)) << key;
    if (key.starts_with("reference."))
      EXPECT_TRUE(variant == withPresets[key]) << key;
    else
      EXPECT_FALSE(variant == withPresets[key]) << key << " is built as its preset";
  }

  // Deterministic; a material without a tuning file builds its presets; --tuning names one.
  ASSERT_EQ(run(kMatc + " compile " + red + " -o " + dir + "/again.matpkg").exitCode, 0);
  EXPECT_EQ(facet::test::readText(dir + "/again.matpkg"), facet::test::readText(dir + "/tuned.matpkg"));
  fs::rename(dir + "/red_plastic.tuning.json", dir + "/chosen.json");
  ASSERT_EQ(run(kMatc + " compile " + red + " -o " + dir + "/untuned.matpkg").exitCode, 0);
  EXPECT_EQ(facet::test::readText(dir + "/untuned.matpkg"), facet::test::readText(dir + "/presets.matpkg"));
  ASSERT_EQ(run(kMatc + " compile " + red + " --tuning " + dir + "/chosen.json -o " + dir + "/named.matpkg").exitCode,
            0);
  EXPECT_EQ(facet::test::readText(dir + "/named.matpkg"), facet::test::readText(dir + "/tuned.matpkg"));
  EXPECT_EQ(run(kMatc + " compile " + red + " --tuning " + dir + "/chosen.json --no-tuning").exitCode, 2);
}

// A malformed or stale tuning file: exit 1, the file and the JSON pointer named, no package.
TEST(MatcTuning, ABadTuningFileFailsTheBuildAtItsJsonPointer) {
  const std::string dir = facet::test::scratchDir("matc-tuning-errors");
  const std::string red = copyTunedRedPlastic(dir);
  const std::string tuning = dir + "/red_plastic.tuning.json";
  const std::string out = dir + "/out.matpkg";
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {R"({"material": "red_plastic", "tiers": )", tuning + ":1:"},
      {R"({"material": "red_plastic", "tiers": {"high": {"config": {"spekular": "lut"}}}})",
       tuning + ": error: /tiers/high/config/spekular: unknown axis 'spekular'"},
      {R"({"material": "red_plastic", "tiers": {"high": {"config": {"specular": "phong"}}}})",
       tuning + ": error: /tiers/high/config/specular: unknown option 'phong' (known: ggx_smith, ggx_fastv, "
                "fused_hammon, zioma, lut)"},
      {R"({"material": "red_plastic", "tiers": {"ultra": {}}})",
       tuning + ": error: /tiers/ultra: unknown tier 'ultra' (known: high, mid, low)"},
      {R"({"material": "red_plastic", "tiers": {"reference": {}}})",
       tuning + ": error: /tiers/reference: unknown tier 'reference'"},
      {R"({"material": "blue_plastic", "tiers": {}})",
       tuning + ": error: /material: the file tunes 'blue_plastic', not 'red_plastic'"},
      // red_plastic writes no clearCoat: the file cannot choose a coat for it.
      {R"({"material": "red_plastic", "tiers": {"high": {"config": {"clear_coat": "none"}}}})",
       tuning + ": error: /tiers/high/config/clear_coat: 'red_plastic' has nothing the axis 'clear_coat' changes: "
                "the file can only record the tier's own 'ggx_kelemen', not 'none'"},
      {R"({"material": "red_plastic"})", tuning + ": error: /tiers: missing"},
  };
  for (const Case& c : cases) {
    write(dir, "red_plastic.tuning.json", c.text);
    for (const std::string& command : {kMatc + " compile " + red + " -o " + out, kMatc + " lint " + red}) {
      auto r = run(command);
      EXPECT_EQ(r.exitCode, 1) << command << "\n" << c.text;
      EXPECT_NE(r.err.find(c.message), std::string::npos) << command << "\n" << r.err;
      EXPECT_FALSE(fs::exists(out)) << c.text;
    }
  }
  // A tier the file leaves out ships its preset; an axis the material cannot take may record the
  // tier's own option (what `matc tune --write` writes for every axis).
  write(dir, "red_plastic.tuning.json",
        R"({"material": "red_plastic", "tiers": {"low": {"config": {"clear_coat": "ambient"}}}})");
  EXPECT_EQ(run(kMatc + " compile " + red + " -o " + out).exitCode, 0);

  auto missing = run(kMatc + " compile " + red + " --tuning " + dir + "/none.json -o " + out);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find(dir + "/none.json: error: cannot open the tuning file: no such file"), std::string::npos)
      << missing.err;
  auto folder = run(kMatc + " compile " + red + " --tuning " + dir + " -o " + dir + "/folder.matpkg");
  EXPECT_EQ(folder.exitCode, 1);
  EXPECT_NE(folder.err.find(dir + ": error: cannot open the tuning file: not a regular file"), std::string::npos)
      << folder.err;
  EXPECT_FALSE(fs::exists(dir + "/folder.matpkg"));
}

// The file was searched from the material with its `tier` blocks, so it wins; a block it
// contradicts is reported.
TEST(MatcTuning, TheTuningFileWinsOverATierBlockItContradictsWithAWarning) {
  const std::string dir = facet::test::scratchDir("matc-tuning-blocks");
  const std::string body = "    shading lit\n    surface { baseColor = vec3(0.5); roughness = 0.4 }\n}\n";
  const std::string blocked = write(dir, "tiered.mat", "material tiered {\n    tier mid { diffuse = pixel }\n" + body);
  write(dir, "tiered.tuning.json", R"({"material": "tiered", "tiers": {"mid": {"config": {"diffuse": "vertex"}}}})");
  auto r = run(kMatc + " compile " + blocked + " -o " + dir + "/tiered.matpkg");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find(dir + "/tiered.tuning.json: warning: /tiers/mid/config/diffuse: 'vertex' replaces the "
                             "material's `tier mid { diffuse = pixel }`: the tuning file wins"),
            std::string::npos)
      << r.err;
  // mid's preset diffuse is per vertex: the build is that of the material without the block.
  const std::string plain = write(dir, "plain.mat", "material tiered {\n" + body);
  ASSERT_EQ(run(kMatc + " compile " + plain + " -o " + dir + "/plain.matpkg").exitCode, 0);
  auto tuned = variantsByKey(readPackage(dir + "/tiered.matpkg"));
  auto preset = variantsByKey(readPackage(dir + "/plain.matpkg"));
  EXPECT_TRUE(tuned["mid.dir1"] == preset["mid.dir1"]);
  ASSERT_EQ(run(kMatc + " compile " + blocked + " --no-tuning -o " + dir + "/block.matpkg").exitCode, 0);
  EXPECT_FALSE(variantsByKey(readPackage(dir + "/block.matpkg"))["mid.dir1"] == preset["mid.dir1"]);
}

// matc lint checks the tiers compile ships: the tuned ones, unless --no-tuning.
TEST(MatcTuning, LintChecksTheTunedTiers) {
  const std::string dir = facet::test::scratchDir("matc-tuning-lint");
  const std::string red = copyTunedRedPlastic(dir);
  auto figures = [&](const std::string& options) {
    auto r = run(kMatc + " lint " + red + " --format json " + options);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::map<std::string, nlohmann::json> byKey;
    const nlohmann::json report = nlohmann::json::parse(r.out);
    for (const nlohmann::json& v : report.at("files").at(0).at("variants")) byKey[v.at("key").get<std::string>()] = v;
    return byKey;
  };
  auto tuned = figures("");
  auto presets = figures("--no-tuning");
  ASSERT_TRUE(tuned.count("high.dir1") && presets.count("high.dir1"));
  EXPECT_EQ(tuned["reference.dir1"], presets["reference.dir1"]);
  EXPECT_NE(tuned["high.dir1"], presets["high.dir1"]);
}

// matc eval's tiers as shipped are the ones compile builds: the tuning file's.
TEST(MatcTuning, EvalMeasuresTheTunedTiersAsShipped) {
  const std::string dir = facet::test::scratchDir("matc-tuning-eval");
  const std::string red = copyTunedRedPlastic(dir);
  const auto tiers = tunedTiersOf(red);
  auto shippedHigh = [&](const std::string& options) {
    // ASAN_OPTIONS: test_matc_cli's EvalWritesItsReportOrFailsClearly says why.
    auto r = run("ASAN_OPTIONS=detect_leaks=0 " + kMatc + " eval " + red +
                 " --tiers high --no-swaps --sphere-pixels 8 --frames 0 --out " + dir + "/out " + options);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    nlohmann::json report = nlohmann::json::parse(facet::test::readText(dir + "/out/report.json"));
    for (const nlohmann::json& c : report.at("configurations"))
      if (c.at("name") == "high") return std::pair{c.at("tier_config").get<std::string>(), report.at("tuning_file")};
    ADD_FAILURE() << "no high in the report";
    return std::pair{std::string(), nlohmann::json()};
  };
  auto [tuned, file] = shippedHigh("");
  EXPECT_EQ(tuned, facet::permutations::describe(tiers.at(facet::permutations::Tier::High)));
  EXPECT_EQ(file, dir + "/red_plastic.tuning.json");
  auto [preset, none] = shippedHigh("--no-tuning");
  EXPECT_EQ(preset, facet::permutations::describe(facet::permutations::preset(facet::permutations::Tier::High)));
  EXPECT_EQ(none, "");
}
