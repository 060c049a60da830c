// matc as users run it: exit codes, diagnostics on stderr, no partial output on failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>
#include <regex>

#include "facet/abi/shader_abi.h"
#include "facet/compiler/cost_figures.h"
#include "facet/package/package.h"

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

}  // namespace

TEST(MatcCli, CompileWritesAPackageThatInfoDescribes) {
  std::string dir = facet::test::scratchDir("cli-compile");
  auto r =
      run(kMatc + " compile " + facet::test::examplePath("materials/red_plastic.mat") + " -o " + dir + "/red.matpkg");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("red_plastic: 8 variants"), std::string::npos) << r.out;

  r = run(kMatc + " info " + dir + "/red.matpkg");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("material   red_plastic"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("roughness        float  = 0.35 in [0, 1]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("high.dir1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fragment msl"), std::string::npos) << r.out;
}

TEST(MatcCli, InfoPrintsAnyShaderOfAnyTarget) {
  std::string dir = facet::test::scratchDir("cli-info");
  ASSERT_EQ(
      run(kMatc + " compile " + facet::test::examplePath("materials/brushed_gold.mat") + " -o " + dir + "/g.matpkg")
          .exitCode,
      0);
  std::string base = kMatc + " info " + dir + "/g.matpkg --variant high.dir1 --stage fragment --target ";
  auto spirv = run(base + "spirv");
  EXPECT_EQ(spirv.exitCode, 0);
  EXPECT_NE(spirv.out.find("OpEntryPoint Fragment"), std::string::npos);
  auto glsl = run(base + "glsl_es_300");
  EXPECT_EQ(glsl.out.rfind("#version 300 es", 0), 0u);
  auto msl = run(base + "msl");
  EXPECT_NE(msl.out.find("fragment main0_out main0("), std::string::npos);

  auto missing = run(kMatc + " info " + dir + "/g.matpkg --variant low.dir2 --stage fragment --target msl");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("package has no variant 'low.dir2' (it has: reference.dir0, reference.dir1, high.dir0, "
                             "high.dir1, mid.dir0, mid.dir1, low.dir0, low.dir1)"),
            std::string::npos)
      << missing.err;
}

TEST(MatcCli, EmitSourceWritesEveryGeneratedSource) {
  std::string dir = facet::test::scratchDir("cli-emit");
  auto r = run(kMatc + " compile " + facet::test::examplePath("materials/red_plastic.mat") + " -o " + dir +
               "/r.matpkg --emit-source " + dir + "/src");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* suffix :
       {"vert.es300.glsl", "frag.es300.glsl", "vert.es300.readable.glsl", "frag.es300.readable.glsl",
        "vert.vulkan.glsl", "frag.vulkan.glsl", "vert.spvasm", "frag.spvasm", "vert.metal", "frag.metal"})
    EXPECT_TRUE(fs::exists(dir + "/src/red_plastic.high.dir1." + suffix)) << suffix;
  // The GLSL ES and MSL files are the shipped bytes, which the shader goldens
  // (tests/golden/shaders, scripts/update-goldens.sh) copy and present as such.
  for (const auto& [suffix, stage, target] : {std::array<std::string, 3>{"vert.es300.glsl", "vertex", "glsl_es_300"},
                                              {"frag.es300.glsl", "fragment", "glsl_es_300"},
                                              {"vert.metal", "vertex", "msl"},
                                              {"frag.metal", "fragment", "msl"}}) {
    auto shipped =
        run(kMatc + " info " + dir + "/r.matpkg --variant high.dir1 --stage " + stage + " --target " + target);
    ASSERT_EQ(shipped.exitCode, 0) << shipped.err;
    EXPECT_TRUE(shipped.out == facet::test::readText(dir + "/src/red_plastic.high.dir1." + suffix))
        << suffix << " is not the package's " << stage << " " << target << " shader";
  }
}

TEST(MatcCli, OneAndTwoJobsWriteTheSameBytes) {
  std::string dir = facet::test::scratchDir("cli-jobs");
  std::string mat = facet::test::examplePath("materials/banded_ceramic.mat");
  ASSERT_EQ(run(kMatc + " compile " + mat + " -j 1 -o " + dir + "/one.matpkg").exitCode, 0);
  ASSERT_EQ(run(kMatc + " compile " + mat + " -j 2 -o " + dir + "/two.matpkg").exitCode, 0);
  EXPECT_EQ(facet::test::readText(dir + "/one.matpkg"), facet::test::readText(dir + "/two.matpkg"));
  EXPECT_EQ(run(kMatc + " compile " + mat + " -j 0").exitCode, 2);
}

// Ninja/Make rebuild a package when its material or a template/chunk its variants used changes.
TEST(MatcCli, DepfileListsTheMaterialAndTheChunksItsVariantsUsed) {
  std::string dir = facet::test::scratchDir("cli-depfile");
  std::string mat = facet::test::examplePath("materials/red_plastic.mat");
  auto r = run(kMatc + " compile " + mat + " --tiers low -o '" + dir + "/my pkg.matpkg' --depfile " + dir + "/pkg.d");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::string depfile = facet::test::readText(dir + "/pkg.d");
  EXPECT_EQ(depfile.rfind(dir + "/my\\ pkg.matpkg: \\\n", 0), 0u) << depfile;
  for (const std::string& dep : {mat, facet::test::sourceDir() + "/chunks/specular_lut_lobe.glsl",
                                 facet::test::sourceDir() + "/templates/forward_lit.frag.glsl"})
    EXPECT_TRUE(depfile.find("  " + dep + " \\\n") != std::string::npos ||
                depfile.find("  " + dep + "\n") != std::string::npos)
        << dep << "\n"
        << depfile;
  EXPECT_EQ(depfile.find("specular_zioma_lobe.glsl"), std::string::npos) << "another tier's chunk\n" << depfile;
}

TEST(MatcCli, CacheOptionsSelectTheCacheAndNoCacheTouchesNone) {
  std::string dir = facet::test::scratchDir("cli-cache");
  std::string mat = facet::test::examplePath("materials/brushed_gold.mat");
  std::string compile = kMatc + " compile " + mat + " --tiers mid -o " + dir + "/g.matpkg";
  auto cold = run(compile + " --cache " + dir + "/cache");
  ASSERT_EQ(cold.exitCode, 0) << cold.err;
  EXPECT_EQ(cold.out.find("from the cache"), std::string::npos) << cold.out;
  auto warm = run(compile + " --cache " + dir + "/cache");
  ASSERT_EQ(warm.exitCode, 0) << warm.err;
  EXPECT_NE(warm.out.find("(2 from the cache)"), std::string::npos) << warm.out;
  auto none = run(compile + " --no-cache");
  EXPECT_EQ(none.out.find("from the cache"), std::string::npos) << none.out;
  EXPECT_EQ(run(compile + " --no-cache --cache " + dir).exitCode, 2);
}

