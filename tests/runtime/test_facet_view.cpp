// facet-view as users run it: a scene rendered on Vulkan with validation exits 0 and writes its
// PNG; a bad scene exits 1 with a located error and writes nothing. In the ASan build the same
// runs also fail on any leak at exit (LeakSanitizer turns the exit code non-zero).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "facet/compiler/build.h"
#include "facet/package/package.h"
#include "gltf_test_files.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
using facet::test::run;

const std::string kFacetView = FACET_VIEW;

}  // namespace

TEST(FacetView, RendersAnExampleSceneOnVulkanWithValidation) {
  std::string packages = facet::test::writeExamplePackages("view-packages");
  std::string out = facet::test::scratchDir("view-out");
  auto r = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
               " --out " + out + " --backend vulkan --validation");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_TRUE(fs::is_regular_file(out + "/sphere.vulkan.png")) << r.out;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
}

// The graded example scene runs its own post variant (LUT and vignette) on both APIs, and
// --hdr-format r11g11b10f reaches the backend and the frame graph's byte counts.
TEST(FacetView, RendersTheGradedSceneWithAPackedHdrTarget) {
  std::string packages = facet::test::writeExamplePackages("view-packages");
  std::string out = facet::test::scratchDir("view-graded-out");
  auto r = run(
      kFacetView + " " + facet::test::examplePath("scenes/cube_look.json") + " --packages " + packages + " --out " +
      out + " --backend both --validation --hdr-format r11g11b10f --post-path separate --stats --frames 1 --warmup 0");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_TRUE(fs::is_regular_file(out + "/cube_look.vulkan.png")) << r.out;
  EXPECT_TRUE(fs::is_regular_file(out + "/cube_look.gl.png")) << r.out;
  EXPECT_NE(r.out.find("vulkan: separate path, r11g11b10f HDR, frame graph at 384x256"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total: loaded 0 B, stored 786432 B, sampled 393216 B per frame"), std::string::npos)
      << "HDR at 4 bytes per pixel, stored and sampled\n"
      << r.out;
}

// --msaa 4 reaches both backends and the frame graph: the samples are transient, so the bytes
// stored are those of one sample; --msaa 3 is a usage error (exit 2).
TEST(FacetView, MsaaReachesTheBackendsAndTheFrameGraph) {
  std::string packages = facet::test::writeExamplePackages("view-packages");
  std::string out = facet::test::scratchDir("view-msaa-out");
  auto r = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
               " --out " + out + " --backend both --validation --msaa 4 --stats --frames 1 --warmup 0");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("vulkan: merged path, rgba16f HDR, frame graph at 256x256, MSAA 4x"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("gl: merged path, rgba16f HDR, frame graph at 256x256, MSAA 4x"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hdr_ms 4x"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total: loaded 0 B, stored 262144 B, sampled 0 B per frame"), std::string::npos) << r.out;
  auto bad = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
                 " --out " + out + " --msaa 3");
  EXPECT_EQ(bad.exitCode, 2) << bad.out << bad.err;
}

// --msaa-form attachments: Vulkan's portable form (lavapipe offers the extension), whose merged
// post subpass reads the samples themselves (hdr_ms, an input attachment, still transient); an
// unknown form is a usage error.
TEST(FacetView, MsaaFormAttachmentsToneMapsEachSampleOnVulkan) {
  std::string packages = facet::test::writeExamplePackages("view-packages");
  std::string out = facet::test::scratchDir("view-msaa-form-out");
  auto r =
      run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages + " --out " +
          out + " --backend vulkan --validation --msaa 4 --msaa-form attachments --stats --frames 1" + " --warmup 0");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("the post subpass tone maps each sample (subpassInputMS)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hdr_ms     load clear     store dont_care (input attachment)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total: loaded 0 B, stored 262144 B, sampled 0 B per frame"), std::string::npos) << r.out;
  auto first =
      run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages + " --out " +
          out + " --backend vulkan --msaa 4 --msaa-form resolve-first --stats --frames 1" + " --warmup 0");
  ASSERT_EQ(first.exitCode, 0) << first.out << first.err;
  EXPECT_EQ(first.out.find("subpassInputMS"), std::string::npos) << first.out;
  EXPECT_NE(first.out.find("pResolveAttachments"), std::string::npos) << first.out;
  auto bad = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
                 " --out " + out + " --msaa 4 --msaa-form tiles");
  EXPECT_EQ(bad.exitCode, 2) << bad.out << bad.err;
}

