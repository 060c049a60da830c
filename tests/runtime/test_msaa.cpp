// MSAA on both backends and both post paths: a resolved silhouette has values between the
// surface and the background (one sample per pixel has none), a sample count the device does not
// offer is an error at creation, a masked material's alpha-tested edge resolves by alpha to
// coverage, and Vulkan's portable merged path tone maps each sample before averaging. Vulkan
// validation (with synchronization validation) and GL debug output stay clean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "facet/runtime/png.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using namespace facet::runtime;

// An unlit white sphere (HDR 1.0 exactly) against a constant sky: every pixel is the surface, the
// background, or (MSAA) a resolved mix of the two on the silhouette. The masked one's alpha is a
// triangle wave across the diagonal: stripes about 5 pixels wide whose edges are alpha-tested.
const char* kMaterials[] = {
    "material white { shading unlit\n surface { baseColor = vec3(1.0, 1.0, 1.0) } }",
    "material stripes { shading unlit\n blending masked(0.5)\n doubleSided\n"
    " surface { baseColor = vec3(1.0, 1.0, 1.0)\n"
    " alpha = abs(fract((vertex.worldPosition.x + vertex.worldPosition.y) * 1.5) * 2.0 - 1.0) } }",
    "material hot { shading unlit\n surface { baseColor = vec3(50.0, 50.0, 50.0) } }",
};

// Per-sample tone mapping against resolve-first on thin_edges.json, PSNR against 16 samples:
// measured 39.14 against 38.77 dB on lavapipe (tools/measure_msaa.cpp); the bound keeps half.
constexpr double kPerSampleGainBoundDb = 0.18;

std::string sceneJson(const std::string& material) {
  return R"({"width": 64, "height": 64, "tier": "high", "sky": {"luminance": 1000},
  "camera": {"position": [0, 0, 4], "fovY": 40, "aperture": 16, "shutter": 0.008, "iso": 100},
  "objects": [{"material": ")" +
         material + R"(", "radius": 1.2}]})";
}

const std::string& packages() {
  static const std::string dir =
      facet::test::writePackagesFromTexts("msaa", {kMaterials[0], kMaterials[1], kMaterials[2]});
  return dir;
}

bool render(RenderBackend& backend, const std::string& material, FrameResult* out, std::string* error,
            uint32_t width = 64, uint32_t height = 64) {
  auto scene = parseScene(facet::test::examplePath("scenes/inline.json"), sceneJson(material), error);
  if (!scene) return false;
  scene->width = width;
  scene->height = height;
  auto frame = SceneFrame::prepare(*scene, packages(), error);
  return frame && backend.render(frame->frame(), out, error);
}

// Pixels whose red HDR value lies strictly between the background's and the surface's (by more
// than RGBA16F's rounding), inside the frame's central square of side `side`.
struct Mix {
  int between = 0;
  int total = 0;
};
Mix countBetween(const FrameResult& r, float background, float surface, uint32_t side) {
  Mix mix;
  const uint32_t from = (r.width - side) / 2;
  for (uint32_t y = from; y < from + side; ++y) {
    for (uint32_t x = from; x < from + side; ++x) {
      const float v = r.hdr[(size_t{y} * r.width + x) * 4];
      const float lo = std::min(background, surface), hi = std::max(background, surface);
      const float margin = 0.02f * (hi - lo);
      mix.between += v > lo + margin && v < hi - margin;
      ++mix.total;
    }
  }
  return mix;
}

// The same for the 8-bit output: strictly between the two end values by more than a step.
int countBetweenLdr(const FrameResult& r, uint8_t background, uint8_t surface) {
  int between = 0;
  const int lo = std::min(background, surface), hi = std::max(background, surface);
  for (size_t i = 0; i < r.ldr.size(); i += 4) between += r.ldr[i] > lo + 1 && r.ldr[i] < hi - 1;
  return between;
}