// `--cache .` or `--cache ~/work` must not make the cache's trimming delete the user's files:
// a folder that is not the cache's own is refused (exit 2) and left as it was, and so is a regular
// file. The default cache only speeds builds up: when it is unusable the build goes on without it.
TEST(MatcCli, CacheRefusesAFolderOrFileThatIsNotItsOwn) {
  const std::string dir = facet::test::scratchDir("cli-cache-foreign");
  const std::string mat = facet::test::examplePath("materials/brushed_gold.mat");
  // A bound of 1 MiB that the user's 2 MiB file alone exceeds: trimming such a folder used to
  // delete it (oldest first), and the stale-looking temporary name under any bound.
  const std::string compile = kMatc + " compile " + mat + " --tiers mid -o " + dir + "/g.matpkg --cache-max-size 1";
  fs::create_directories(dir + "/work");
  const std::string big(2 << 20, 'm');
  const std::vector<std::string> theirs = {write(dir, "work/notes.txt", "mine"), write(dir, "work/old.tmp.1", "mine"),
                                           write(dir, "work/big.dat", big)};
  for (const std::string& f : theirs) fs::last_write_time(f, fs::file_time_type::clock::now() - std::chrono::hours(2));
  auto r = run(compile + " --cache " + dir + "/work");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("matc: error: --cache: '" + dir + "/work' is not a variant cache"), std::string::npos) << r.err;
  r = run(compile + " --cache " + theirs[0]);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("is not a folder"), std::string::npos) << r.err;
  for (const std::string& f : theirs)
    EXPECT_TRUE(fs::exists(f) && facet::test::readText(f) == (f == theirs[2] ? big : "mine")) << f;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir + "/work"), fs::directory_iterator()), 3);
  EXPECT_FALSE(fs::exists(dir + "/g.matpkg"));

  fs::create_directories(dir + "/xdg/facet");
  write(dir, "xdg/facet/matc", "not a folder");
  r = run("XDG_CACHE_HOME=" + dir + "/xdg " + compile);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("matc: warning: building without the variant cache"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/g.matpkg"));
}

// Without a terminal (as here: a pipe) compile prints no progress line; info --json is one JSON
// document with what the text summary shows.
TEST(MatcCli, CompileIsQuietOnAPipeAndInfoJsonDescribesThePackage) {
  std::string dir = facet::test::scratchDir("cli-json");
  auto c = run(kMatc + " compile " + facet::test::examplePath("materials/red_plastic.mat") + " --no-cache -o " + dir +
               "/r.matpkg");
  ASSERT_EQ(c.exitCode, 0) << c.err;
  EXPECT_EQ(c.err, "");
  auto r = run(kMatc + " info " + dir + "/r.matpkg --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["material"], "red_plastic");
  EXPECT_EQ(doc["format"], "1.6");                 // 1.6: shaders read per-instance transforms
  EXPECT_EQ(doc["preshadedBlockSize"], 80);        // 32 bytes of parameters, 48 of derived inputs
  ASSERT_EQ(doc["preshaderPrograms"].size(), 1u);  // every tier is linear: one program
  EXPECT_EQ(doc["preshaderPrograms"][0]["variants"].size(), 8u);
  ASSERT_EQ(doc["variants"].size(), 8u);
  EXPECT_EQ(doc["variants"][3]["key"], "high.dir1");
  EXPECT_EQ(doc["variants"][3]["shaders"].size(), 6u);
  uint64_t stored = doc["dictionaryStoredBytes"];
  for (const auto& v : doc["variants"])
    for (const auto& s : v["shaders"]) stored += s["storedBytes"].get<uint64_t>();
  for (const auto& t : doc["textures"]) stored += t["storedBytes"].get<uint64_t>();
  EXPECT_LT(stored, fs::file_size(dir + "/r.matpkg"));
  EXPECT_EQ(doc["parameters"][1]["name"], "roughness");
  EXPECT_EQ(doc["textures"][0]["variants"][0], "low.dir1");
}

// info --json carries the text summary's static cost table: per variant and stage, the same
// figures in the same order, under the cost model's names (compiler/cost_figures.h), each the
// table's cell once printed as the table prints it. tools/mesa_stats reads them from here.
TEST(MatcCli, InfoJsonCarriesTheCostTable) {
  std::string dir = facet::test::scratchDir("cli-json-costs");
  ASSERT_EQ(run(kMatc + " compile " + facet::test::examplePath("materials/red_plastic.mat") + " --no-cache -o " + dir +
                "/r.matpkg")
                .exitCode,
            0);
  auto text = run(kMatc + " info " + dir + "/r.matpkg");
  auto json = run(kMatc + " info " + dir + "/r.matpkg --json");
  ASSERT_EQ(text.exitCode, 0) << text.err;
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(json.out);
  auto words = [](const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
  };
  std::istringstream lines(text.out.substr(text.out.find("\nstatic cost")));
  std::string line;
  while (std::getline(lines, line) && line.rfind("  variant ", 0) != 0) {
  }
  const std::vector<std::string> headings = words(line);
  ASSERT_GT(headings.size(), 2u) << text.out;
  size_t rows = 0;
  while (std::getline(lines, line) && line.rfind("  ", 0) == 0) {
    const std::vector<std::string> cells = words(line);
    ASSERT_EQ(cells.size(), headings.size()) << line;
    const auto variant = std::find_if(doc["variants"].begin(), doc["variants"].end(),
                                      [&](const auto& v) { return v["key"] == cells[0]; });
    ASSERT_NE(variant, doc["variants"].end()) << line;
    ASSERT_TRUE(variant->contains("costs") && (*variant)["costs"].contains(cells[1])) << line;
    const nlohmann::ordered_json& costs = (*variant)["costs"][cells[1]];
    ASSERT_EQ(costs.size(), headings.size() - 2) << line;
    size_t column = 2;
    for (const auto& [name, value] : costs.items()) {
      const facet::compiler::CostFigure* figure = facet::compiler::findCostFigure(name);
      ASSERT_NE(figure, nullptr) << name;
      EXPECT_EQ(figure->column, headings[column]) << name;
      EXPECT_EQ(facet::compiler::formatFigure(*figure, value.get<double>()), cells[column]) << line << " " << name;
      EXPECT_EQ(value.is_number_integer(), figure->integer) << name;
      ++column;
    }
    ++rows;
  }
  EXPECT_EQ(rows, 16u);  // 8 variants, a vertex and a fragment stage each
}

// The Metal slots recorded in the package (section MSLB) are shown in text and JSON, are the shader
// ABI's, and are the ones every variant's MSL declares (painted_tiles: blocks, frame and
// material samplers; the low tier adds the specular LUT).
TEST(MatcCli, InfoShowsTheMslSlotsTheShadersDeclare) {
  std::string dir = facet::test::scratchDir("cli-msl-slots");
  const std::string package = dir + "/p.matpkg";
  ASSERT_EQ(
      run(kMatc + " compile " + facet::test::examplePath("materials/painted_tiles.mat") + " -o " + package).exitCode,
      0);
  auto text = run(kMatc + " info " + package);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  const size_t environmentLine = text.out.find("\n  facet_environment ");
  ASSERT_NE(environmentLine, std::string::npos) << text.out;
  const std::string line =
      text.out.substr(environmentLine + 1, text.out.find('\n', environmentLine + 1) - environmentLine - 1);
  const std::string environmentSlot =
      "texture(" + std::to_string(facet::abi::mslTextureIndex(facet::abi::kEnvironmentBinding)) + ")";
  EXPECT_NE(line.find(environmentSlot), std::string::npos) << line;
  EXPECT_NE(line.find("Vulkan set 1 binding " + std::to_string(facet::abi::kEnvironmentBinding)), std::string::npos)
      << line;

  auto json = run(kMatc + " info " + package + " --json");
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const nlohmann::json doc = nlohmann::json::parse(json.out);
  ASSERT_GE(doc["mslSlots"].size(), 6u);
  for (const std::string variant : {"high.dir1", "low.dir1"}) {
    auto msl = run(kMatc + " info " + package + " --variant " + variant + " --stage fragment --target msl");
    ASSERT_EQ(msl.exitCode, 0) << msl.err;
    size_t declared = 0;
    for (const auto& slot : doc["mslSlots"]) {
      const std::string name = slot["name"], index = std::to_string(slot["index"].get<uint32_t>());
      if (slot["kind"] == "buffer") {
        const std::regex pattern(name + R"(& \w+ \[\[buffer\((\d+)\)\]\])");
        std::smatch match;
        if (!std::regex_search(msl.out, match, pattern)) continue;  // a block this stage does not read
        EXPECT_EQ(match[1].str(), index) << variant << " " << name;
      } else {
        if (msl.out.find(" " + name + " [[texture(") == std::string::npos) continue;
        EXPECT_NE(msl.out.find(" " + name + " [[texture(" + index + ")]]"), std::string::npos)
            << variant << " " << name;
        EXPECT_NE(msl.out.find(" " + name + "Smplr [[sampler(" + index + ")]]"), std::string::npos)
            << variant << " " << name;
      }
      ++declared;
    }
    EXPECT_GE(declared, 5u) << variant;  // frame and material blocks, the environment, both material textures
  }
}

// On a terminal (util-linux `script` gives matc a pseudo-terminal) the progress line counts the
// variants and is erased before the result line.
TEST(MatcCli, CompileDrawsAProgressLineOnATerminal) {
  std::string dir = facet::test::scratchDir("cli-progress");
  std::string compile = kMatc + " compile " + facet::test::examplePath("materials/red_plastic.mat") +
                        " --no-cache -o " + dir + "/r.matpkg";
  auto r = run("script -qec '" + compile + "' /dev/null");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("\rred_plastic: compiling variants 8/8\r\033[K"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("red_plastic: 8 variants,"), std::string::npos) << r.out;
}

TEST(MatcCli, MalformedMaterialExitsOneWithLocatedErrorAndNoOutput) {
  std::string dir = facet::test::scratchDir("cli-bad");
  std::string mat = write(dir, "bad.mat", "material bad {\n  surface {\n    roughness = 0.5 +\n  }\n}\n");
  auto r = run(kMatc + " compile " + mat + " -o " + dir + "/bad.matpkg");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(mat + ":4:3: error: expected an expression, found '}'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1 error generated."), std::string::npos) << r.err;
  for (const auto& entry : fs::directory_iterator(dir)) EXPECT_EQ(entry.path().filename(), "bad.mat");
}

