// The post pass's effects as a renderer runs them: a backend is created with a post variant
// (VulkanOptions::post / GlOptions::post, from a scene's "post"), the variants give the images
// their effects should, and an effect the runtime does not embed is refused at creation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "facet/runtime/color_grading.h"
#include "facet/runtime/material_instance.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/runtime/vignette.h"
#include "facet/scene/scene.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using facet::runtime::FrameResult;
using facet::runtime::PostPath;
using facet::runtime::PostSettings;

struct Frame {
  std::string packages;
  std::unique_ptr<facet::runtime::SceneFrame> frame;
};

const Frame& sphere() {
  static Frame f = [] {
    Frame out;
    facet::compiler::BuildOptions build;
    build.tiers = {facet::permutations::Tier::High};
    out.packages = facet::test::writeExamplePackages("post-effects-packages", build);
    std::string error;
    auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/sphere.json"), &error);
    EXPECT_TRUE(scene) << error;
    if (scene) out.frame = facet::runtime::SceneFrame::prepare(*scene, out.packages, &error);
    EXPECT_TRUE(out.frame) << error;
    return out;
  }();
  return f;
}

enum class Api { Vulkan, Gles };

// One frame through a backend created for `post` on the given API and path, validation on.
FrameResult render(Api api, const PostSettings& post, const facet::runtime::FrameDesc& frame,
                   PostPath path = PostPath::Auto,
                   facet::runtime::HdrFormat hdrFormat = facet::runtime::HdrFormat::Rgba16Float) {
  std::string error;
  std::unique_ptr<facet::runtime::RenderBackend> backend;
  if (api == Api::Vulkan) {
    facet::runtime::VulkanOptions options;
    options.validation = true;
    options.post = post;
    options.postPath = path;
    options.hdrFormat = hdrFormat;
    backend = facet::runtime::createVulkanBackend(options, &error);
  } else {
    facet::runtime::GlOptions options;
    options.context = facet::runtime::GlContextKind::EglGles;
    options.post = post;
    options.postPath = path;
    options.hdrFormat = hdrFormat;
    backend = facet::runtime::createGlBackend(options, &error);
  }
  FrameResult result;
  EXPECT_TRUE(backend) << error;
  if (!backend) return result;
  EXPECT_TRUE(backend->render(frame, &result, &error)) << error;
  for (const std::string& message : backend->validationErrors()) ADD_FAILURE() << "validation: " << message;
  return result;
}

FrameResult renderVulkan(const PostSettings& post) {
  if (!sphere().frame) return {};
  return render(Api::Vulkan, post, sphere().frame->frame());
}

int maxDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  int worst = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  return worst;
}

}  // namespace

TEST(PostEffects, EachToneCurveGivesItsOwnImage) {
  const FrameResult aces = renderVulkan({"aces", false});
  const FrameResult neutral = renderVulkan({"neutral", false});
  const FrameResult none = renderVulkan({"none", false});
  ASSERT_FALSE(aces.ldr.empty());
  ASSERT_EQ(aces.ldr.size(), neutral.ldr.size());
  EXPECT_GT(maxDifference(aces.ldr, neutral.ldr), 8);
  EXPECT_GT(maxDifference(aces.ldr, none.ldr), 8);
  EXPECT_GT(maxDifference(neutral.ldr, none.ldr), 0);
}

// What the post pass quantises, from the HDR the forward pass wrote: the ACES fit, then sRGB
// encoding, in 8-bit steps (chunks/tonemap_aces.glsl, chunks/srgb.glsl).
double exactEncodedSteps(float hdr) {
  const double x = std::clamp(double(hdr), 0.0, 160.0);
  const double display = std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  const double encoded = display <= 0.0031308 ? display * 12.92 : 1.055 * std::pow(display, 1.0 / 2.4) - 0.055;
  return encoded * 255.0;
}