std::unique_ptr<RenderBackend> vulkanWith(PostPath path, uint32_t samples, bool renderToSingleSampled,
                                          std::string* error, bool toneMapSamples = true) {
  VulkanOptions options;
  options.validation = true;
  options.postPath = path;
  options.msaaSamples = samples;
  options.renderToSingleSampled = renderToSingleSampled;
  options.toneMapSamples = toneMapSamples;
  return createVulkanBackend(options, error);
}

std::unique_ptr<RenderBackend> vulkan(PostPath path, uint32_t samples, std::string* error) {
  return vulkanWith(path, samples, true, error);
}

// The portable form: explicit multisampled attachments resolved by pResolveAttachments, forced
// where VK_EXT_multisampled_render_to_single_sampled is offered (lavapipe offers it).
std::unique_ptr<RenderBackend> vulkanPortable(PostPath path, uint32_t samples, std::string* error) {
  return vulkanWith(path, samples, false, error);
}

std::unique_ptr<RenderBackend> gles(PostPath path, uint32_t samples, std::string* error) {
  GlOptions options;
  options.postPath = path;
  options.msaaSamples = samples;
  return createGlBackend(options, error);
}

using Factory = std::unique_ptr<RenderBackend> (*)(PostPath, uint32_t, std::string*);

// Every backend and path: at 1 sample the silhouette is a hard step (no value between sky and
// surface); at 4 samples it is resolved (values between, in HDR and in the 8-bit output).
TEST(Msaa, AResolvedSilhouetteHasIntermediateValuesOnEveryBackendAndPath) {
  for (Factory make : {&vulkan, &vulkanPortable, &gles}) {
    for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
      std::string error;
      auto one = make(path, 1, &error);
      ASSERT_TRUE(one) << error;
      auto four = make(path, 4, &error);
      ASSERT_TRUE(four) << error;
      SCOPED_TRACE(std::string(four->name()) + " " + toString(path) + " " + four->msaaMethod());
      EXPECT_EQ(four->msaaSamples(), 4u);
      EXPECT_EQ(four->postPath(), path);
      FrameResult a, b;
      ASSERT_TRUE(render(*one, "white", &a, &error)) << error;
      ASSERT_TRUE(render(*four, "white", &b, &error)) << error;
      ASSERT_FALSE(a.hdr.empty());
      ASSERT_FALSE(b.hdr.empty());
      const float background = a.hdr[0];  // a corner: the sky
      const float surface = a.hdr[(32 * 64 + 32) * 4];
      ASSERT_NEAR(surface, 1.0f, 1e-3f);
      ASSERT_LT(background, 0.5f);
      const Mix hard = countBetween(a, background, surface, 64);
      const Mix soft = countBetween(b, background, surface, 64);
      EXPECT_EQ(hard.between, 0);
      // The silhouette of a circle 2·1.2/(2·tan 20°)·32 ≈ 53 pixels across: about π·53 ≈ 166
      // pixels, most of them partly covered.
      EXPECT_GT(soft.between, 80) << "of " << soft.total;
      const uint8_t skyLdr = a.ldr[0], whiteLdr = a.ldr[(32 * 64 + 32) * 4];
      EXPECT_EQ(countBetweenLdr(a, skyLdr, whiteLdr), 0);
      EXPECT_GT(countBetweenLdr(b, skyLdr, whiteLdr), 80);
      // Away from edges MSAA changes nothing: the centre and the corner are the same value.
      EXPECT_NEAR(b.hdr[(32 * 64 + 32) * 4], surface, 1e-3f);
      EXPECT_NEAR(b.hdr[0], background, 1e-3f);
      EXPECT_TRUE(one->validationErrors().empty());
      EXPECT_TRUE(four->validationErrors().empty());
      for (const std::string& e : four->validationErrors()) ADD_FAILURE() << e;
    }
  }
}