TEST(MatcCli, MissingInputExitsOne) {
  auto r = run(kMatc + " compile /nonexistent/x.mat");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("cannot read '/nonexistent/x.mat': no such file"), std::string::npos) << r.err;
}

TEST(MatcCli, UsageErrorsExitTwo) {
  EXPECT_EQ(run(kMatc).exitCode, 2);
  EXPECT_EQ(run(kMatc + " compile").exitCode, 2);
  EXPECT_EQ(run(kMatc + " compile a.mat --no-such-flag").exitCode, 2);
  EXPECT_EQ(run(kMatc + " info x.matpkg --variant high.dir1").exitCode, 2);
}

TEST(MatcCli, CorruptPackageIsRejectedWithAnError) {
  std::string dir = facet::test::scratchDir("cli-corrupt");
  ASSERT_EQ(
      run(kMatc + " compile " + facet::test::examplePath("materials/red_plastic.mat") + " -o " + dir + "/r.matpkg")
          .exitCode,
      0);
  fs::resize_file(dir + "/r.matpkg", fs::file_size(dir + "/r.matpkg") / 2);
  auto r = run(kMatc + " info " + dir + "/r.matpkg");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(dir + "/r.matpkg: error: "), std::string::npos) << r.err;

  write(dir, "garbage.matpkg", std::string(1000, '\x7f'));
  r = run(kMatc + " info " + dir + "/garbage.matpkg");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err;
}

// matc info runs the checks the runtime runs on load (LoadedMaterial: the meaning, every variant's
// SPIR-V and interface), so a package an app would refuse exits 1 with the runtime's reason
// after info has printed what the package holds. It used to exit 0, silently.
TEST(MatcCli, InfoExitsOneOnPackagesTheRuntimeRefuses) {
  namespace pkg = facet::package;
  std::string dir = facet::test::scratchDir("cli-refused");
  ASSERT_EQ(
      run(kMatc + " compile " + facet::test::examplePath("materials/red_plastic.mat") + " -o " + dir + "/r.matpkg")
          .exitCode,
      0);
  const pkg::ReadResult good = pkg::readFile(dir + "/r.matpkg");
  ASSERT_TRUE(good.package) << good.error;
  struct Case {
    std::function<void(pkg::Package&)> edit;
    std::string why;
  };
  const Case cases[] = {
      {[](pkg::Package& p) { p.material.paramBlockSize = 4097; },
       "the parameter block is 4097 bytes; the limit is 4096"},
      {[](pkg::Package& p) { p.material.params[1].defaultValue[0] = std::nan(""); },
       "parameter 'roughness': its default is not a finite number"},
      {[](pkg::Package& p) {
         for (pkg::PreshaderOp& op : p.preshader.programs[0].ops)
           if (op.code == pkg::PreshaderOpcode::Store) op.offset = p.preshader.blockSize;
       },
       "preshader program 0: preshader op"},
      {[](pkg::Package& p) {
         for (pkg::Shader& s : p.variants[2].shaders)
           if (s.target == pkg::Target::Spirv)
             s.stage = s.stage == pkg::Stage::Vertex ? pkg::Stage::Fragment : pkg::Stage::Vertex;
       },
       "material 'red_plastic' variant high.dir0: the fragment shader (SPIR-V) is a vertex shader"},
  };
  for (const Case& c : cases) {
    pkg::Package p = *good.package;
    c.edit(p);
    std::string error;
    ASSERT_TRUE(pkg::writeFile(dir + "/bad.matpkg", pkg::write(p), &error)) << error;
    for (const char* mode : {"", " --json"}) {
      auto r = run(kMatc + " info " + dir + "/bad.matpkg" + mode);
      EXPECT_EQ(r.exitCode, 1) << c.why << mode;
      EXPECT_NE(r.err.find(dir + "/bad.matpkg: error: the runtime refuses this package: " + c.why), std::string::npos)
          << r.err;
      EXPECT_NE(r.out.find("red_plastic"), std::string::npos) << "what the package holds is still printed";
    }
  }
  EXPECT_EQ(run(kMatc + " info " + dir + "/r.matpkg").exitCode, 0);
}

TEST(MatcCli, SceneManifestBuildsOnlyTheVariantsItNeeds) {
  std::string dir = facet::test::scratchDir("cli-scene");
  std::string scene = facet::test::examplePath("scenes/sphere.json");
  auto r = run(kMatc + " compile " + facet::test::examplePath("materials/red_plastic.mat") + " -o " + dir +
               "/r.matpkg --scene " + scene);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("red_plastic: 1 variant for scene " + scene + " (8 without it)"), std::string::npos) << r.out;
  auto info = run(kMatc + " info " + dir + "/r.matpkg");
  EXPECT_NE(info.out.find("variants   1\n  high.dir1\n"), std::string::npos) << info.out;

  auto unused = run(kMatc + " compile " + facet::test::examplePath("materials/brushed_gold.mat") + " -o " + dir +
                    "/g.matpkg --scene " + scene);
  EXPECT_EQ(unused.exitCode, 1);
  EXPECT_NE(unused.err.find("no object of the scene uses material 'brushed_gold'"), std::string::npos) << unused.err;
  EXPECT_FALSE(fs::exists(dir + "/g.matpkg"));
}

