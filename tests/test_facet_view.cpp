// facet-view as users run it: a scene rendered on Vulkan with validation exits 0 and writes its
// PNG; a bad scene exits 1 with a located error and writes nothing. In the ASan build the same
// runs also fail on any leak at exit (LeakSanitizer turns the exit code non-zero).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "facet/package.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using facet::test::run;

const std::string kFacetView = FACET_VIEW;

}  // namespace

TEST(FacetView, RendersAnExampleSceneOnVulkanWithValidation) {
  std::string packages = facet::test::writeExamplePackages("view-packages");
  std::string out = facet::test::scratchDir("view-out");
  auto r = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages + " --out " +
               out + " --backend vulkan --validation");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_TRUE(fs::is_regular_file(out + "/sphere.vulkan.png")) << r.out;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
}

// The graded example scene runs its own post variant (LUT and vignette) on both APIs, and
// --hdr-format r11g11b10f reaches the backend and the frame graph's byte counts.
TEST(FacetView, RendersTheGradedSceneWithAPackedHdrTarget) {
  std::string packages = facet::test::writeExamplePackages("view-packages");
  std::string out = facet::test::scratchDir("view-graded-out");
  auto r = run(kFacetView + " " + facet::test::examplePath("scenes/cube_look.json") + " --packages " + packages + " --out " +
               out + " --backend both --validation --hdr-format r11g11b10f --post-path separate --stats --frames 1 --warmup 0");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_TRUE(fs::is_regular_file(out + "/cube_look.vulkan.png")) << r.out;
  EXPECT_TRUE(fs::is_regular_file(out + "/cube_look.gl.png")) << r.out;
  EXPECT_NE(r.out.find("vulkan: separate path, r11g11b10f HDR, frame graph at 384x256"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total: loaded 0 B, stored 786432 B, sampled 393216 B per frame"), std::string::npos)
      << "HDR at 4 bytes per pixel, stored and sampled\n" << r.out;
}

// A package whose shaders read another interface than it declares (here: the preshader section
// dropped, so they read a 64-byte block where a draw binds 32) makes facet-view exit 1 naming the
// material, variant and stage, and write no image: on Vulkan at load (the SPIR-V), on GL before the
// first draw (the linked program of a package without SPIR-V). Vulkan used to draw it, exit 0.
TEST(FacetView, APackageWhoseShadersDisagreeWithItExitsOne) {
  namespace pkg = facet::package;
  std::string packages = facet::test::writeExamplePackages("view-hostile");
  pkg::ReadResult r = pkg::readFile(packages + "/red_plastic.matpkg");
  ASSERT_TRUE(r.package) << r.error;
  pkg::Package p = *r.package;
  p.preshader = {};
  struct Run {
    const char* backend;
    std::string why;
  };
  for (const Run& c : {Run{"vulkan", "the fragment shader (SPIR-V) reads MaterialParams as 64 bytes, but the runtime binds 32"},
                       Run{"gl", "the fragment shader (GLSL ES) reads MaterialParams as 64 bytes, but the runtime binds 32"}}) {
    if (std::string(c.backend) == "gl")
      for (pkg::Variant& v : p.variants) std::erase_if(v.shaders, [](auto& s) { return s.target != pkg::Target::GlslEs300; });
    std::string error;
    ASSERT_TRUE(pkg::writeFile(packages + "/red_plastic.matpkg", pkg::write(p), &error)) << error;
    std::string out = facet::test::scratchDir("view-hostile-out");
    auto run = facet::test::run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
                                " --out " + out + " --backend " + c.backend + " --validation");
    EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
    EXPECT_NE(run.err.find("material 'red_plastic' variant high.dir1: " + c.why), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out + "/sphere." + c.backend + ".png"));
  }
}

TEST(FacetView, ABrokenSceneIsALocatedErrorAndWritesNothing) {
  std::string dir = facet::test::scratchDir("view-broken");
  std::ofstream(dir + "/broken.json") << "{\n  \"objects\": [\n    {\"material\": }\n  ]\n}\n";
  auto r = run(kFacetView + " " + dir + "/broken.json --out " + dir + "/out --backend vulkan");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.rfind(dir + "/broken.json:3:18: error: invalid JSON", 0), 0u) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out")) << "no output folder for a scene that does not load";
}

TEST(FacetView, ImagesOutsideTheSceneFolderNeedAnAssetRoot) {
  std::string packages = facet::test::writeExamplePackages("view-asset-packages");
  std::string dir = facet::test::scratchDir("view-assets");
  fs::create_directories(dir + "/scenes");
  fs::copy_file(facet::test::examplePath("scenes/textures/tiles.png"), dir + "/tiles.png", fs::copy_options::overwrite_existing);
  std::ofstream(dir + "/scenes/s.json") << R"({"width": 32, "height": 32, "sun": {},
    "objects": [{"material": "painted_tiles", "params": {"albedo": "../tiles.png"}}]})";
  const std::string command = kFacetView + " " + dir + "/scenes/s.json --packages " + packages + " --out " + dir +
                              "/out --backend vulkan";
  auto r = run(command);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("/objects/0/params/albedo: '../tiles.png' is outside the folder"), std::string::npos) << r.err;
  r = run(command + " --asset-root " + dir);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir + "/out/s.vulkan.png"));
}