// Both Vulkan forms, on both paths: the extension where the device offers it (lavapipe does) and
// the portable fallback, forced, render the same image (the same standard 4-sample pattern) when
// both resolve first. The extension's form and the separate path never tone map per sample.
TEST(Msaa, VulkanRendersTheSameWithTheExtensionAndWithoutIt) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(toString(path));
    std::string error;
    auto extension = vulkan(path, 4, &error);
    ASSERT_TRUE(extension) << error;
    auto portable = vulkanWith(path, 4, false, &error, false);
    ASSERT_TRUE(portable) << error;
    EXPECT_FALSE(extension->toneMapsSamples());
    EXPECT_FALSE(portable->toneMapsSamples());
    FrameResult a, b;
    ASSERT_TRUE(render(*extension, "white", &a, &error)) << error;
    ASSERT_TRUE(render(*portable, "white", &b, &error)) << error;
    EXPECT_NE(portable->msaaMethod().find("pResolveAttachments"), std::string::npos) << portable->msaaMethod();
    if (extension->msaaMethod().find("VK_EXT_multisampled_render_to_single_sampled") == std::string::npos) {
      ADD_FAILURE() << "lavapipe offers VK_EXT_multisampled_render_to_single_sampled, not used: "
                    << extension->msaaMethod();
    }
    ASSERT_EQ(a.ldr.size(), b.ldr.size());
    int worst = 0;
    for (size_t i = 0; i < a.ldr.size(); ++i) worst = std::max(worst, std::abs(int(a.ldr[i]) - int(b.ldr[i])));
    EXPECT_LE(worst, 1);
    for (const std::string& e : extension->validationErrors()) ADD_FAILURE() << e;
    for (const std::string& e : portable->validationErrors()) ADD_FAILURE() << e;
  }
}

// The mobile path (HDR not read back): the resolved HDR and both multisampled attachments are
// transient, and the 8-bit output is that of the path that reads HDR back.
TEST(Msaa, TheMobilePathGivesTheSameImage) {
  std::string error;
  VulkanOptions options;
  options.validation = true;
  options.msaaSamples = 4;
  for (bool renderToSingleSampled : {true, false}) {
    options.renderToSingleSampled = renderToSingleSampled;
    options.readBackHdr = true;
    auto readBack = createVulkanBackend(options, &error);
    ASSERT_TRUE(readBack) << error;
    options.readBackHdr = false;
    auto mobile = createVulkanBackend(options, &error);
    ASSERT_TRUE(mobile) << error;
    FrameResult a, b;
    ASSERT_TRUE(render(*readBack, "white", &a, &error)) << error;
    ASSERT_TRUE(render(*mobile, "white", &b, &error)) << error;
    EXPECT_TRUE(b.hdr.empty());
    EXPECT_EQ(a.ldr, b.ldr);
    for (const std::string& e : mobile->validationErrors()) ADD_FAILURE() << e;
  }
}