// A scene of built-in meshes with rotations and scales (the yard) is a manifest like any other:
// each material it names is built with the variants it asks for (its sun casts: the receiver of
// four cascades and the depth-only program), and info --scene finds them.
TEST(MatcCli, SceneOfBuiltInMeshesIsAManifest) {
  std::string dir = facet::test::scratchDir("cli-yard");
  std::string scene = facet::test::examplePath("scenes/yard.json");
  for (const char* name : {"red_plastic", "brushed_gold", "banded_ceramic"}) {
    const std::string package = dir + "/" + name + ".matpkg";
    auto r = run(kMatc + " compile " + facet::test::examplePath("materials/" + std::string(name) + ".mat") + " -o " +
                 package + " --scene " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find(std::string(name) + ": 2 variants for scene " + scene), std::string::npos) << r.out;
    auto info = run(kMatc + " info " + package + " --scene " + scene);
    EXPECT_EQ(info.exitCode, 0) << info.err;
    for (const char* key : {"high.dir1.sh4", "high.depth"}) {
      EXPECT_NE(info.out.find(std::string("asks for ") + key + "; the package has 2 variants, including it"),
                std::string::npos)
          << info.out;
    }
  }
}

// A scene with point lights asks for a .pt variant: a default build lacks it (info --scene says
// so, exit 1), --point-lights or --scene builds it.
TEST(MatcCli, PointLightVariantsAreBuiltOnRequestAndCheckedAgainstAScene) {
  std::string dir = facet::test::scratchDir("cli-lamps");
  std::string scene = facet::test::examplePath("scenes/lamps.json");
  std::string material = facet::test::examplePath("materials/red_plastic.mat");
  ASSERT_EQ(run(kMatc + " compile " + material + " -o " + dir + "/plain.matpkg").exitCode, 0);
  auto missing = run(kMatc + " info " + dir + "/plain.matpkg --scene " + scene);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.out.find("asks for high.dir0.pt2; the package has 8 variants\n"), std::string::npos) << missing.out;
  EXPECT_NE(missing.err.find("not built with high.dir0.pt2"), std::string::npos) << missing.err;

  auto built = run(kMatc + " compile " + material + " -o " + dir + "/lamps.matpkg --point-lights 0,2");
  ASSERT_EQ(built.exitCode, 0) << built.err;
  EXPECT_NE(built.out.find("16 variants"), std::string::npos) << built.out;
  auto found = run(kMatc + " info " + dir + "/lamps.matpkg --scene " + scene);
  EXPECT_EQ(found.exitCode, 0) << found.err;
  EXPECT_NE(found.out.find("the package has 16 variants, including it"), std::string::npos) << found.out;
  // Point lights read the lut tier's table too: a low variant lit by them alone ships it (it used
  // to be listed for variants with the sun only, and drew its point lights with an unbound table).
  auto summary = run(kMatc + " info " + dir + "/lamps.matpkg");
  EXPECT_EQ(summary.exitCode, 0) << summary.err;
  EXPECT_NE(summary.out.find("facet_specularLut r8_unorm 128x64, sampled by low.dir0.pt2, low.dir1, low.dir1.pt2,"),
            std::string::npos)
      << summary.out;

  EXPECT_EQ(run(kMatc + " compile " + material + " -o " + dir + "/bad.matpkg --point-lights 3").exitCode, 2);
  EXPECT_FALSE(fs::exists(dir + "/bad.matpkg"));
}

// A scene whose sun casts asks for receiver variants (.sh): none is built by default (today's
// output does not grow), --shadows or --scene builds them, and objects that do not receive keep the
// plain key, so such a scene asks for both.
TEST(MatcCli, ShadowReceiversAreBuiltOnlyWhenAskedFor) {
  std::string dir = facet::test::scratchDir("cli-shadows");
  std::string scene = write(dir, "yard.json", R"({"tier": "mid", "sun": {"castShadows": true},
      "shadows": {"cascades": 2}, "objects": [
      {"mesh": "plane", "material": "red_plastic", "scale": 10},
      {"mesh": "box", "material": "red_plastic", "position": [0, 1, 0], "receiveShadows": false}]})");
  std::string material = facet::test::examplePath("materials/red_plastic.mat");
  ASSERT_EQ(run(kMatc + " compile " + material + " -o " + dir + "/plain.matpkg").exitCode, 0);
  auto missing = run(kMatc + " info " + dir + "/plain.matpkg --scene " + scene);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.out.find("asks for mid.dir1; the package has 8 variants, including it\n"), std::string::npos)
      << missing.out;
  EXPECT_NE(missing.out.find("asks for mid.dir1.sh2; the package has 8 variants\n"), std::string::npos) << missing.out;
  // The casters' depth-only program (the shadow pass) is missing too.
  EXPECT_NE(missing.out.find("asks for mid.depth; the package has 8 variants\n"), std::string::npos) << missing.out;
  EXPECT_NE(missing.err.find("not built with mid.dir1.sh2, mid.depth"), std::string::npos) << missing.err;

  // 8 + 3 receivers and a depth-only program per tier.
  auto built = run(kMatc + " compile " + material + " -o " + dir + "/shadows.matpkg --shadows 0,1,2,4");
  ASSERT_EQ(built.exitCode, 0) << built.err;
  EXPECT_NE(built.out.find("24 variants"), std::string::npos) << built.out;
  auto listed = run(kMatc + " info " + dir + "/shadows.matpkg");
  EXPECT_NE(listed.out.find("\nformat     1.7\n"), std::string::npos) << listed.out;
  EXPECT_NE(listed.out.find("\ndepth      4 depth-only programs for the shadow pass (position only): reference.depth, "
                            "high.depth, mid.depth, low.depth\n"),
            std::string::npos)
      << listed.out;
  // The runtime's own checks accept the receivers' interface (block, compare sampler).
  auto found = run(kMatc + " info " + dir + "/shadows.matpkg --scene " + scene);
  EXPECT_EQ(found.exitCode, 0) << found.err;
  auto fragment =
      run(kMatc + " info " + dir + "/shadows.matpkg --variant low.dir1.sh4 --stage fragment --target glsl_es_300");
  ASSERT_EQ(fragment.exitCode, 0) << fragment.err;
  EXPECT_NE(fragment.out.find("uniform highp sampler2DShadow facet_shadowAtlas;"), std::string::npos) << fragment.out;
  auto plain = run(kMatc + " info " + dir + "/shadows.matpkg --variant low.dir1 --stage fragment --target glsl_es_300");
  EXPECT_EQ(plain.out.find("facet_shadowAtlas"), std::string::npos) << plain.out;

  auto forScene = run(kMatc + " compile " + material + " -o " + dir + "/scene.matpkg --scene " + scene);
  ASSERT_EQ(forScene.exitCode, 0) << forScene.err;
  EXPECT_NE(forScene.out.find("3 variants for scene " + scene + " (8 without it)"), std::string::npos) << forScene.out;
  EXPECT_EQ(run(kMatc + " info " + dir + "/scene.matpkg --scene " + scene).exitCode, 0);

  EXPECT_EQ(run(kMatc + " compile " + material + " -o " + dir + "/bad.matpkg --shadows 3").exitCode, 2);
  EXPECT_FALSE(fs::exists(dir + "/bad.matpkg"));
}

