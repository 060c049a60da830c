// Render scale: the forward pass renders at scaledSize() of the output and the post pass upscales
// it bilinearly, on the separate path (a subpass cannot change resolution). On both backends the
// output keeps its size, the HDR image has the scaled size and equals the same frame rendered at
// that size, and the output matches that HDR upscaled and encoded on the CPU; scale 1 is today's
// frame; a scale outside 0.5..1 (or NaN) is an error at creation, in the scene and in facet-view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using namespace facet::runtime;

// A lit sphere (smooth shading, a highlight) against a constant sky, at an odd output size.
const char* kMaterial =
    "material red { shading lit\n surface { baseColor = vec3(0.8, 0.1, 0.05)\n metallic = 0.0\n"
    " roughness = 0.4\n reflectance = 0.5 } }";
constexpr uint32_t kWidth = 67;
constexpr uint32_t kHeight = 45;

const std::string& packages() {
  static const std::string dir = facet::test::writePackagesFromTexts("render_scale", {kMaterial});
  return dir;
}

std::unique_ptr<SceneFrame> sceneFrame(std::string* error) {
  const std::string json = R"({"width": )" + std::to_string(kWidth) + R"(, "height": )" + std::to_string(kHeight) +
                           R"(, "tier": "high", "sky": {"luminance": 1000},
  "sun": {"direction": [-0.4, -0.6, -0.7], "illuminance": 60000},
  "camera": {"position": [0, 0, 4], "fovY": 40, "aperture": 16, "shutter": 0.008, "iso": 100},
  "post": {"toneCurve": "none"},
  "objects": [{"material": "red", "radius": 1.2}]})";
  auto scene = parseScene(facet::test::examplePath("scenes/inline.json"), json, error);
  if (!scene) return nullptr;
  return SceneFrame::prepare(*scene, packages(), error);
}

PostSettings noToneCurve() {
  PostSettings post;
  post.toneCurve = "none";
  return post;
}

std::unique_ptr<RenderBackend> vulkan(PostPath path, double scale, std::string* error) {
  VulkanOptions options;
  options.validation = true;
  options.postPath = path;
  options.post = noToneCurve();
  options.renderScale = scale;
  return createVulkanBackend(options, error);
}

std::unique_ptr<RenderBackend> gles(PostPath path, double scale, std::string* error) {
  GlOptions options;
  options.postPath = path;
  options.post = noToneCurve();
  options.renderScale = scale;
  return createGlBackend(options, error);
}

using Factory = std::unique_ptr<RenderBackend> (*)(PostPath, double, std::string*);