// Per-sample tone mapping on the portable form's merged path, on tests/data/scenes/thin_edges.json
// (bright specular spheres against a dark sky, rows of 3-pixel and 1-pixel spheres): closer to 16
// tone-mapped samples per pixel (the scene at 4x the width and height, each 4x4 block averaged in
// linear light) than the same 4 samples resolved first. Measured on lavapipe: see the bound.
// Fails when the post subpass reads the resolve (the image is then the resolve-first one).
TEST(Msaa, ThePortableMergedPathToneMapsEachSampleCloserToTheReference) {
  std::string error;
  std::vector<std::string> texts;
  for (const char* name : {"red_plastic", "brushed_gold", "banded_ceramic"})
    texts.push_back(facet::test::readText(facet::test::examplePath(std::string("materials/") + name + ".mat")));
  const std::string dir = facet::test::writePackagesFromTexts("msaa_thin_edges", texts);
  auto scene = loadScene(facet::test::sourceDir() + "/tests/data/scenes/thin_edges.json", &error);
  ASSERT_TRUE(scene) << error;
  const auto draw = [&](RenderBackend& backend, uint32_t scale, FrameResult* out) {
    Scene big = *scene;
    big.width *= scale;
    big.height *= scale;
    auto frame = SceneFrame::prepare(big, dir, &error);
    return frame && backend.render(frame->frame(), out, &error);
  };
  auto one = vulkan(PostPath::Merged, 1, &error);
  ASSERT_TRUE(one) << error;
  auto perSample = vulkanWith(PostPath::Merged, 4, false, &error, true);
  ASSERT_TRUE(perSample) << error;
  auto resolveFirst = vulkanWith(PostPath::Merged, 4, false, &error, false);
  ASSERT_TRUE(resolveFirst) << error;
  EXPECT_TRUE(perSample->toneMapsSamples()) << perSample->msaaMethod();
  EXPECT_NE(perSample->msaaMethod().find("subpassInputMS"), std::string::npos) << perSample->msaaMethod();
  FrameResult big, a, b;
  ASSERT_TRUE(draw(*one, 4, &big)) << error;
  ASSERT_TRUE(draw(*perSample, 1, &a)) << error;
  ASSERT_TRUE(draw(*resolveFirst, 1, &b)) << error;
  // The reference: each 4x4 block of the 8-bit output decoded from sRGB, averaged, encoded.
  const auto decode = [](int v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const auto encode = [](double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    return c < 0.0031308 ? c * 12.92 * 255.0 : (1.055 * std::pow(c, 1.0 / 2.4) - 0.055) * 255.0;
  };
  ASSERT_EQ(a.ldr.size(), b.ldr.size());
  ASSERT_EQ(big.width, a.width * 4);
  const auto psnr = [&](const FrameResult& r) {
    double squares = 0;
    size_t n = 0;
    for (uint32_t y = 0; y < r.height; ++y)
      for (uint32_t x = 0; x < r.width; ++x)
        for (int ch = 0; ch < 3; ++ch) {
          double sum = 0;
          for (uint32_t j = 0; j < 4; ++j)
            for (uint32_t i = 0; i < 4; ++i)
              sum += decode(big.ldr[((size_t{y} * 4 + j) * big.width + x * 4 + i) * 4 + ch]);
          const double d = std::round(encode(sum / 16)) - r.ldr[(size_t{y} * r.width + x) * 4 + ch];
          squares += d * d;
          ++n;
        }
    return 10 * std::log10(255.0 * 255.0 / (squares / double(n)));
  };
  const double perSampleDb = psnr(a), resolveFirstDb = psnr(b);
  std::printf("PSNR against 16 samples: tone-mapped per sample %.2f dB, resolved first %.2f dB\n", perSampleDb,
              resolveFirstDb);
  EXPECT_GT(perSampleDb, resolveFirstDb + kPerSampleGainBoundDb);
  for (const std::string& e : perSample->validationErrors()) ADD_FAILURE() << e;
  for (const std::string& e : resolveFirst->validationErrors()) ADD_FAILURE() << e;
}

// An HDR edge: a surface of HDR 50 against the sky. Resolved first, a pixel a quarter covered
// averages to 12.5, which ACES maps to white, so the silhouette steps from sky to white as at one
// sample; tone-mapped per sample it takes a quarter, half, three quarters of white in display
// light. Vulkan's portable merged path tone maps per sample; the extension's form resolves first.
TEST(Msaa, PerSampleToneMappingAntialiasesAnHdrEdge) {
  std::string error;
  auto one = vulkan(PostPath::Merged, 1, &error);
  ASSERT_TRUE(one) << error;
  auto perSample = vulkanWith(PostPath::Merged, 4, false, &error, true);
  ASSERT_TRUE(perSample) << error;
  auto resolveFirst = vulkan(PostPath::Merged, 4, &error);
  ASSERT_TRUE(resolveFirst) << error;
  FrameResult sharp, a, b;
  ASSERT_TRUE(render(*one, "hot", &sharp, &error)) << error;
  ASSERT_TRUE(render(*perSample, "hot", &a, &error)) << error;
  ASSERT_TRUE(render(*resolveFirst, "hot", &b, &error)) << error;
  ASSERT_NEAR(sharp.hdr[(32 * 64 + 32) * 4], 50.0f, 0.1f);
  const uint8_t sky = sharp.ldr[0], white = sharp.ldr[(32 * 64 + 32) * 4];
  ASSERT_EQ(white, 255);
  // Between the sky and 240 (three quarters of white encodes to about 225).
  const auto between = [&](const FrameResult& r) {
    int n = 0;
    for (size_t i = 0; i < r.ldr.size(); i += 4) n += r.ldr[i] > sky + 1 && r.ldr[i] < 240;
    return n;
  };
  EXPECT_EQ(between(sharp), 0);
  EXPECT_EQ(between(b), 0);
  EXPECT_GT(between(a), 80);  // of about 166 silhouette pixels (see the first test)
  for (const std::string& e : perSample->validationErrors()) ADD_FAILURE() << e;
  for (const std::string& e : resolveFirst->validationErrors()) ADD_FAILURE() << e;
}

std::unique_ptr<RenderBackend> vulkanResolveFirst(PostPath path, uint32_t samples, std::string* error) {
  return vulkanWith(path, samples, false, error, false);
}

// Odd and tiny viewports on every form and path: the multisampled attachments, the resolve and
// the per-sample reads have the frame's own size. At 67 × 45 the silhouette has resolved values
// (none at 1 sample); 3 × 2 and 1 × 1 render; no validation error.
TEST(Msaa, OddAndTinySizesRenderOnEveryFormAndPath) {
  for (Factory make : {&vulkan, &vulkanPortable, &vulkanResolveFirst, &gles}) {
    for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
      std::string error;
      auto one = make(path, 1, &error);
      ASSERT_TRUE(one) << error;
      auto four = make(path, 4, &error);
      ASSERT_TRUE(four) << error;
      for (auto [w, h] : {std::pair<uint32_t, uint32_t>{67, 45}, {3, 2}, {1, 1}}) {
        SCOPED_TRACE(std::string(four->name()) + " " + toString(path) + " " + four->msaaMethod() + " " +
                     std::to_string(w) + "x" + std::to_string(h));
        FrameResult a, b;
        ASSERT_TRUE(render(*one, "white", &a, &error, w, h)) << error;
        ASSERT_TRUE(render(*four, "white", &b, &error, w, h)) << error;
        ASSERT_EQ(b.width, w);
        ASSERT_EQ(b.height, h);
        ASSERT_EQ(b.ldr.size(), size_t{w} * h * 4);
        if (w == 67) {
          const uint8_t sky = a.ldr[0], white = a.ldr[(22 * 67 + 33) * 4];
          EXPECT_EQ(countBetweenLdr(a, sky, white), 0);
          EXPECT_GT(countBetweenLdr(b, sky, white), 40);  // a silhouette about 37 pixels across
        }
      }
      for (const std::string& e : four->validationErrors()) ADD_FAILURE() << e;
      for (const std::string& e : one->validationErrors()) ADD_FAILURE() << e;
    }
  }
}