// The vertex-stage slope bias (docs/shadows.md, "Bias"): `<tier>.depth.slope` beside `<tier>.depth`
// with --vertex-slope-bias, in place of it for a scene whose slopeStage is "vertex"; info --scene
// names it, and a package without it fails the scene. The flag without a depth-only program to
// give it is a usage error.
TEST(MatcCli, VertexSlopeBiasProgramsAreBuiltOnlyWhenAskedFor) {
  std::string dir = facet::test::scratchDir("cli-vertex-slope");
  std::string scene = write(dir, "yard.json", R"({"tier": "low", "sun": {"castShadows": true},
      "shadows": {"cascades": 1, "slopeStage": "vertex"}, "objects": [
      {"mesh": "plane", "material": "red_plastic", "scale": 10},
      {"mesh": "box", "material": "red_plastic", "position": [0, 1, 0]}]})");
  std::string material = facet::test::examplePath("materials/red_plastic.mat");
  ASSERT_EQ(run(kMatc + " compile " + material + " -o " + dir + "/shadows.matpkg --shadows 0,1").exitCode, 0);
  auto missing = run(kMatc + " info " + dir + "/shadows.matpkg --scene " + scene);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("not built with low.depth.slope"), std::string::npos) << missing.err;

  auto built = run(kMatc + " compile " + material + " -o " + dir + "/slope.matpkg --shadows 0,1 --vertex-slope-bias");
  ASSERT_EQ(built.exitCode, 0) << built.err;
  // 8, a .sh1 receiver and the two depth-only programs per tier.
  EXPECT_NE(built.out.find("20 variants"), std::string::npos) << built.out;
  auto listed = run(kMatc + " info " + dir + "/slope.matpkg");
  EXPECT_NE(listed.out.find("\ndepth      8 depth-only programs for the shadow pass (position only; .depth.slope also "
                            "the normal, for the vertex-stage slope bias): reference.depth, reference.depth.slope, "),
            std::string::npos)
      << listed.out;
  auto found = run(kMatc + " info " + dir + "/slope.matpkg --scene " + scene);
  EXPECT_EQ(found.exitCode, 0) << found.err;
  EXPECT_NE(found.out.find("asks for low.depth.slope; the package has 20 variants, including it\n"), std::string::npos)
      << found.out;

  auto forScene = run(kMatc + " compile " + material + " -o " + dir + "/scene.matpkg --scene " + scene);
  ASSERT_EQ(forScene.exitCode, 0) << forScene.err;
  EXPECT_NE(forScene.out.find("2 variants for scene"), std::string::npos)
      << forScene.out;  // low.dir1.sh1, low.depth.slope
  auto sceneListed = run(kMatc + " info " + dir + "/scene.matpkg");
  EXPECT_NE(sceneListed.out.find("program for the shadow pass (position only; .depth.slope also the normal, for the "
                                 "vertex-stage slope bias): low.depth.slope\n"),
            std::string::npos)
      << sceneListed.out;

  auto usage = run(kMatc + " compile " + material + " -o " + dir + "/bad.matpkg --vertex-slope-bias");
  EXPECT_EQ(usage.exitCode, 2);
  EXPECT_NE(usage.err.find("--vertex-slope-bias: no depth-only program is built without --shadows"), std::string::npos)
      << usage.err;
  EXPECT_FALSE(fs::exists(dir + "/bad.matpkg"));
}

// The spot's receivers (docs/shadows.md, "Spot shadows"): `.sp1` twins of the point-light variants
// with --spot-shadows, exactly the scene's with --scene (an object that does not receive asks for
// the plain variant), and info --scene names them.
TEST(MatcCli, SpotShadowReceiversAreBuiltOnlyWhenAskedFor) {
  std::string dir = facet::test::scratchDir("cli-spot-shadows");
  std::string scene = write(dir, "spot.json", R"({"tier": "low", "lights": [
      {"type": "point", "position": [2, 2, 0]},
      {"type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0], "outerAngle": 40, "castShadows": true}],
      "objects": [
      {"mesh": "plane", "material": "red_plastic", "scale": 10},
      {"mesh": "box", "material": "red_plastic", "position": [0, 1, 0], "receiveShadows": false}]})");
  std::string material = facet::test::examplePath("materials/red_plastic.mat");
  ASSERT_EQ(run(kMatc + " compile " + material + " -o " + dir + "/points.matpkg --point-lights 0,2").exitCode, 0);
  auto missing = run(kMatc + " info " + dir + "/points.matpkg --scene " + scene);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("not built with low.dir0.pt2.sp1, low.depth"), std::string::npos) << missing.err;

  // 16 + dir0.pt2.sp1, dir1.pt2.sp1 and a depth-only program per tier.
  auto built = run(kMatc + " compile " + material + " -o " + dir + "/spot.matpkg --point-lights 0,2 --spot-shadows");
  ASSERT_EQ(built.exitCode, 0) << built.err;
  EXPECT_NE(built.out.find("28 variants"), std::string::npos) << built.out;
  auto found = run(kMatc + " info " + dir + "/spot.matpkg --scene " + scene);
  EXPECT_EQ(found.exitCode, 0) << found.err;
  EXPECT_NE(found.out.find("asks for low.dir0.pt2.sp1; the package has 28 variants, including it\n"), std::string::npos)
      << found.out;
  EXPECT_NE(found.out.find("asks for low.dir0.pt2; the package has 28 variants, including it\n"), std::string::npos)
      << found.out;
  auto fragment =
      run(kMatc + " info " + dir + "/spot.matpkg --variant low.dir0.pt2.sp1 --stage fragment --target glsl_es_300");
  ASSERT_EQ(fragment.exitCode, 0) << fragment.err;
  EXPECT_NE(fragment.out.find("uniform highp sampler2DShadow facet_shadowAtlas;"), std::string::npos) << fragment.out;
  EXPECT_NE(fragment.out.find("v_spotShadowPosition"), std::string::npos) << fragment.out;

  auto forScene = run(kMatc + " compile " + material + " -o " + dir + "/scene.matpkg --scene " + scene);
  ASSERT_EQ(forScene.exitCode, 0) << forScene.err;
  EXPECT_NE(forScene.out.find("3 variants for scene " + scene + " (8 without it)"), std::string::npos) << forScene.out;
  EXPECT_EQ(run(kMatc + " info " + dir + "/scene.matpkg --scene " + scene).exitCode, 0);
}

// matc lint builds receivers when asked (--shadows, as compile) and checks that their shadow
// coordinates stay highp (the shadow-precision rule, tests/lint/test_lint.cpp).
TEST(MatcCli, LintChecksShadowReceiversWhenAskedFor) {
  std::string material = facet::test::examplePath("materials/red_plastic.mat");
  auto r = run(kMatc + " lint " + material + " --tiers high,low --shadows 0,1,4 --format json");
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  for (const char* key : {"\"high.dir1\"", "\"high.dir1.sh1\"", "\"low.dir1.sh4\""})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << "\n" << r.out;
  EXPECT_EQ(r.out.find("shadow-precision"), std::string::npos) << r.out;
  r = run(kMatc + " lint " + material + " --tiers low --format json");
  EXPECT_EQ(r.out.find(".sh"), std::string::npos) << "no receivers unless asked for\n" << r.out;
  EXPECT_EQ(run(kMatc + " lint " + material + " --shadows 3").exitCode, 2);
}