// --fxaa reaches both backends and the frame graph: the tone-mapped image is stored and sampled
// (4 + 4 bytes a pixel more than without), on top of the LDR output.
TEST(FacetView, FxaaReachesTheBackendsAndTheFrameGraph) {
  std::string packages = facet::test::writeExamplePackages("view-packages");
  std::string out = facet::test::scratchDir("view-fxaa-out");
  auto r = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
               " --out " + out + " --backend both --validation --fxaa --stats --frames 1 --warmup 0");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("vulkan: merged path, rgba16f HDR, frame graph at 256x256, MSAA 1x (off"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("), FXAA:\nrender pass 0: forward post\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("render pass 1: fxaa\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gl: merged path, rgba16f HDR, frame graph at 256x256, MSAA 1x (off), FXAA:"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("tonemapped"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total: loaded 0 B, stored 524288 B, sampled 262144 B per frame"), std::string::npos) << r.out;
}

// --bloom reaches both backends and the frame graph: the path is the separate one, HDR (256 × 256
// at 8 bytes) is stored and sampled twice, and the chain of 3 levels (128², 64², 32² at 8 bytes) is
// stored after each downsample, loaded and stored again by the upsamples of the two finer levels;
// settings out of range and levels without --bloom are usage errors (exit 2).
TEST(FacetView, BloomReachesTheBackendsAndTheFrameGraph) {
  std::string packages = facet::test::writeExamplePackages("view-packages");
  std::string out = facet::test::scratchDir("view-bloom-out");
  auto r = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
               " --out " + out +
               " --backend both --validation --bloom 0.5 --bloom-levels 3 --bloom-threshold 1 --stats --frames 1 "
               "--warmup 0");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  for (const char* api : {"vulkan", "gl"}) {
    EXPECT_NE(r.out.find(std::string(api) + ": separate path, rgba16f HDR, frame graph at 256x256"), std::string::npos)
        << r.out;
  }
  EXPECT_NE(r.out.find("), bloom of 3 levels:\nrender pass 0: forward\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("render pass 5: bloom_up0\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total: loaded 163840 B, stored 1122304 B, sampled 1384448 B per frame"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(" bloom "), std::string::npos) << "Vulkan times the chain: " << r.out;
  for (const char* bad : {"--bloom 2", "--bloom 0.5 --bloom-levels 13", "--bloom-levels 3", "--bloom nan"}) {
    auto u = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
                 " --out " + out + " --backend vulkan " + bad);
    EXPECT_EQ(u.exitCode, 2) << bad << ": " << u.err;
    EXPECT_NE(u.err.find("facet-view: error: "), std::string::npos) << bad << ": " << u.err;
  }
}

// --render-scale 0.5 reaches both backends and the frame graph: the merged path becomes the
// separate one, HDR (128 × 128 at 8 bytes) is stored and sampled beside the 256 × 256 LDR; a
// scale outside 0.5..1, or NaN, is a usage error (exit 2).
TEST(FacetView, RenderScaleReachesTheBackendsAndTheFrameGraph) {
  std::string packages = facet::test::writeExamplePackages("view-packages");
  std::string out = facet::test::scratchDir("view-scale-out");
  auto r = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
               " --out " + out + " --backend both --validation --render-scale 0.5 --stats --frames 1 --warmup 0");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  for (const char* api : {"vulkan", "gl"}) {
    EXPECT_NE(r.out.find(std::string(api) +
                         ": separate path, rgba16f HDR, frame graph at 256x256, forward pass at 128x128 (render "
                         "scale 0.5)"),
              std::string::npos)
        << r.out;
  }
  EXPECT_NE(r.out.find("total: loaded 0 B, stored 393216 B, sampled 131072 B per frame"), std::string::npos) << r.out;
  for (const char* scale : {"0.3", "1.5", "nan"}) {
    auto bad = run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " + packages +
                   " --out " + out + " --render-scale " + scale);
    EXPECT_EQ(bad.exitCode, 2) << scale << bad.out << bad.err;
    EXPECT_NE(bad.err.find("--render-scale must be in 0.5..1"), std::string::npos) << scale << bad.err;
  }
}