// Dithering moves a pixel by less than one 8-bit step from the exact value it quantises, and on
// average not at all, where plain rounding is off by the fraction it drops (the flat background of
// the sphere scene is one value, so its rounding error does not average out).
TEST(PostEffects, DitheringKeepsTheMeanOfTheExactValue) {
  const FrameResult plain = renderVulkan({"aces", false});
  const FrameResult dithered = renderVulkan({"aces", true});
  ASSERT_FALSE(plain.ldr.empty());
  ASSERT_EQ(plain.ldr.size(), dithered.ldr.size());
  ASSERT_EQ(plain.hdr.size(), plain.ldr.size());
  EXPECT_LE(maxDifference(plain.ldr, dithered.ldr), 1);
  double plainError = 0, ditheredError = 0, worst = 0;
  size_t channels = 0;
  for (size_t i = 0; i < plain.ldr.size(); ++i) {
    if (i % 4 == 3) continue;
    const double exact = exactEncodedSteps(plain.hdr[i]);
    if (exact < 1 || exact > 254) continue;  // at the ends the target clamps one side of the noise
    plainError += plain.ldr[i] - exact;
    ditheredError += dithered.ldr[i] - exact;
    worst = std::max(worst, std::abs(dithered.ldr[i] - exact));
    ++channels;
  }
  ASSERT_GT(channels, plain.ldr.size() / 4);
  plainError /= double(channels);
  ditheredError /= double(channels);
  EXPECT_LT(worst, 1.5);  // |noise| < 1 step, then rounding
  EXPECT_LT(std::abs(ditheredError), 0.02) << "plain rounding: " << plainError;
  EXPECT_GT(std::abs(plainError), 3 * std::abs(ditheredError));
}

TEST(PostEffects, AnEffectNotBuiltInIsRefusedAtCreation) {
  std::string error;
  facet::runtime::VulkanOptions vk;
  vk.post.toneCurve = "filmic";
  EXPECT_FALSE(facet::runtime::createVulkanBackend(vk, &error));
  EXPECT_NE(error.find(
                "no post variant with tone curve 'filmic' (built in: tone curves aces, neutral, none, each with any of "
                "colour grading, vignette, dithering and bloom)"),
            std::string::npos)
      << error;
  facet::runtime::GlOptions gl;
  gl.post.toneCurve = "filmic";
  EXPECT_FALSE(facet::runtime::createGlBackend(gl, &error));
  EXPECT_NE(error.find("no post variant with tone curve 'filmic'"), std::string::npos) << error;
}

TEST(PostEffects, SceneNamesThePostEffects) {
  std::string error;
  auto scene = facet::runtime::parseScene(
      "s.json", R"({"post": {"toneCurve": "neutral", "dither": true}, "objects": []})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_EQ(scene->post, (PostSettings{"neutral", true, false, false}));
  EXPECT_FALSE(facet::runtime::parseScene("s.json", R"({"post": {"toneCurve": "filmic"}, "objects": []})", &error));
  EXPECT_NE(error.find("s.json: error: /post/toneCurve: expected \"aces\", \"neutral\" or \"none\", not 'filmic'"),
            std::string::npos)
      << error;
  EXPECT_FALSE(facet::runtime::parseScene("s.json", R"({"post": {"dither": 1}, "objects": []})", &error));
  EXPECT_NE(error.find("/post/dither: expected true or false"), std::string::npos) << error;
}

// Grading through the identity table changes nothing beyond the LUT's RGBA16F rounding and the
// filter's fixed-point weights: within one 8-bit step, on both APIs and both paths.
TEST(PostEffects, IdentityLutGivesTheUngradedImage) {
  ASSERT_TRUE(sphere().frame);
  const facet::runtime::ColorLutTexels identity = facet::runtime::colorLutTexels(facet::runtime::buildColorLut({}));
  facet::runtime::FrameDesc graded = sphere().frame->frame();
  graded.colorLut = &identity;
  for (Api api : {Api::Vulkan, Api::Gles})
    for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
      SCOPED_TRACE(std::string(api == Api::Vulkan ? "Vulkan " : "GLES ") + facet::runtime::toString(path));
      const FrameResult plain = render(api, {"aces", false}, sphere().frame->frame(), path);
      const FrameResult lut = render(api, {"aces", false, true}, graded, path);
      ASSERT_FALSE(plain.ldr.empty());
      ASSERT_EQ(plain.ldr.size(), lut.ldr.size());
      EXPECT_LE(maxDifference(plain.ldr, lut.ldr), 1);
    }
}