TEST(MatcCli, TiersOptionSelectsTiersAndRejectsUnknownOnes) {
  std::string dir = facet::test::scratchDir("cli-tiers");
  std::string mat = facet::test::examplePath("materials/red_plastic.mat");
  auto r = run(kMatc + " compile " + mat + " -o " + dir + "/r.matpkg --tiers reference");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("red_plastic: 2 variants"), std::string::npos) << r.out;
  EXPECT_EQ(run(kMatc + " compile " + mat + " -o " + dir + "/r.matpkg --tiers ultra").exitCode, 2);

  // The low tier alone: its two variants, and the specular table they sample (dir1 only).
  r = run(kMatc + " compile " + mat + " -o " + dir + "/low.matpkg --tiers low");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("red_plastic: 2 variants"), std::string::npos) << r.out;
  auto info = run(kMatc + " info " + dir + "/low.matpkg");
  EXPECT_NE(info.out.find("variants   2\n  low.dir0\n"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("textures   1\n  facet_specularLut r8_unorm 128x64, sampled by low.dir1, 8192 bytes ("),
            std::string::npos)
      << info.out;
}

// matc lint as CI runs it: exit 0 on clean materials, 1 on an error (or on a warning with
// --werror), 2 on a usage error; the baseline is written, then holds.
TEST(MatcCli, LintExitCodesAndBaselineRoundTrip) {
  std::string dir = facet::test::scratchDir("cli-lint");
  std::string hazards = facet::test::sourceDir() + "/tests/data/lint/hazards.mat";
  auto r = run(kMatc + " lint " + hazards + " --tiers high");
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("hazards.mat:10:21: error: sqrt of a value that is always negative [-2, -1] is NaN [domain]"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("[fp16-constant]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hazards.mat:14:18: warning: output 'normal' can be shorter than 2^-7 (its squared length is in "
                       "[0, 1]): in fp16 its squared length flushes to 0 and normalize gives NaN (0 · inf) "
                       "[direction-length]\n            normal = vec3(0.0, 0.0, params.roughness)\n"
                       "                     ^~~~\n"),
            std::string::npos)
      << r.out;

  std::string warnOnly =
      write(dir, "warn.mat",
            "material warn {\n    param gain: float = 2.0\n    surface {\n        roughness = params.gain\n    }\n}\n");
  EXPECT_EQ(run(kMatc + " lint " + warnOnly + " --tiers high").exitCode, 0);
  r = run(kMatc + " lint " + warnOnly + " --tiers high --werror");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.out.find("warn.mat:2:11: warning: parameter 'gain' has no range"), std::string::npos) << r.out;

  EXPECT_EQ(run(kMatc + " lint " + warnOnly + " --update-baseline").exitCode, 2);
  std::string red = facet::test::examplePath("materials/red_plastic.mat");
  std::string baseline = dir + "/baseline.json";
  EXPECT_EQ(run(kMatc + " lint " + red + " --baseline " + baseline).exitCode, 1) << "a missing baseline is an error";
  ASSERT_EQ(run(kMatc + " lint " + red + " --baseline " + baseline + " --update-baseline").exitCode, 0);
  r = run(kMatc + " lint " + red + " --baseline " + baseline + " --werror --format json");
  EXPECT_EQ(r.exitCode, 0) << r.out;
  EXPECT_NE(r.out.find("\"errors\": 0"), std::string::npos) << r.out;
}

// --tolerance nan used to pass the range check and switch every baseline comparison off (no
// comparison with NaN is true): a tolerance must be a finite number in [0, 1000].
TEST(MatcCli, LintToleranceMustBeAFiniteNumberInRange) {
  const std::string dir = facet::test::scratchDir("cli-lint-tolerance");
  const std::string red = facet::test::examplePath("materials/red_plastic.mat");
  const std::string lint = kMatc + " lint " + red + " --baseline " + dir + "/b.json --tiers low";
  ASSERT_EQ(run(lint + " --update-baseline").exitCode, 0);
  // A baseline whose figures are all far below today's: every comparison fails.
  std::string baseline = facet::test::readText(dir + "/b.json");
  baseline = std::regex_replace(baseline, std::regex(": [0-9.]+"), ": 0.001");
  write(dir, "b.json", baseline);
  EXPECT_EQ(run(lint).exitCode, 1);
  for (const char* tolerance : {"nan", "NaN", "-nan", "inf", "-1", "1e999", "1001"}) {
    auto r = run(lint + " --tolerance " + tolerance);
    EXPECT_EQ(r.exitCode, 2) << tolerance << "\n" << r.out;
    EXPECT_NE(r.err.find("--tolerance: Value " + std::string(tolerance) + " is not a number in [0, 1000]"),
              std::string::npos)
        << r.err;
  }
  EXPECT_EQ(run(lint + " --tolerance 1000").exitCode, 1) << "still far past a 1000 % tolerance";
}

// The output never replaces the material it was compiled from, nor a device node.
TEST(MatcCli, CompileRefusesToOverwriteItsInputOrADevice) {
  std::string dir = facet::test::scratchDir("cli-overwrite");
  std::string text = facet::test::readText(facet::test::examplePath("materials/red_plastic.mat"));
  std::string mat = write(dir, "red.mat", text);
  auto r = run(kMatc + " compile " + mat + " -o " + mat);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("the output '" + mat + "' (-o) is the input material '" + mat + "'"), std::string::npos)
      << r.err;
  EXPECT_EQ(facet::test::readText(mat), text);
  std::string pkgNamed = write(dir, "odd.matpkg", text);  // default output = input with .matpkg
  EXPECT_EQ(run(kMatc + " compile " + pkgNamed).exitCode, 1);
  EXPECT_EQ(facet::test::readText(pkgNamed), text);
  r = run(kMatc + " compile " + mat + " -o /dev/null");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("cannot write '/dev/null': it exists and is not a regular file"), std::string::npos) << r.err;
}

