// R11G11B10F as the HDR target (VulkanOptions / GlOptions::hdrFormat): both APIs render every
// example scene with it on both paths, the frame graph counts half the HDR bytes, and the error it
// costs against RGBA16F stays bounded. The figures printed here are docs/runtime.md's
// ("HDR format"): `ctest --test-dir build/test -R HdrFormat -V`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/scene/scene.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using namespace facet::runtime;

struct Difference {
  double psnr = 0;  // dB over the RGB channels of the 8-bit output
  int worst = 0;    // largest difference in 8-bit steps
};

Difference compare(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  double squared = 0;
  size_t n = 0;
  Difference d;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    if (i % 4 == 3) continue;
    const int e = int(a[i]) - int(b[i]);
    squared += double(e) * e;
    d.worst = std::max(d.worst, std::abs(e));
    ++n;
  }
  const double mse = squared / double(std::max<size_t>(n, 1));
  d.psnr = mse == 0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / mse);
  return d;
}

}  // namespace

TEST(HdrFormat, FrameGraphCountsHalfTheHdrBytes) {
  fg::CompiledGraph wide, packed;
  std::string error;
  ASSERT_TRUE(buildForwardPostGraph(1920, 1080, PostPath::Separate, false).graph.compile(&wide, &error)) << error;
  ASSERT_TRUE(buildForwardPostGraph(1920, 1080, PostPath::Separate, false, HdrFormat::R11G11B10Float)
                  .graph.compile(&packed, &error))
      << error;
  EXPECT_EQ(wide.storedBytes(), 16588800u + 8294400u);   // HDR 8 B/pixel + LDR
  EXPECT_EQ(packed.storedBytes(), 8294400u + 8294400u);  // HDR 4 B/pixel + LDR
  EXPECT_EQ(packed.sampledBytes(), 8294400u);
  fg::CompiledGraph merged;
  ASSERT_TRUE(buildForwardPostGraph(1920, 1080, PostPath::Merged, false, HdrFormat::R11G11B10Float)
                  .graph.compile(&merged, &error));
  EXPECT_EQ(merged.storedBytes(), 8294400u) << "merged: HDR never leaves the tile, whatever its format";
  EXPECT_STREQ(toString(HdrFormat::R11G11B10Float), "r11g11b10f");
}

// Each example scene with its own post variant, RGBA16F against R11G11B10F (Vulkan merged), the
// packed format on GLES too (both paths), validation on.
TEST(HdrFormat, R11G11B10FRendersEveryExampleSceneWithBoundedError) {
  facet::compiler::BuildOptions build;
  build.pointLightCounts = {0, 1, 2, 4};
  build.shadowCascadeCounts = {0, 4};  // yard.json's sun casts, with the default 4 cascades
  const std::string packages = facet::test::writeExamplePackages("hdr-format-packages", build);
  std::string error;
  for (const std::string& path : facet::test::exampleScenes()) {
    SCOPED_TRACE(path);
    auto scene = loadScene(path, &error);
    ASSERT_TRUE(scene) << error;
    auto frame = SceneFrame::prepare(*scene, packages, &error);
    ASSERT_TRUE(frame) << error;
    std::vector<FrameResult> images;
    for (HdrFormat format : {HdrFormat::Rgba16Float, HdrFormat::R11G11B10Float}) {
      VulkanOptions options;
      options.validation = true;
      options.readBackHdr = false;
      options.post = scene->post;
      options.bloom = scene->bloom;
      options.hdrFormat = format;
      auto backend = createVulkanBackend(options, &error);
      ASSERT_TRUE(backend) << error;
      EXPECT_EQ(backend->hdrFormat(), format);
      images.emplace_back();
      ASSERT_TRUE(backend->render(frame->frame(), &images.back(), &error)) << error;
      for (const std::string& message : backend->validationErrors()) ADD_FAILURE() << "validation: " << message;
    }
    const Difference d = compare(images[0].ldr, images[1].ldr);
    std::printf("%s: R11G11B10F against RGBA16F, 8-bit output: PSNR %.1f dB, worst %d steps\n",
                std::filesystem::path(path).filename().c_str(), d.psnr, d.worst);
    // Measured: 52.7..59.2 dB, at most 2 steps (4 on graded.json, whose contrast and saturation
    // widen the packed format's rounding). The bounds leave a margin for other drivers' rounding.
    EXPECT_GT(d.psnr, 48.0);
    EXPECT_LE(d.worst, 6);

    if (scene->sun && scene->sun->castShadows) continue;  // GL does not draw the shadow pass (docs/shadows.md)
    for (PostPath gpuPath : {PostPath::Merged, PostPath::Separate}) {
      GlOptions options;
      options.context = GlContextKind::EglGles;
      options.postPath = gpuPath;
      options.post = scene->post;
      options.bloom = scene->bloom;
      options.hdrFormat = HdrFormat::R11G11B10Float;
      auto gl = createGlBackend(options, &error);
      ASSERT_TRUE(gl) << error;
      FrameResult image;
      ASSERT_TRUE(gl->render(frame->frame(), &image, &error)) << error;
      EXPECT_EQ(image.hdr.size(), image.ldr.size()) << "read back, alpha 1";
      EXPECT_GT(compare(image.ldr, images[1].ldr).psnr, 35.0) << "GLES " << toString(gpuPath) << " against Vulkan";
      for (const std::string& message : gl->validationErrors()) ADD_FAILURE() << "GL: " << message;
    }
  }
}