// A .cube that swaps red and blue swaps them in the image: the texels' order (red fastest), the
// 3D texture's axes and the shader's coordinates agree.
TEST(PostEffects, CubeFileThatSwapsRedAndBlueSwapsThemInTheImage) {
  ASSERT_TRUE(sphere().frame);
  std::string cube = "TITLE \"swap red and blue\"\nLUT_3D_SIZE 2\n";
  for (int b = 0; b < 2; ++b)
    for (int g = 0; g < 2; ++g)
      for (int r = 0; r < 2; ++r) cube += std::to_string(b) + " " + std::to_string(g) + " " + std::to_string(r) + "\n";
  std::string error;
  const auto lut = facet::runtime::parseCubeLut("swap.cube", cube, &error);
  ASSERT_TRUE(lut) << error;
  const facet::runtime::ColorLutTexels texels = facet::runtime::colorLutTexels(*lut);
  facet::runtime::FrameDesc graded = sphere().frame->frame();
  graded.colorLut = &texels;
  for (Api api : {Api::Vulkan, Api::Gles}) {
    SCOPED_TRACE(api == Api::Vulkan ? "Vulkan" : "GLES");
    const FrameResult plain = render(api, {"aces", false}, sphere().frame->frame());
    const FrameResult swapped = render(api, {"aces", false, true}, graded);
    ASSERT_FALSE(plain.ldr.empty());
    ASSERT_EQ(plain.ldr.size(), swapped.ldr.size());
    int worst = 0, redVsBlue = 0;
    for (size_t i = 0; i < plain.ldr.size(); i += 4) {
      worst = std::max({worst, std::abs(swapped.ldr[i] - plain.ldr[i + 2]), std::abs(swapped.ldr[i + 2] - plain.ldr[i]),
                        std::abs(swapped.ldr[i + 1] - plain.ldr[i + 1])});
      redVsBlue = std::max(redVsBlue, std::abs(plain.ldr[i] - plain.ldr[i + 2]));
    }
    EXPECT_GT(redVsBlue, 100) << "the red sphere makes the swap visible";
    EXPECT_LE(worst, 1);
  }
}

TEST(PostEffects, GradingVariantWithoutALutIsAnErrorNotACrash) {
  ASSERT_TRUE(sphere().frame);
  std::string error;
  facet::runtime::VulkanOptions options;
  options.post = {"aces", false, true};
  auto backend = facet::runtime::createVulkanBackend(options, &error);
  ASSERT_TRUE(backend) << error;
  FrameResult result;
  EXPECT_FALSE(backend->render(sphere().frame->frame(), &result, &error));
  EXPECT_NE(error.find("the post variant grades colour, so the frame needs a colorLut of 32³ RGBA16F texels"),
            std::string::npos)
      << error;
}

// The vignette keeps the centre as it was and scales the corners' encoded value by
// 1 − intensity (|p| = √2 there, past radius + smoothness), on both APIs and both paths.
TEST(PostEffects, VignetteDarkensTheCornersAndNotTheCentre) {
  ASSERT_TRUE(sphere().frame);
  facet::runtime::FrameDesc frame = sphere().frame->frame();
  const uint32_t w = frame.width, h = frame.height;
  frame.postUniforms = facet::runtime::postUniforms({0.6, 0.5, 0.5, 1}, w, h);
  for (Api api : {Api::Vulkan, Api::Gles})
    for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
      SCOPED_TRACE(std::string(api == Api::Vulkan ? "Vulkan " : "GLES ") + facet::runtime::toString(path));
      const FrameResult plain = render(api, {"aces", false}, sphere().frame->frame(), path);
      const FrameResult dark = render(api, {"aces", false, false, true}, frame, path);
      ASSERT_EQ(plain.ldr.size(), size_t(w) * h * 4);
      ASSERT_EQ(plain.ldr.size(), dark.ldr.size());
      auto at = [&](const FrameResult& r, uint32_t x, uint32_t y, int c) {
        return int(r.ldr[(size_t(y) * w + x) * 4 + size_t(c)]);
      };
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(at(dark, w / 2, h / 2, c), at(plain, w / 2, h / 2, c));
        for (auto [x, y] : {std::pair{0u, 0u}, {w - 1, 0u}, {0u, h - 1}, {w - 1, h - 1}}) {
          const int before = at(plain, x, y, c);
          if (c == 0) {
            EXPECT_GT(before, 40) << "a corner bright enough to see the vignette";
          }
          EXPECT_NEAR(at(dark, x, y, c), 0.4 * before, 1.5) << "corner " << x << "," << y;
        }
      }
    }
}