// A package whose shaders read another interface than it declares (here: the preshader section
// dropped, so they read a 64-byte block where a draw binds 32) makes facet-view exit 1 naming the
// material, variant and stage, and write no image: on Vulkan at load (the SPIR-V), on GL before the
// first draw (the linked program of a package without SPIR-V). Vulkan used to draw it, exit 0.
// --stats counts the shadow pass's draws: one per cascade and caster that can shadow it. The 40 m
// ground reaches both cascades of this view, the box near the camera only the first: 3 draws.
TEST(FacetView, StatsCountTheShadowPassCasterDraws) {
  facet::compiler::BuildOptions options;
  options.shadowCascadeCounts = {0, 2};
  const std::string packages = facet::test::writePackagesFromTexts(
      "view-shadow-packages", {"material plastic { shading lit\n surface { baseColor = vec3(0.7, 0.7, 0.7) } }"},
      options);
  const std::string dir = facet::test::scratchDir("view-shadow-stats");
  std::ofstream(dir + "/s.json") << R"({"width": 64, "height": 48,
    "camera": {"position": [2.6, 2.2, 3.6], "target": [0.2, 0.2, 0.2]},
    "sun": {"direction": [0.7, -0.4, -0.5], "castShadows": true},
    "shadows": {"atlasSize": 512, "cascades": 2},
    "objects": [{"mesh": "plane", "material": "plastic", "scale": [40, 1, 40]},
                {"mesh": "box", "material": "plastic", "position": [0, 0.5, 0]}]})";
  auto r = run(kFacetView + " " + dir + "/s.json --packages " + packages + " --out " + dir +
               "/out --backend vulkan --validation --stats --json --frames 1 --warmup 0");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const auto report = nlohmann::json::parse(r.out);
  ASSERT_EQ(report.size(), 1u);
  EXPECT_EQ(report[0]["shadowCascades"], 2);
  EXPECT_EQ(report[0]["shadowCasterDraws"], 3);
  r = run(kFacetView + " " + dir + "/s.json --packages " + packages + " --out " + dir +
          "/out --backend vulkan --stats --frames 1 --warmup 0");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("shadow pass: 3 caster draws over 2 cascades (512² atlas)"), std::string::npos) << r.out;

  // --shadow-cascades tints the receivers by cascade: this view's ground spans both.
  r = run(kFacetView + " " + dir + "/s.json --packages " + packages + " --out " + dir +
          "/tinted --backend vulkan --shadow-cascades");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  size_t first = 0, second = 0, third = 0, fourth = 0;
  const size_t at = r.out.find("vulkan: receiver pixels per cascade: ");
  ASSERT_NE(at, std::string::npos) << r.out;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "vulkan: receiver pixels per cascade: %zu, %zu, %zu, %zu", &first, &second,
                        &third, &fourth),
            4)
      << r.out;
  EXPECT_GT(first, 100u);
  EXPECT_GT(second, 100u);
  EXPECT_EQ(third + fourth, 0u);
  EXPECT_LE(first + second, 64u * 48u);
  EXPECT_TRUE(fs::is_regular_file(dir + "/tinted/s.vulkan.png"));
  // A scene whose sun does not cast has no cascades to show: an error, nothing written.
  std::ofstream(dir + "/lit.json") << R"({"width": 16, "height": 16, "sun": {},
    "objects": [{"mesh": "box", "material": "plastic"}]})";
  r = run(kFacetView + " " + dir + "/lit.json --packages " + packages + " --out " + dir +
          "/lit --backend vulkan --shadow-cascades");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("the scene's sun does not cast shadows"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/lit/lit.vulkan.png"));
}

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
  for (const Run& c :
       {Run{"vulkan", "the fragment shader (SPIR-V) reads MaterialParams as 76 bytes, but the runtime binds 32"},
        Run{"gl", "the fragment shader (GLSL ES) reads MaterialParams as 80 bytes, but the runtime binds 32"}}) {
    if (std::string(c.backend) == "gl")
      for (pkg::Variant& v : p.variants)
        std::erase_if(v.shaders, [](auto& s) { return s.target != pkg::Target::GlslEs300; });
    std::string error;
    ASSERT_TRUE(pkg::writeFile(packages + "/red_plastic.matpkg", pkg::write(p), &error)) << error;
    std::string out = facet::test::scratchDir("view-hostile-out");
    auto run = facet::test::run(kFacetView + " " + facet::test::examplePath("scenes/sphere.json") + " --packages " +
                                packages + " --out " + out + " --backend " + c.backend + " --validation");
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
  fs::copy_file(facet::test::examplePath("scenes/textures/tiles.png"), dir + "/tiles.png",
                fs::copy_options::overwrite_existing);
  std::ofstream(dir + "/scenes/s.json") << R"({"width": 32, "height": 32, "sun": {},
    "objects": [{"material": "painted_tiles", "params": {"albedo": "../tiles.png"}}]})";
  const std::string command =
      kFacetView + " " + dir + "/scenes/s.json --packages " + packages + " --out " + dir + "/out --backend vulkan";
  auto r = run(command);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("/objects/0/params/albedo: '../tiles.png' is outside the folder"), std::string::npos) << r.err;
  r = run(command + " --asset-root " + dir);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir + "/out/s.vulkan.png"));
}