double srgbEncode(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  return c < 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// The output the post pass should give: each output pixel's centre mapped into the HDR image
// (u = (x + 0.5) / W · w − 0.5), bilinear between the four nearest texels, clamped to the edge,
// then the "none" tone curve (a clamp) and sRGB encoding, in 8-bit steps. nearest: the texel
// the centre falls in instead (what an unfiltered read would give).
std::vector<double> upscaleOnCpu(const std::vector<float>& hdr, uint32_t w, uint32_t h, uint32_t outW, uint32_t outH,
                                 bool nearest = false) {
  std::vector<double> out(size_t{outW} * outH * 3);
  const auto texel = [&](int x, int y, int c) {
    x = std::clamp(x, 0, int(w) - 1);
    y = std::clamp(y, 0, int(h) - 1);
    return double(hdr[(size_t(y) * w + size_t(x)) * 4 + size_t(c)]);
  };
  for (uint32_t y = 0; y < outH; ++y) {
    for (uint32_t x = 0; x < outW; ++x) {
      const double u = (x + 0.5) / outW * w - 0.5, v = (y + 0.5) / outH * h - 0.5;
      const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
      const double fx = nearest ? std::round(u - x0) : u - x0, fy = nearest ? std::round(v - y0) : v - y0;
      for (int c = 0; c < 3; ++c) {
        const double top = texel(x0, y0, c) * (1 - fx) + texel(x0 + 1, y0, c) * fx;
        const double bottom = texel(x0, y0 + 1, c) * (1 - fx) + texel(x0 + 1, y0 + 1, c) * fx;
        out[(size_t{y} * outW + x) * 3 + size_t(c)] = 255.0 * srgbEncode(top * (1 - fy) + bottom * fy);
      }
    }
  }
  return out;
}

// On both backends, from either requested path: the output has the output's size, HDR the
// scaled size (rounded: 67 × 45 at 0.5 is 34 × 23), equal to the same frame rendered at 34 × 23
// with no scale, and the 8-bit output is that HDR upscaled on the CPU. Tolerance: rounding to
// 8 bits is half a step; the GPUs' bilinear weights are fixed point (8 fractional bits on
// llvmpipe, off by up to 2^-9 of the step between two texels) and filter fp16 values, which adds
// a fraction of a step where neighbours differ most (the silhouette). Measured worst: 0.50 steps
// on lavapipe, 0.74 on llvmpipe's GL (printed); the bound is 1 step. An unfiltered read (the
// nearest texel) is several steps off on the silhouette and the shading: checked too, so the
// scene can tell the two apart.
TEST(RenderScale, TheForwardPassRendersSmallerAndThePostPassUpscalesBilinearly) {
  std::string error;
  auto prepared = sceneFrame(&error);
  ASSERT_TRUE(prepared) << error;
  for (Factory make : {&vulkan, &gles}) {
    for (PostPath requested : {PostPath::Merged, PostPath::Separate}) {
      auto scaled = make(requested, 0.5, &error);
      ASSERT_TRUE(scaled) << error;
      EXPECT_EQ(scaled->postPath(), PostPath::Separate);
      EXPECT_EQ(scaled->renderScale(), 0.5);
      FrameResult result;
      ASSERT_TRUE(scaled->render(prepared->frame(), &result, &error)) << error;
      EXPECT_EQ(result.width, kWidth);
      EXPECT_EQ(result.height, kHeight);
      ASSERT_EQ(result.ldr.size(), size_t{kWidth} * kHeight * 4);
      ASSERT_EQ(result.hdrWidth, 34u);
      ASSERT_EQ(result.hdrHeight, 23u);
      ASSERT_EQ(result.hdr.size(), size_t{34} * 23 * 4);

      // The same frame (same projection) into a 34 × 23 target at scale 1.
      auto small = make(PostPath::Separate, 1.0, &error);
      ASSERT_TRUE(small) << error;
      FrameDesc frame = prepared->frame();
      frame.width = 34;
      frame.height = 23;
      FrameResult reference;
      ASSERT_TRUE(small->render(frame, &reference, &error)) << error;
      EXPECT_EQ(reference.hdr, result.hdr) << scaled->name();

      const std::vector<double> expected = upscaleOnCpu(reference.hdr, 34, 23, kWidth, kHeight);
      double worst = 0, sum = 0;
      for (size_t p = 0; p < size_t{kWidth} * kHeight; ++p) {
        for (size_t c = 0; c < 3; ++c) {
          const double d = std::abs(double(result.ldr[p * 4 + c]) - expected[p * 3 + c]);
          worst = std::max(worst, d);
          sum += d;
        }
      }
      const double mean = sum / (double(kWidth) * kHeight * 3);
      std::printf("%s, %s requested: worst %.2f steps, mean %.3f steps from the CPU upscale\n", scaled->name(),
                  toString(requested), worst, mean);
      EXPECT_LE(worst, 1.0) << scaled->name();
      EXPECT_LE(mean, 0.3) << scaled->name();
      const std::vector<double> unfiltered = upscaleOnCpu(reference.hdr, 34, 23, kWidth, kHeight, true);
      double nearestWorst = 0;
      for (size_t i = 0; i < unfiltered.size(); ++i)
        nearestWorst = std::max(nearestWorst, std::abs(unfiltered[i] - expected[i]));
      EXPECT_GT(nearestWorst, 4.0) << "the scene cannot tell a bilinear upscale from a nearest one";
      EXPECT_TRUE(scaled->validationErrors().empty());
      for (const std::string& e : scaled->validationErrors()) ADD_FAILURE() << e;
      EXPECT_TRUE(small->validationErrors().empty());
    }
  }
}

// Scale 1 is the frame of a backend given no scale: the same path (merged stays merged) and the
// same bytes, HDR and output.
TEST(RenderScale, ScaleOneIsTheUnscaledFrame) {
  std::string error;
  auto prepared = sceneFrame(&error);
  ASSERT_TRUE(prepared) << error;
  for (Factory make : {&vulkan, &gles}) {
    auto one = make(PostPath::Merged, 1.0, &error);
    ASSERT_TRUE(one) << error;
    EXPECT_EQ(one->postPath(), PostPath::Merged);
    FrameResult a, b;
    ASSERT_TRUE(one->render(prepared->frame(), &a, &error)) << error;
    auto upscaledButWhole = make(PostPath::Separate, 1.0, &error);
    ASSERT_TRUE(upscaledButWhole) << error;
    ASSERT_TRUE(upscaledButWhole->render(prepared->frame(), &b, &error)) << error;
    EXPECT_EQ(a.hdrWidth, kWidth);
    EXPECT_EQ(a.hdrHeight, kHeight);
    EXPECT_EQ(a.hdr, b.hdr) << one->name();
    EXPECT_EQ(a.ldr, b.ldr) << one->name();
  }
}

// Sizes that round: 1 × 1 stays 1 × 1 at 0.5, an odd 0.75 of 101 × 33 is 76 × 25, and the
// output keeps its size.
TEST(RenderScale, OddSizesRoundAndStayAtLeastOnePixel) {
  EXPECT_EQ(scaledSize(1, 0.5), 1u);
  EXPECT_EQ(scaledSize(101, 0.75), 76u);
  EXPECT_EQ(scaledSize(33, 0.75), 25u);
  EXPECT_EQ(scaledSize(1920, 1.0), 1920u);
  std::string error;
  auto prepared = sceneFrame(&error);
  ASSERT_TRUE(prepared) << error;
  for (Factory make : {&vulkan, &gles}) {
    auto backend = make(PostPath::Auto, 0.75, &error);
    ASSERT_TRUE(backend) << error;
    for (auto [w, h] : {std::pair<uint32_t, uint32_t>{101, 33}, {1, 1}, {3, 2}}) {
      FrameDesc frame = prepared->frame();
      frame.width = w;
      frame.height = h;
      FrameResult result;
      ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
      EXPECT_EQ(result.width, w);
      EXPECT_EQ(result.height, h);
      EXPECT_EQ(result.ldr.size(), size_t{w} * h * 4);
      EXPECT_EQ(result.hdrWidth, scaledSize(w, 0.75));
      EXPECT_EQ(result.hdrHeight, scaledSize(h, 0.75));
    }
    EXPECT_TRUE(backend->validationErrors().empty());
    for (const std::string& e : backend->validationErrors()) ADD_FAILURE() << e;
  }
}

// The frame graph: at 0.5 the merged path becomes the separate one, HDR is stored and sampled at
// a quarter of its bytes, depth stays transient and LDR keeps the output's size.
TEST(RenderScale, TheFrameGraphStoresAndSamplesTheSmallerHdr) {
  fg::CompiledGraph compiled;
  std::string error;
  const ForwardPostGraph g =
      buildForwardPostGraph(1920, 1080, PostPath::Merged, false, HdrFormat::Rgba16Float, 1, false, 0.5);
  ASSERT_TRUE(g.graph.compile(&compiled, &error)) << error;
  EXPECT_EQ(compiled.renderPasses.size(), 2u);
  EXPECT_EQ(g.graph.resource(g.hdr).width, 960u);
  EXPECT_EQ(g.graph.resource(g.hdr).height, 540u);
  EXPECT_EQ(compiled.traffic[g.hdr].storedBytes, 960u * 540u * 8u);
  EXPECT_EQ(compiled.traffic[g.hdr].sampledBytes, 960u * 540u * 8u);
  EXPECT_TRUE(compiled.traffic[g.depth].transient);
  EXPECT_EQ(compiled.traffic[g.ldr].storedBytes, 1920u * 1080u * 4u);
  EXPECT_EQ(compiled.storedBytes(), 960u * 540u * 8u + 1920u * 1080u * 4u);
  // At 1 the merged path is today's: one render pass, HDR transient.
  fg::CompiledGraph whole;
  const ForwardPostGraph one = buildForwardPostGraph(1920, 1080, PostPath::Merged, false);
  ASSERT_TRUE(one.graph.compile(&whole, &error)) << error;
  EXPECT_EQ(whole.renderPasses.size(), 1u);
  EXPECT_TRUE(whole.traffic[one.hdr].transient);
  EXPECT_EQ(effectivePostPath(PostPath::Merged, 0.75), PostPath::Separate);
  EXPECT_EQ(effectivePostPath(PostPath::Merged, 1.0), PostPath::Merged);
}

TEST(RenderScale, AScaleOutsideItsRangeIsAnErrorAtCreation) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double scale : {0.49, 1.01, 0.0, -1.0, nan}) {
    std::string error;
    EXPECT_FALSE(vulkan(PostPath::Auto, scale, &error));
    EXPECT_NE(error.find("VulkanOptions::renderScale must be in 0.5..1, not "), std::string::npos) << error;
    error.clear();
    EXPECT_FALSE(gles(PostPath::Auto, scale, &error));
    EXPECT_NE(error.find("GlOptions::renderScale must be in 0.5..1, not "), std::string::npos) << error;
  }
  EXPECT_EQ(renderScaleError("x", nan), "x must be in 0.5..1, not nan");
}

TEST(RenderScale, TheSceneNamesItAndItsErrorsTheirPointer) {
  std::string error;
  auto scene = parseScene("s.json", R"({"renderScale": 0.75, "objects": []})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_EQ(scene->renderScale, 0.75);
  auto defaulted = parseScene("s.json", R"({"objects": []})", &error);
  ASSERT_TRUE(defaulted) << error;
  EXPECT_EQ(defaulted->renderScale, 1.0);
  const std::pair<const char*, const char*> bad[] = {
      {"0.25", "s.json: error: /renderScale: value 0.25 is outside [0.5, 1.0]"},
      {"1.5", "s.json: error: /renderScale: value 1.5 is outside [0.5, 1.0]"},
      {"\"half\"", "s.json: error: /renderScale: expected a number"},
  };
  for (const auto& [value, message] : bad) {
    error.clear();
    EXPECT_FALSE(parseScene("s.json", std::string(R"({"renderScale": )") + value + R"(, "objects": []})", &error))
        << value;
    EXPECT_NE(error.find(message), std::string::npos) << error;
  }
}

}  // namespace