// One rule for every file every command writes: an output is never an input and never another
// output, whatever path names it (another spelling, a symbolic link, a hard link, a file that
// does not exist yet). The error names both arguments, exits 1 and changes no file.
TEST(MatcCli, NoCommandWritesOverItsInputsOrWritesOneFileTwice) {
  const std::string dir = facet::test::scratchDir("cli-clash");
  const std::string text = facet::test::readText(facet::test::examplePath("materials/red_plastic.mat"));
  const std::string mat = write(dir, "red.mat", text);
  fs::create_symlink(mat, dir + "/link.mat");
  fs::create_hard_link(mat, dir + "/hard.mat");
  const std::string config = write(dir, "budgets.json", R"({"tiers": {}})");
  const std::string scene = write(dir, "scene.json", "{}");
  fs::create_directories(dir + "/real");
  fs::create_symlink(dir + "/real", dir + "/alias");
  fs::create_directories(dir + "/src");
  const std::string emitted =
      write(dir, "src/red_plastic.low.dir0.frag.metal", text);  // a material named as an emitted file
  fs::create_directories(dir + "/out");
  const std::string report = write(dir, "out/report.json", "{}");
  const std::string post = dir + "/post";
  fs::create_directories(post);
  const std::string postCpp = write(dir, "post/post.aces.vert.metal", "keep");

  // --tiers last: a list option would take the material as one more tier.
  auto compile = [](const std::string& args) { return kMatc + " compile " + args + " --no-cache --tiers low"; };
  auto lint = [](const std::string& args) { return kMatc + " lint " + args + " --tiers low"; };
  struct Clash {
    std::string command, first, second;  // the two arguments the message must name
  };
  const std::vector<Clash> clashes = {
      {compile(mat + " --depfile " + mat), "(--depfile) is the input material", ""},
      {compile(mat + " -o " + dir + "/link.mat"), "(-o) is the input material", ""},
      {compile(mat + " -o " + dir + "/hard.mat"), "(-o) is the input material", ""},
      {compile(mat + " -o " + dir + "/p.matpkg --depfile " + dir + "/./p.matpkg"), "(-o) and '",
       "(--depfile) are the same file"},
      {compile(mat + " -o " + dir + "/alias/p.matpkg --depfile " + dir + "/real/p.matpkg"), "(-o) and '",
       "(--depfile)"},
      {compile(mat + " --scene " + scene + " -o " + scene), "(-o) is the --scene file", ""},
      {compile(emitted + " -o " + dir + "/e.matpkg --emit-source " + dir + "/src"),
       "(--emit-source) is the input material", ""},
      {lint(mat + " -o " + mat), "(-o) is the input material", ""},
      {lint(dir + " -o " + mat), "(-o) is the input material", ""},  // a folder stands for its .mat files
      {lint(mat + " --config " + config + " -o " + config), "(-o) is the --config file", ""},
      {lint(mat + " --baseline " + config + " -o " + config), "(-o) is the --baseline file", ""},
      {lint(mat + " --baseline " + dir + "/new.json --update-baseline -o " + dir + "/new.json"), "(-o) and '",
       "(--baseline with --update-baseline) are the same file"},
      {kMatc + " eval " + mat + " --scene " + report + " --out " + dir + "/out", "(--out) is the --scene file", ""},
      {kMatc + " eval " + write(dir, "out/report.md", text) + " --out " + dir + "/out", "(--out) is the input material",
       ""},
      {kMatc + " post --emit-source " + post + " --cpp " + postCpp, "(--emit-source) and '",
       "(--cpp) are the same file"},
  };
  for (const Clash& c : clashes) {
    auto r = run(c.command);
    EXPECT_EQ(r.exitCode, 1) << c.command << "\n" << r.err;
    EXPECT_NE(r.err.find(c.first), std::string::npos) << c.command << "\n" << r.err;
    EXPECT_NE(r.err.find(c.second), std::string::npos) << c.command << "\n" << r.err;
  }
  for (const std::string& kept : {mat, emitted, dir + "/out/report.md"})
    EXPECT_EQ(facet::test::readText(kept), text) << kept;
  EXPECT_EQ(facet::test::readText(config), R"({"tiers": {}})");
  EXPECT_EQ(facet::test::readText(scene), "{}");
  EXPECT_EQ(facet::test::readText(report), "{}");
  EXPECT_EQ(facet::test::readText(postCpp), "keep");
  for (const char* absent : {"p.matpkg", "real/p.matpkg", "e.matpkg", "new.json", "out/plot.svg"})
    EXPECT_FALSE(fs::exists(dir + "/" + absent)) << absent;
}

// The outputs of one command land together: when one cannot be written, none is replaced.
TEST(MatcCli, AnOutputThatCannotBeWrittenLeavesTheOthersUnchanged) {
  const std::string dir = facet::test::scratchDir("cli-together");
  const std::string mat = facet::test::examplePath("materials/red_plastic.mat");
  const std::string package = write(dir, "red.matpkg", "old package");
  auto r = run(kMatc + " compile " + mat + " --no-cache --tiers low -o " + package + " --depfile " + dir +
               "/no-such-folder/red.d");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("cannot write '" + dir + "/no-such-folder/red.d'"), std::string::npos) << r.err;
  EXPECT_EQ(facet::test::readText(package), "old package");
  r = run(kMatc + " compile " + mat + " --no-cache --tiers low -o " + package + " --emit-source " + dir +
          "/src --depfile " + dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(facet::test::readText(package), "old package");
  EXPECT_TRUE(fs::is_empty(dir + "/src"));

  const std::string report = write(dir, "report.txt", "old report");
  r = run(kMatc + " lint " + mat + " --tiers low -o " + report + " --baseline " + dir +
          "/no-such-folder/b.json --update-baseline");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(facet::test::readText(report), "old report");
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"red.matpkg", "report.txt", "src"})) << "no temporary file is left";
}

// matc eval (docs/eval.md): the report on success; the compiler's diagnostics for a bad material
// and a clear error without a Vulkan device, exit 1; usage errors exit 2.
TEST(MatcCli, EvalWritesItsReportOrFailsClearly) {
  std::string dir = facet::test::scratchDir("cli-eval");
  const std::string red = facet::test::examplePath("materials/red_plastic.mat");
  const std::string tiny = " --tiers high --no-swaps --sphere-pixels 16 --frames 1 --out " + dir + "/out";
  // In the sanitizer build, LeakSanitizer would report lavapipe's per-load bytes at matc's exit
  // (keep_vulkan_driver_loaded.cpp explains them; it is linked into tests, not into matc), so
  // leak checking is off for this one process. test_eval runs the same code in-process with it on.
  auto r = run("ASAN_OPTIONS=detect_leaks=0 " + kMatc + " eval " + red + tiny);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("[1/2] reference"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("red_plastic: 2 configurations -> " + dir + "/out/report.md"), std::string::npos) << r.out;
  for (const char* file :
       {"report.md", "report.json", "plot.svg", "images/high.frontal.png", "images/reference.grazing.png"})
    EXPECT_TRUE(fs::exists(dir + "/out/" + file)) << file;

  auto missing = run(kMatc + " eval " + dir + "/nope.mat" + tiny);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("matc: error: cannot read"), std::string::npos) << missing.err;
  auto bad =
      run(kMatc + " eval " + write(dir, "bad.mat", "material bad { surface { roughness = params.nope } }") + tiny);
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("bad.mat:1:"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("error: unknown parameter 'nope'"), std::string::npos) << bad.err;
  // No Vulkan driver: the loader finds no ICD.
  auto noDevice = run("VK_ICD_FILENAMES=" + dir + "/no-such-icd.json " + kMatc + " eval " + red + tiny);
  EXPECT_EQ(noDevice.exitCode, 1);
  EXPECT_NE(noDevice.err.find("matc: error: no Vulkan device to render on"), std::string::npos) << noDevice.err;
  EXPECT_EQ(run(kMatc + " eval " + red + " --frames -1").exitCode, 2);
  EXPECT_EQ(run(kMatc + " eval").exitCode, 2);
}