// Hostile glTF meshes end in exit 1 with the file and the place, never a crash (a 20,000-deep
// `extras` overflowed tinygltf's stack; a .glb whose BIN chunk length counted its own header was
// read past its end; a NaN normal rendered a black object with exit 0).
TEST(FacetView, HostileGltfMeshesAreLocatedErrors) {
  std::string packages = facet::test::writePackagesFromTexts(
      "view-gltf-packages", {"material flat { shading unlit\n surface { baseColor = vec3(0.5) } }"});
  std::string dir = facet::test::scratchDir("view-gltf");
  facet::test::writeText(dir + "/deep.gltf", "{\"asset\": {\"version\": \"2.0\"},\n\"extras\": " +
                                                 std::string(20000, '[') + std::string(20000, ']') + "}");
  const std::string json = facet::test::quadJson(R"({"byteLength": 236})");
  std::vector<uint8_t> overlong = facet::test::glb(json, facet::test::quadBin());
  overlong[12 + 8 + (json.size() + 3) / 4 * 4] += 8;  // the BIN chunk's length counts its 8-byte header
  facet::test::writeBytes(dir + "/overlong.glb", overlong);
  std::vector<uint8_t> bin = facet::test::quadBin();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(bin.data() + 48 + 4, &nan, 4);  // normal 0's y
  facet::test::writeBytes(dir + "/nan.bin", bin);
  facet::test::writeText(dir + "/nan.gltf", facet::test::quadJson(R"({"uri": "nan.bin", "byteLength": 236})"));
  const std::pair<const char*, std::string> cases[] = {
      {"deep.gltf", dir + "/deep.gltf:2:74: error: arrays and objects nest more than 64 deep"},
      {"overlong.glb", dir + "/overlong.glb: error: GLB chunk 1 at byte "},
      {"nan.gltf",
       dir + "/nan.gltf: error: /meshes/0/primitives/0/attributes/NORMAL: /accessors/1 element 0 is not finite"}};
  for (const auto& [mesh, expected] : cases) {
    std::ofstream(dir + "/s.json") << R"({"width": 16, "height": 16, "objects": [{"mesh": ")" << mesh
                                   << R"(", "material": "flat"}]})";
    auto r = run(kFacetView + " " + dir + "/s.json --packages " + packages + " --out " + dir + "/out --backend vulkan");
    EXPECT_EQ(r.exitCode, 1) << mesh << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("facet-view: error: " + dir + "/s.json: object 0: " + expected, 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out")) << mesh;
  }
}