// The example scene that grades, vignettes and dithers, run with its own post variant: the merged
// and separate paths agree within one step on Vulkan and on GLES (validation on). Across APIs the
// forward pass already differs by up to 2 steps (llvmpipe's GLES computes mediump in fp16,
// lavapipe in fp32: test_render_path.cpp), which the grading's contrast and saturation widen to 3.
TEST(PostEffects, GradedExampleSceneGivesTheSameImageOnBothPathsAndBothApis) {
  ASSERT_TRUE(sphere().frame);  // builds the example packages
  std::string error;
  auto scene = facet::runtime::loadScene(facet::test::examplePath("scenes/graded.json"), &error);
  ASSERT_TRUE(scene) << error;
  ASSERT_TRUE(scene->post.colorGrading && scene->post.vignette && scene->post.dither);
  auto frame = facet::runtime::SceneFrame::prepare(*scene, sphere().packages, &error);
  ASSERT_TRUE(frame) << error;
  const FrameResult ungraded = render(Api::Vulkan, {"neutral", true}, frame->frame(), PostPath::Merged);
  for (Api api : {Api::Vulkan, Api::Gles}) {
    SCOPED_TRACE(api == Api::Vulkan ? "Vulkan" : "GLES");
    const FrameResult merged = render(api, scene->post, frame->frame(), PostPath::Merged);
    const FrameResult separate = render(api, scene->post, frame->frame(), PostPath::Separate);
    ASSERT_FALSE(merged.ldr.empty());
    ASSERT_EQ(merged.ldr.size(), separate.ldr.size());
    ASSERT_EQ(merged.ldr.size(), ungraded.ldr.size());
    EXPECT_LE(maxDifference(merged.ldr, separate.ldr), 1);
    EXPECT_GT(maxDifference(merged.ldr, ungraded.ldr), 20) << "the grading shows";
    if (api == Api::Gles) {
      const FrameResult vulkan = render(Api::Vulkan, scene->post, frame->frame(), PostPath::Merged);
      EXPECT_LE(maxDifference(merged.ldr, vulkan.ldr), 3);
    }
  }
}