// matc links no renderer: `matc eval` runs facet-eval, the one beside matc's own executable, else
// PATH's, and says where it looked when there is neither (exit 1). Run by matc, facet-eval's usage
// and messages are matc's; run on its own, its own.
TEST(MatcCli, EvalRunsFacetEvalBesideMatcOrOnPath) {
  const std::string dir = fs::canonical(facet::test::scratchDir("cli-eval-program")).string();
  const std::string alone = dir + "/matc";  // a matc with no facet-eval beside it
  fs::copy_file(kMatc, alone);
  const std::string built = fs::path(kMatc).parent_path().string();  // where the build put both
  const std::string red = facet::test::examplePath("materials/red_plastic.mat");

  auto absent = run("PATH=/usr/bin:/bin " + alone + " eval " + red);
  EXPECT_EQ(absent.exitCode, 1);
  EXPECT_NE(absent.err.find("matc: error: matc eval runs facet-eval, which is neither beside matc (" + dir +
                            "/facet-eval) nor on PATH"),
            std::string::npos)
      << absent.err;

  auto onPath = run("PATH=" + built + ":/usr/bin:/bin " + alone + " eval --help");
  EXPECT_EQ(onPath.exitCode, 0) << onPath.err;
  EXPECT_NE(onPath.out.find("Usage: " + alone + " eval [OPTIONS] input"), std::string::npos) << onPath.out;
  EXPECT_NE(onPath.out.find("--sphere-pixels"), std::string::npos) << onPath.out;
  auto usage = run("PATH=" + built + ":/usr/bin:/bin " + alone + " eval " + red + " --tiers ultra");
  EXPECT_EQ(usage.exitCode, 2);
  EXPECT_NE(usage.err.find("matc: error: unknown tier 'ultra'"), std::string::npos) << usage.err;

  auto beside = run(kMatc + " eval " + dir + "/nope.mat");
  EXPECT_EQ(beside.exitCode, 1);
  EXPECT_NE(beside.err.find("matc: error: cannot read '" + dir + "/nope.mat'"), std::string::npos) << beside.err;
  auto itself = run(built + "/facet-eval " + dir + "/nope.mat");
  EXPECT_EQ(itself.exitCode, 1);
  EXPECT_NE(itself.err.find("facet-eval: error: cannot read '" + dir + "/nope.mat'"), std::string::npos) << itself.err;
}

namespace {

// Each committed tuning file is gated by its own test, so that a newly tuned example is gated
// without a change here and one render's time is one test's.
class CommittedTuning : public testing::TestWithParam<std::string> {};

}  // namespace

TEST(MatcCli, EveryTunedExampleIsGated) {
  const std::vector<std::string> tuned = facet::test::exampleTunedMaterials();
  for (const char* name : {"red_plastic", "brushed_gold", "velvet", "car_paint", "brushed_metal", "satin_plastic",
                           "hammered_floor", "banded_ceramic", "painted_tiles"})
    EXPECT_NE(std::find(tuned.begin(), tuned.end(), name), tuned.end()) << name;
}

// The committed choices still meet the budgets (ASAN_OPTIONS: see EvalWritesItsReportOrFailsClearly).
TEST_P(CommittedTuning, StillMeetsItsBudgets) {
  auto gate = run("ASAN_OPTIONS=detect_leaks=0 " + kMatc + " tune " +
                  facet::test::examplePath("materials/" + GetParam() + ".mat") + " --budgets " +
                  facet::test::examplePath("lint/tune_budgets.json") + " --check");
  EXPECT_EQ(gate.exitCode, 0) << GetParam() << ": " << gate.err;
  EXPECT_NE(gate.out.find("high: "), std::string::npos) << gate.out;
}

INSTANTIATE_TEST_SUITE_P(Examples, CommittedTuning, testing::ValuesIn(facet::test::exampleTunedMaterials()),
                         [](const testing::TestParamInfo<std::string>& param) { return param.param; });

// matc tune compiles lavapipe's pipelines without LLVM's optimisation passes (GALLIVM_PERF=nopt,
// docs/tune.md "Time"): every candidate's figures, to the last digit of report.json, are the ones
// the optimised code gives (a GALLIVM_PERF the user sets, even empty, is kept).
TEST(MatcCli, TuneScoresTheSameWithoutLavapipesOptimisationPasses) {
  const std::string dir = facet::test::scratchDir("cli-tune-nopt");
  const std::string tune = kMatc + " tune " + facet::test::examplePath("materials/red_plastic.mat") + " --budgets " +
                           facet::test::examplePath("lint/tune_budgets.json") +
                           " --max-changes 0 --sphere-pixels 16 --cache " + dir + "/cache --out ";
  auto optimised = run("ASAN_OPTIONS=detect_leaks=0 GALLIVM_PERF= " + tune + dir + "/optimised");
  auto unoptimised = run("ASAN_OPTIONS=detect_leaks=0 env -u GALLIVM_PERF " + tune + dir + "/default");
  ASSERT_EQ(optimised.exitCode, 0) << optimised.err;
  ASSERT_EQ(unoptimised.exitCode, 0) << unoptimised.err;
  const std::string report = facet::test::readText(dir + "/default/report.json");
  EXPECT_NE(report.find("\"psnr_db\""), std::string::npos);
  EXPECT_TRUE(report == facet::test::readText(dir + "/optimised/report.json"))
      << "diff " << dir << "/default/report.json " << dir << "/optimised/report.json";
}

// matc tune (docs/tune.md): usage errors exit 2, a bad budgets or tuning file 1 at its JSON
// pointer; the gate (--check) fails, with the figures, a tuning file whose high tier takes a worse lobe.
TEST(MatcCli, TuneGateAndItsErrors) {
  const std::string dir = facet::test::scratchDir("cli-tune");
  const std::string red = facet::test::examplePath("materials/red_plastic.mat");
  auto adreno = run(kMatc + " tune " + red + " --gpu adreno-630");
  EXPECT_EQ(adreno.exitCode, 2);
  EXPECT_NE(adreno.err.find("matc: error: --gpu: 'adreno-630' cannot be a target"), std::string::npos) << adreno.err;
  EXPECT_EQ(run(kMatc + " tune " + red + " --write --check").exitCode, 2);
  const std::string budgets = write(dir, "b.json", R"({"tiers": {"mid": {"min_psnr_db": "40"}}})");
  auto bad = run(kMatc + " tune " + red + " --budgets " + budgets);
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find(budgets + ": error: /tiers/mid/min_psnr_db: expected a number"), std::string::npos) << bad.err;

  // A tuning file whose high tier reads the lut lobe: far below high's 50 dB.
  fs::copy_file(red, dir + "/red_plastic.mat", fs::copy_options::overwrite_existing);
  write(dir, "red_plastic.tuning.json",
        R"({"material": "red_plastic", "gpu": "mali-g57", "vertices_per_pixel": 0.1,
            "tiers": {"high": {"config": {"specular": "lut"}, "cost": 1, "psnr_db": 60}}})");
  auto worse = run("ASAN_OPTIONS=detect_leaks=0 " + kMatc + " tune " + dir + "/red_plastic.mat --check");
  EXPECT_EQ(worse.exitCode, 1);
  EXPECT_NE(worse.err.find("red_plastic.tuning.json: error: tier high: the tuned configuration no longer meets its "
                           "budget (PSNR ≥ 50.0 dB, no energy gain): "),
            std::string::npos)
      << worse.err;
  write(dir, "red_plastic.tuning.json",
        R"({"material": "red_plastic", "tiers": {"mid": {"config": {"specular": 3}}}})");
  auto malformed = run(kMatc + " tune " + dir + "/red_plastic.mat --check");
  EXPECT_EQ(malformed.exitCode, 1);
  EXPECT_NE(malformed.err.find("red_plastic.tuning.json: error: /tiers/mid/config/specular: expected a string"),
            std::string::npos)
      << malformed.err;
}