// Counts that are not 1, 2 or 4, and counts the device does not offer, fail creation with a
// message naming the count, never a validation error.
TEST(Msaa, AnUnsupportedSampleCountIsAnError) {
  std::string error;
  EXPECT_FALSE(vulkan(PostPath::Auto, 3, &error));
  EXPECT_NE(error.find("must be 1, 2 or 4, not 3"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(gles(PostPath::Auto, 8, &error));
  EXPECT_NE(error.find("must be 1, 2 or 4, not 8"), std::string::npos) << error;
  // lavapipe offers 1 and 4 samples (framebufferColorSampleCounts): 2 is refused by name. A
  // device that offers 2 must render with it instead, validation-clean.
  error.clear();
  auto two = vulkan(PostPath::Auto, 2, &error);
  if (two) {
    FrameResult frame;
    EXPECT_TRUE(render(*two, "white", &frame, &error)) << error;
    for (const std::string& e : two->validationErrors()) ADD_FAILURE() << e;
    return;
  }
  EXPECT_NE(error.find("MSAA 2x is not offered by this device"), std::string::npos) << error;
  EXPECT_NE(error.find("sample counts offered: 1, 4"), std::string::npos) << error;
}

// Alpha to coverage: the stripes' alpha-tested edges cross the middle of the sphere, where no
// silhouette is. With one sample each pixel there is surface or sky; with four, the edge pixels
// keep a fraction of their samples (fractional coverage) and resolve between the two. Fails
// without either half: alpha 1 written (no coverage) or alpha to coverage off (all samples kept).
TEST(Msaa, AlphaToCoverageGivesAMaskedEdgeFractionalCoverage) {
  for (Factory make : {&vulkan, &vulkanPortable, &gles}) {
    std::string error;
    auto one = make(PostPath::Auto, 1, &error);
    ASSERT_TRUE(one) << error;
    auto four = make(PostPath::Auto, 4, &error);
    ASSERT_TRUE(four) << error;
    SCOPED_TRACE(four->name());
    FrameResult a, b;
    ASSERT_TRUE(render(*one, "stripes", &a, &error)) << error;
    ASSERT_TRUE(render(*four, "stripes", &b, &error)) << error;
    if (std::getenv("MSAA_DEBUG")) {
      writePng(std::string("/tmp/a2c_") + four->name() + "_1.png", a.width, a.height, a.ldr, &error);
      writePng(std::string("/tmp/a2c_") + four->name() + "_4.png", b.width, b.height, b.ldr, &error);
    }
    const float background = a.hdr[0];
    // The centre 24×24 pixels lie inside the silhouette (radius ≈ 26 pixels).
    const Mix hard = countBetween(a, background, 1.0f, 24);
    const Mix soft = countBetween(b, background, 1.0f, 24);
    EXPECT_EQ(hard.between, 0);
    // About five stripe edges cross the square diagonally: over 100 edge pixels.
    EXPECT_GT(soft.between, 40) << "of " << soft.total;
    int surfacePixels = 0;
    for (size_t i = 0; i < a.hdr.size(); i += 4) surfacePixels += std::abs(a.hdr[i] - 1.0f) < 1e-3f;
    EXPECT_GT(surfacePixels, 300);  // the stripes are drawn, not all discarded
    EXPECT_TRUE(four->validationErrors().empty());
    for (const std::string& e : four->validationErrors()) ADD_FAILURE() << e;
  }
}

// The scene's "antialiasing": {"msaa": N, "fxaa": bool}: 1, 2 or 4 samples, FXAA on or off,
// errors at their JSON pointer.
TEST(Msaa, TheSceneNamesTheSampleCountAndFxaa) {
  const auto parse = [](const std::string& antialiasing, std::string* error) {
    return parseScene("s.json", R"({"antialiasing": )" + antialiasing + R"(, "objects": []})", error);
  };
  std::string error;
  auto four = parse(R"({"msaa": 4})", &error);
  ASSERT_TRUE(four) << error;
  EXPECT_EQ(four->msaaSamples, 4u);
  auto defaulted = parseScene("s.json", R"({"objects": []})", &error);
  ASSERT_TRUE(defaulted) << error;
  EXPECT_EQ(defaulted->msaaSamples, 1u);
  EXPECT_FALSE(four->fxaa);
  EXPECT_FALSE(defaulted->fxaa);
  auto both = parse(R"({"msaa": 4, "fxaa": true})", &error);
  ASSERT_TRUE(both) << error;
  EXPECT_EQ(both->msaaSamples, 4u);
  EXPECT_TRUE(both->fxaa);
  const std::pair<const char*, const char*> bad[] = {
      {R"({"msaa": 3})", "s.json: error: /antialiasing/msaa: expected 1, 2 or 4 samples, not 3"},
      {R"({"msaa": 8})", "s.json: error: /antialiasing/msaa: value 8 is outside [1.0, 4.0]"},
      {R"({"msaa": 2.5})", "s.json: error: /antialiasing/msaa: expected a whole number, not 2.5"},
      {R"({"taa": true})", "s.json: error: /antialiasing/taa: unknown key 'taa'"},
      {R"({"fxaa": 1})", "s.json: error: /antialiasing/fxaa: expected true or false"},
      {R"("4x")", "s.json: error: /antialiasing: expected an object"},
  };
  for (const auto& [text, message] : bad) {
    error.clear();
    EXPECT_FALSE(parse(text, &error)) << text;
    EXPECT_NE(error.find(message), std::string::npos) << error;
  }
}

}  // namespace
