// FXAA on both backends and both post paths: it changes only pixels next to an edge (a pixel
// whose 3×3 neighbourhood is one colour leaves byte-identical), and it turns a hard silhouette
// into one with values between surface and background. Vulkan validation and GL debug output
// stay clean. The frame graph's bytes are in test_frame_graph.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_compile.h"
#include "test_support.h"

namespace {

using namespace facet::runtime;

// An unlit white sphere (HDR 1.0) against a constant sky: without anti-aliasing every pixel is
// one of two colours and the silhouette is a hard step.
const char* kWhite = "material white { shading unlit\n surface { baseColor = vec3(1.0, 1.0, 1.0) } }";
constexpr uint32_t kSize = 64;

bool render(RenderBackend& backend, FrameResult* out, std::string* error, uint32_t width = kSize,
            uint32_t height = kSize) {
  static const std::string packages = facet::test::writePackagesFromTexts("fxaa", {kWhite});
  const std::string json = R"({"width": 64, "height": 64, "tier": "high", "sky": {"luminance": 1000},
  "camera": {"position": [0, 0, 4], "fovY": 40, "aperture": 16, "shutter": 0.008, "iso": 100},
  "objects": [{"material": "white", "radius": 1.2}]})";
  auto scene = parseScene(facet::test::examplePath("scenes/inline.json"), json, error);
  if (!scene) return false;
  scene->width = width;
  scene->height = height;
  auto frame = SceneFrame::prepare(*scene, packages, error);
  return frame && backend.render(frame->frame(), out, error);
}

std::unique_ptr<RenderBackend> vulkan(PostPath path, bool fxaa, std::string* error) {
  VulkanOptions options;
  options.validation = true;
  options.postPath = path;
  options.fxaa = fxaa;
  return createVulkanBackend(options, error);
}

std::unique_ptr<RenderBackend> gles(PostPath path, bool fxaa, std::string* error) {
  GlOptions options;
  options.postPath = path;
  options.fxaa = fxaa;
  return createGlBackend(options, error);
}

using Factory = std::unique_ptr<RenderBackend> (*)(PostPath, bool, std::string*);

const uint8_t* pixel(const FrameResult& r, uint32_t x, uint32_t y) { return &r.ldr[(size_t{y} * r.width + x) * 4]; }

// Every pixel within one of (x, y), clamped to the image, has the colour of (x, y).
bool uniformNeighbourhood(const FrameResult& r, uint32_t x, uint32_t y) {
  for (uint32_t ny = y == 0 ? 0 : y - 1; ny <= std::min(y + 1, r.height - 1); ++ny)
    for (uint32_t nx = x == 0 ? 0 : x - 1; nx <= std::min(x + 1, r.width - 1); ++nx)
      for (int c = 0; c < 3; ++c)
        if (pixel(r, nx, ny)[c] != pixel(r, x, y)[c]) return false;
  return true;
}

TEST(Fxaa, ChangesOnlyEdgePixelsAndSmoothsAHardEdgeOnEveryBackendAndPath) {
  for (Factory make : {&vulkan, &gles}) {
    for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
      std::string error;
      auto off = make(path, false, &error);
      ASSERT_TRUE(off) << error;
      auto on = make(path, true, &error);
      ASSERT_TRUE(on) << error;
      SCOPED_TRACE(std::string(on->name()) + " " + toString(path));
      EXPECT_TRUE(on->fxaa());
      EXPECT_FALSE(off->fxaa());
      EXPECT_EQ(on->postPath(), path);
      FrameResult hard, smooth;
      ASSERT_TRUE(render(*off, &hard, &error)) << error;
      ASSERT_TRUE(render(*on, &smooth, &error)) << error;
      ASSERT_EQ(hard.ldr.size(), size_t{kSize} * kSize * 4);
      ASSERT_EQ(smooth.ldr.size(), hard.ldr.size());
      const uint8_t sky = pixel(hard, 0, 0)[0], white = pixel(hard, 32, 32)[0];
      ASSERT_GT(white, sky + 100);
      int between = 0, changed = 0, interior = 0;
      for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
          const uint8_t* a = pixel(hard, x, y);
          const uint8_t* b = pixel(smooth, x, y);
          ASSERT_TRUE(a[0] == sky || a[0] == white) << x << "," << y;  // a hard step without FXAA
          const bool same = a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
          changed += !same;
          between += b[0] > sky + 1 && b[0] + 1 < white;
          if (uniformNeighbourhood(hard, x, y)) {
            ++interior;
            EXPECT_TRUE(same) << "pixel " << x << "," << y << " away from the edge changed: " << int(a[0]) << " -> "
                              << int(b[0]);
          }
        }
      }
      // The silhouette of a disc about 53 pixels across runs through about π · 53 ≈ 166 pixels;
      // every edge pixel that is not exactly axis-aligned gets blended with its neighbours.
      EXPECT_GT(between, 80) << changed << " changed";
      EXPECT_GT(interior, int(kSize * kSize) / 2);
      for (const std::string& e : on->validationErrors()) ADD_FAILURE() << e;
      for (const std::string& e : off->validationErrors()) ADD_FAILURE() << e;
    }
  }
}

// Odd and tiny viewports: the FXAA pass's taps clamp at the border and its texel size comes from
// the image's own size, so an odd frame is filtered like any other: pixels away from the edge
// stay byte-identical (at 1 × 1 and 3 × 2 every pixel), the silhouette is softened, no
// validation error.
TEST(Fxaa, OddAndTinySizesChangeOnlyEdgePixels) {
  for (Factory make : {&vulkan, &gles}) {
    for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
      std::string error;
      auto off = make(path, false, &error);
      ASSERT_TRUE(off) << error;
      auto on = make(path, true, &error);
      ASSERT_TRUE(on) << error;
      for (auto [w, h] : {std::pair<uint32_t, uint32_t>{67, 45}, {3, 2}, {1, 1}}) {
        SCOPED_TRACE(std::string(on->name()) + " " + toString(path) + " " + std::to_string(w) + "x" +
                     std::to_string(h));
        FrameResult hard, smooth;
        ASSERT_TRUE(render(*off, &hard, &error, w, h)) << error;
        ASSERT_TRUE(render(*on, &smooth, &error, w, h)) << error;
        ASSERT_EQ(smooth.width, w);
        ASSERT_EQ(smooth.height, h);
        ASSERT_EQ(smooth.ldr.size(), hard.ldr.size());
        int changed = 0;
        for (uint32_t y = 0; y < h; ++y) {
          for (uint32_t x = 0; x < w; ++x) {
            const uint8_t* a = pixel(hard, x, y);
            const uint8_t* b = pixel(smooth, x, y);
            const bool same = a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
            changed += !same;
            if (uniformNeighbourhood(hard, x, y)) {
              EXPECT_TRUE(same) << "pixel " << x << "," << y;
            }
          }
        }
        if (w == 67) {
          EXPECT_GT(changed, 40);  // a silhouette about 37 pixels across
        }
      }
      for (const std::string& e : on->validationErrors()) ADD_FAILURE() << e;
      for (const std::string& e : off->validationErrors()) ADD_FAILURE() << e;
    }
  }
}

}  // namespace