namespace {

// A full-frame unlit quad whose HDR value rises from `lo` to `hi` across the frame (uv0.x).
struct GradientFrame {
  std::shared_ptr<facet::runtime::Material> material;
  std::unique_ptr<facet::runtime::MaterialInstance> instance;
  facet::runtime::Mesh quad;
  facet::runtime::FrameDesc frame;
};

std::unique_ptr<GradientFrame> slowGradient(uint32_t width, uint32_t height) {
  const std::string packages = facet::test::writePackagesFromTexts(
      "post-gradient",
      {"material gradient { shading unlit\n param lo: float = 0.5 in [0, 16]\n param hi: float = 0.9 in [0, 16]\n"
       " surface { baseColor = vec3(params.lo + (params.hi - params.lo) * vertex.uv0.x) } }"});
  std::string error;
  auto loaded = facet::runtime::LoadedMaterial::load(packages + "/gradient.matpkg", &error);
  EXPECT_TRUE(loaded) << error;
  if (!loaded) return nullptr;
  auto g = std::make_unique<GradientFrame>();
  g->material = facet::runtime::Material::create(std::move(*loaded), {"high", true, 0}, &error);
  EXPECT_TRUE(g->material) << error;
  if (!g->material) return nullptr;
  g->instance = g->material->createInstance();
  for (const auto& c : {std::array<float, 2>{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
    facet::runtime::Vertex v{{c[0], c[1], 0}};
    v.uv0[0] = (c[0] + 1) / 2;
    facet::runtime::appendVertex(g->quad, v);
  }
  g->quad.indices = {0, 1, 2, 0, 2, 3};
  g->frame.width = width;
  g->frame.height = height;
  for (int i = 0; i < 16; ++i) g->frame.frame.viewProjection[i] = i % 5 == 0 ? 1.0f : 0.0f;
  g->frame.draws.push_back(g->instance->draw(g->quad, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}));
  return g;
}

// Per channel: the 8-bit values between the channel's smallest and largest that no pixel has.
std::array<int, 3> emptyBins(const std::vector<uint8_t>& ldr) {
  std::array<int, 3> empty{};
  for (int c = 0; c < 3; ++c) {
    std::array<size_t, 256> histogram{};
    for (size_t i = size_t(c); i < ldr.size(); i += 4) ++histogram[ldr[i]];
    int lo = 0, hi = 255;
    while (lo < 255 && histogram[size_t(lo)] == 0) ++lo;
    while (hi > 0 && histogram[size_t(hi)] == 0) --hi;
    for (int v = lo; v < hi; ++v) empty[size_t(c)] += histogram[size_t(v)] == 0 ? 1 : 0;
  }
  return empty;
}

}  // namespace

// The dithering test, on a full-frame render: the 8-bit histogram of a slow HDR gradient
// (0.5 to 0.9 over 256 columns, no tone curve: 56 output steps, under a quarter step per column)
// has no empty bin between its ends with dithering on. Without dithering it has empty bins when
// the HDR target is R11G11B10F: its 6-bit (red, green) and 5-bit (blue) mantissas step by 2^-7
// and 2^-6 there, 0.9 to 2.6 output steps; triangular noise of ±1 step fills every gap of up to
// two bins. An RGBA16F target steps by 2^-11 (under 0.2 output steps), so its histogram has no
// gap either way: what dithering removes there is the banding of tests/compiler/test_chunks.cpp
// (PostChunks.TriangularDitherRemovesBandingFromASlowGradient), not missing values.
TEST(PostEffects, DitheringLeavesNoEmptyBinInTheHistogramOfASlowGradient) {
  auto gradient = slowGradient(256, 128);
  ASSERT_TRUE(gradient);
  using facet::runtime::HdrFormat;
  for (Api api : {Api::Vulkan, Api::Gles})
    for (HdrFormat format : {HdrFormat::Rgba16Float, HdrFormat::R11G11B10Float})
      for (bool dither : {false, true}) {
        SCOPED_TRACE(std::string(api == Api::Vulkan ? "Vulkan " : "GLES ") + facet::runtime::toString(format) +
                     (dither ? " dithered" : " plain"));
        const FrameResult image = render(api, {"none", dither}, gradient->frame, PostPath::Auto, format);
        ASSERT_EQ(image.ldr.size(), 256u * 128 * 4);
        EXPECT_LT(int(image.ldr[0]) + 40, int(image.ldr[255 * 4])) << "the gradient spans about 56 steps";
        const std::array<int, 3> empty = emptyBins(image.ldr);
        std::printf("%s %s %s: empty bins between the ends r %d, g %d, b %d\n", api == Api::Vulkan ? "Vulkan" : "GLES",
                    facet::runtime::toString(format), dither ? "dithered" : "plain", empty[0], empty[1], empty[2]);
        if (dither || format == HdrFormat::Rgba16Float) {
          EXPECT_EQ(empty, (std::array<int, 3>{0, 0, 0}));
        } else {
          for (int c = 0; c < 3; ++c) EXPECT_GT(empty[size_t(c)], 2) << "channel " << c;
          EXPECT_GT(empty[2], 20) << "blue keeps 5 mantissa bits";
        }
      }
}
