// Tests of the Vulkan backend (runtime/vulkan/) on whatever device the machine has; on CI and
// developer machines that is Mesa's lavapipe. A missing Vulkan driver is a failure, not a skip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "facet/abi/shader_abi.h"
#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/vulkan_backend.h"

#include "vk_test_frames.h"

namespace facet::runtime {
namespace {

using namespace testing;

std::unique_ptr<RenderBackend> makeBackend(bool validation = false, bool stageBufferUploads = false) {
  std::string error;
  VulkanOptions options;
  options.validation = validation;
  options.stageBufferUploads = stageBufferUploads;
  auto backend = createVulkanBackend(options, &error);
  EXPECT_NE(backend, nullptr) << "createVulkanBackend failed: " << error;
  return backend;
}

FrameResult renderOrFail(RenderBackend& backend, const FrameDesc& frame) {
  FrameResult result;
  std::string error;
  EXPECT_TRUE(backend.render(frame, &result, &error)) << error;
  EXPECT_EQ(result.width, frame.width);
  EXPECT_EQ(result.height, frame.height);
  EXPECT_EQ(result.hdr.size(), size_t{frame.width} * frame.height * 4);
  EXPECT_EQ(result.ldr.size(), size_t{frame.width} * frame.height * 4);
  return result;
}

// Row 0 is the top of the picture.
Rgba hdrAt(const FrameResult& result, uint32_t row, uint32_t col) {
  const float* p = &result.hdr[(size_t{row} * result.width + col) * 4];
  return {p[0], p[1], p[2], p[3]};
}

void expectHdr(const FrameResult& result, uint32_t row, uint32_t col, const Rgba& want) {
  const Rgba got = hdrAt(result, row, col);
  EXPECT_EQ(got.r, want.r) << "red at row " << row << " col " << col;
  EXPECT_EQ(got.g, want.g) << "green at row " << row << " col " << col;
  EXPECT_EQ(got.b, want.b) << "blue at row " << row << " col " << col;
  EXPECT_EQ(got.a, want.a) << "alpha at row " << row << " col " << col;
}

// What templates/post_tonemap.frag.glsl computes (chunks/tonemap_aces.glsl, chunks/srgb.glsl).
uint8_t expectedLdr(float hdr) {
  const float x = std::clamp(hdr, 0.0f, 160.0f);
  const float mapped = std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
  const float srgb = mapped < 0.0031308f ? mapped * 12.92f : 1.055f * std::pow(mapped, 1.0f / 2.4f) - 0.055f;
  return static_cast<uint8_t>(std::lround(srgb * 255.0f));
}

// All values are exactly representable in fp16, so the HDR readback must equal them.
constexpr Rgba kClear{0.25f, 0.5f, 2.0f, 1.0f};
constexpr Rgba kRed{1.0f, 0.0f, 0.0f, 1.0f};
constexpr Rgba kGreen{0.0f, 1.0f, 0.0f, 1.0f};
constexpr Rgba kBlue{0.0f, 0.0f, 0.75f, 0.5f};
constexpr Rgba kBlack{0.0f, 0.0f, 0.0f, 1.0f};

TEST(VulkanBackend, ClearColourReachesHdrAndLdrTargets) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);
  EXPECT_STREQ(backend->name(), "vulkan");
  // Not square, so a swapped width and height shows.
  FrameResult result = renderOrFail(*backend, emptyFrame(8, 5, kClear));
  ASSERT_EQ(result.hdr.size(), 8u * 5u * 4u);
  const uint8_t want[4] = {expectedLdr(kClear.r), expectedLdr(kClear.g), expectedLdr(kClear.b), 255};
  for (uint32_t row = 0; row < 5; ++row) {
    for (uint32_t col = 0; col < 8; ++col) {
      expectHdr(result, row, col, kClear);
      for (int c = 0; c < 4; ++c) {
        const int got = result.ldr[(size_t{row} * 8 + col) * 4 + c];
        EXPECT_NEAR(got, want[c], 1) << "channel " << c << " at row " << row << " col " << col;
      }
    }
  }
}

// A shadow pass the device cannot draw or that reads out of bounds is refused with what is wrong
// (the pass itself is tested in tests/shadow_reference/test_vulkan_shadows.cpp).
TEST(VulkanBackend, AMalformedShadowPassIsRefused) {
  auto backend = makeBackend(true);
  ASSERT_NE(backend, nullptr);
  FrameDesc frame = emptyFrame(8, 5, kClear);
  frame.shadow = ShadowPassDesc{};
  frame.shadow->atlasSize = 256;
  frame.shadow->cascades.resize(1);
  ShadowCascadeDesc& cascade = frame.shadow->cascades[0];
  cascade.viewport[2] = 256;
  cascade.viewport[3] = 256;
  FrameResult result;
  std::string error;
  EXPECT_TRUE(backend->render(frame, &result, &error)) << error;  // an empty pass: the atlas cleared
  cascade.casters = {0};
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_EQ(error, "shadow cascade 0: caster 0 is out of range (0 casters)");
  cascade.casters.clear();
  cascade.viewport[0] = 1;
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_EQ(error, "shadow cascade 0: viewport is outside the 256 texel atlas");
  cascade.viewport[0] = 0;
  frame.shadow->atlasSize = 0;
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_EQ(error.rfind("shadow atlas size 0 is outside 1..", 0), 0u) << error;
  EXPECT_TRUE(backend->validationErrors().empty());
}

TEST(VulkanBackend, TriangleCoversExpectedPixelsUpright) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);
  // The triangle's right angle sits at the origin; model moves it to (-1, 1) and the
  // view-projection halves x and y, so in OpenGL clip space it spans x in [-0.5, 0],
  // y in [0, 0.5] with the right angle at the upper left: the upper-left quadrant's
  // lower-right part, in a 32×32 image pixels 8..15 both ways, top-left at (row 8, col 8).
  const Mesh mesh = triangle({{0, 0, 0}, {1, 0, 0}, {0, -1, 0}});
  FrameDesc frame = emptyFrame(32, 32, kBlack);
  frame.frame.viewProjection[0] = 0.5f;
  frame.frame.viewProjection[5] = 0.5f;
  DrawItem draw = solidDraw(mesh, kRed);
  draw.instances[0].rows[0][3] = -1.0f;  // translation: the rows' last column
  draw.instances[0].rows[1][3] = 1.0f;
  frame.draws.push_back(draw);
  FrameResult result = renderOrFail(*backend, frame);
  ASSERT_EQ(result.hdr.size(), 32u * 32u * 4u);

  expectHdr(result, 9, 9, kRed);      // near the right angle: upper left of the triangle
  expectHdr(result, 9, 13, kRed);     // along the top edge
  expectHdr(result, 13, 9, kRed);     // along the left edge
  expectHdr(result, 14, 14, kBlack);  // beyond the hypotenuse
  // Mirror images of (9, 9) in each other quadrant stay clear: no flip in x or y.
  expectHdr(result, 22, 9, kBlack);
  expectHdr(result, 9, 22, kBlack);
  expectHdr(result, 22, 22, kBlack);
  // Counted coverage: about half of the 8×8 block.
  int covered = 0;
  for (uint32_t row = 0; row < 32; ++row) {
    for (uint32_t col = 0; col < 32; ++col) {
      const bool red = hdrAt(result, row, col).r == 1.0f;
      covered += red;
      if (red) {
        EXPECT_TRUE(row >= 8 && row < 16 && col >= 8 && col < 16)
            << "red outside the expected block at row " << row << " col " << col;
      }
    }
  }
  EXPECT_GE(covered, 28);
  EXPECT_LE(covered, 36);
  // The post pass sees the same orientation.
  EXPECT_NEAR(result.ldr[(9 * 32 + 9) * 4 + 0], expectedLdr(1.0f), 1);
  EXPECT_EQ(result.ldr[(22 * 32 + 9) * 4 + 0], 0);
}

TEST(VulkanBackend, MaterialParamsReachFragmentShader) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);
  // Three vertical strips, each its own draw: red, blue, and one with no parameter bytes,
  // which must read zeros.
  const Mesh left = triangle({{-1, -1, 0}, {-1, 3, 0}, {-0.5f, -1, 0}});
  const Mesh middle = triangle({{-0.25f, -1, 0}, {-0.25f, 3, 0}, {0.25f, -1, 0}});
  const Mesh right = triangle({{0.5f, -1, 0}, {0.5f, 3, 0}, {1, -1, 0}});
  FrameDesc frame = emptyFrame(16, 16, kGreen);
  frame.draws.push_back(solidDraw(left, kRed));
  frame.draws.push_back(solidDraw(middle, kBlue));
  DrawItem empty = solidDraw(right, kRed);
  empty.materialParams.clear();
  frame.draws.push_back(empty);
  FrameResult result = renderOrFail(*backend, frame);
  ASSERT_EQ(result.hdr.size(), 16u * 16u * 4u);
  expectHdr(result, 15, 0, kRed);
  expectHdr(result, 15, 7, kBlue);
  expectHdr(result, 15, 13, Rgba{0, 0, 0, 0});
  expectHdr(result, 15, 10, kGreen);  // between the strips: the clear colour

  // A second frame with new parameters must not see the old ones.
  frame.draws[0].materialParams = materialBytes(kBlue);
  FrameResult second = renderOrFail(*backend, frame);
  ASSERT_EQ(second.hdr.size(), 16u * 16u * 4u);
  expectHdr(second, 15, 0, kBlue);
}

TEST(VulkanBackend, DepthTestKeepsNearestSurface) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);
  // OpenGL clip z: -0.9 is near the near plane (and would be clipped away if the backend did
  // not remap z from [-w, w] to [0, w]); 0.5 is farther.
  const Mesh nearMesh = fullScreenTriangle(-0.9f);
  const Mesh farMesh = fullScreenTriangle(0.5f);
  for (bool nearFirst : {false, true}) {
    SCOPED_TRACE(nearFirst ? "near drawn first" : "far drawn first");
    FrameDesc frame = emptyFrame(8, 8, kBlack);
    if (nearFirst) frame.draws.push_back(solidDraw(nearMesh, kRed));
    frame.draws.push_back(solidDraw(farMesh, kGreen));
    if (!nearFirst) frame.draws.push_back(solidDraw(nearMesh, kRed));
    FrameResult result = renderOrFail(*backend, frame);
    ASSERT_EQ(result.hdr.size(), 8u * 8u * 4u);
    for (uint32_t row = 0; row < 8; row += 7) {
      for (uint32_t col = 0; col < 8; col += 7) expectHdr(result, row, col, kRed);
    }
  }
  // Depth is cleared to the far plane: a surface just in front of it is drawn.
  FrameDesc frame = emptyFrame(4, 4, kBlack);
  const Mesh farthest = fullScreenTriangle(0.999f);
  frame.draws.push_back(solidDraw(farthest, kGreen));
  FrameResult result = renderOrFail(*backend, frame);
  ASSERT_EQ(result.hdr.size(), 4u * 4u * 4u);
  expectHdr(result, 2, 2, kGreen);
}

TEST(VulkanBackend, ValidationReportsNoErrors) {
  auto backend = makeBackend(/*validation=*/true);
  ASSERT_NE(backend, nullptr);
  const Mesh nearMesh = fullScreenTriangle(-0.5f);
  const Mesh farMesh = triangle({{-1, -1, 0.5f}, {1, -1, 0.5f}, {0, 1, 0.5f}});
  FrameDesc frame = emptyFrame(24, 16, kClear);
  frame.draws.push_back(solidDraw(farMesh, kGreen));
  frame.draws.push_back(solidDraw(nearMesh, kRed));
  DrawItem noParams = solidDraw(farMesh, kBlue);
  noParams.materialParams.clear();
  frame.draws.push_back(noParams);
  renderOrFail(*backend, frame);
  // A second frame at another size recreates the targets; a third reuses everything.
  frame.width = 7;
  frame.height = 9;
  renderOrFail(*backend, frame);
  renderOrFail(*backend, frame);
  // Many draws: the descriptor pool and the frame arena grow.
  for (int i = 0; i < 100; ++i) frame.draws.push_back(solidDraw(farMesh, kGreen));
  renderOrFail(*backend, frame);
  EXPECT_TRUE(backend->validationErrors().empty())
      << backend->validationErrors().size()
      << " errors, first: " << (backend->validationErrors().empty() ? "" : backend->validationErrors().front());
}

// A grid of `count` objects of 2x2 pixels sharing one mesh, each with its own persistent
// material block (as material instances have), green or red.
struct Grid {
  static constexpr uint32_t kColumns = 50;
  uint32_t rows;
  float cellW = 2.0f / kColumns, cellH;
  Mesh cell;  // one cell-sized square at the clip-space origin, two triangles
  std::vector<UniformBlock> blocks;
  FrameDesc frame;

  explicit Grid(uint32_t count) : rows(count / kColumns), cellH(2.0f / float(count / kColumns)), blocks(count) {
    for (const auto& p : {std::pair{0.0f, 0.0f}, {cellW, 0.0f}, {cellW, cellH}, {0.0f, cellH}})
      appendVertex(cell, Vertex{{p.first, p.second, 0}});
    cell.indices = {0, 1, 2, 0, 2, 3};
    frame = emptyFrame(2 * kColumns, 2 * rows, kBlack);
    for (uint32_t i = 0; i < count; ++i) {
      DrawItem draw = solidDraw(cell, colour(i));
      blocks[i] = {draw.materialParams, nextUniformGeneration()};
      draw.materialParams.clear();
      draw.materialBlock = &blocks[i];
      draw.instances[0].rows[0][3] = -1.0f + float(i % kColumns) * cellW;
      draw.instances[0].rows[1][3] = -1.0f + float(i / kColumns) * cellH;
      frame.draws.push_back(draw);
    }
  }
  static Rgba colour(uint32_t i) { return i % 3 == 0 ? kGreen : kRed; }
};

// 2,000 objects sharing one mesh: one mesh buffer on the device, uploaded once across frames,
// and every object drawn where its own transform puts it with its own colour. A mesh edited in
// place is uploaded again. Their 2,000 material blocks are sub-allocated: the backend makes as
// many vkAllocateMemory calls for 2,000 objects as for 50.
TEST(VulkanBackend, TwoThousandDrawsShareOneMeshBuffer) {
  auto backend = makeBackend(/*validation=*/true);
  ASSERT_NE(backend, nullptr);
  Grid grid(2000);
  const uint32_t kColumns = Grid::kColumns, kRows = grid.rows;
  Mesh& cell = grid.cell;
  const float cellW = grid.cellW;
  const FrameDesc& frame = grid.frame;
  FrameResult result = renderOrFail(*backend, frame);
  renderOrFail(*backend, frame);
  EXPECT_EQ(backend->resources().meshBuffers, 1u);
  EXPECT_EQ(backend->resources().meshUploads, 1u);
  EXPECT_EQ(backend->resources().materialBuffers, 2000u);
  {
    auto small = makeBackend();
    ASSERT_NE(small, nullptr);
    Grid few(50);
    renderOrFail(*small, few.frame);
    renderOrFail(*small, few.frame);
    EXPECT_EQ(backend->resources().memoryAllocations, small->resources().memoryAllocations);
    // Targets, readback buffers, frame arenas, the dummy texture, one block of buffers.
    EXPECT_LE(backend->resources().memoryAllocations, 12u);
  }
  for (uint32_t i = 0; i < kColumns * kRows; ++i) {
    // Cell row r (from the bottom in clip space) covers image rows from the top 2(kRows-1-r)..+1.
    const uint32_t row = 2 * (kRows - 1 - i / kColumns), col = 2 * (i % kColumns);
    const Rgba want = Grid::colour(i);
    const Rgba got = hdrAt(result, row, col);
    ASSERT_TRUE(got.r == want.r && got.g == want.g) << "object " << i << " at row " << row << " col " << col;
  }
  // Edited in place: same address, new bytes.
  cell.vertices[0] = -cellW;
  renderOrFail(*backend, frame);
  EXPECT_EQ(backend->resources().meshBuffers, 1u);
  EXPECT_EQ(backend->resources().meshUploads, 2u);
  EXPECT_TRUE(backend->validationErrors().empty())
      << (backend->validationErrors().empty() ? "" : backend->validationErrors().front());
}

// A pipeline is kept while draws ask for it and destroyed after kEvictAfterFrames frames without
// one, through the retire queue: an app (or matc tune) that makes a new ShaderProgram for each
// frame holds a bounded number of pipelines, one drawn every frame is built once, and a program
// drawn again after its pipeline went is built again and draws as before.
TEST(VulkanBackend, PipelinesOfProgramsNoLongerDrawnAreReleased) {
  auto backend = makeBackend(/*validation=*/true);
  ASSERT_NE(backend, nullptr);
  const Mesh left = triangle({{-1, -1, 0}, {-1, 3, 0}, {-0.5f, -1, 0}});
  const Mesh right = triangle({{0.5f, -1, 0}, {0.5f, 3, 0}, {1, -1, 0}});
  // Kept alive, so each frame's program has an address of its own.
  std::vector<std::unique_ptr<ShaderProgram>> programs;
  const auto frameWith = [&](const ShaderProgram& program) {
    FrameDesc frame = emptyFrame(16, 16, kBlack);
    frame.draws.push_back(solidDraw(left, kRed));
    frame.draws.push_back(solidDraw(right, kBlue));
    frame.draws.back().program = &program;
    return frame;
  };
  constexpr uint64_t kFrames = 3 * kEvictAfterFrames;
  for (uint64_t i = 0; i < kFrames; ++i) {
    programs.push_back(std::make_unique<ShaderProgram>(solidProgram()));
    renderOrFail(*backend, frameWith(*programs.back()));
    EXPECT_LE(backend->resources().programs, kEvictAfterFrames + 1) << "frame " << i;
  }
  EXPECT_EQ(backend->resources().programBuilds, kFrames + 1);  // the left strip's once
  const FrameResult again = renderOrFail(*backend, frameWith(*programs.front()));
  EXPECT_EQ(backend->resources().programBuilds, kFrames + 2);
  expectHdr(again, 15, 0, kRed);
  expectHdr(again, 15, 13, kBlue);
  EXPECT_TRUE(backend->validationErrors().empty())
      << (backend->validationErrors().empty() ? "" : backend->validationErrors().front());
}

// Meshes and material blocks uploaded through a staging copy into device-local memory (the
// discrete-GPU path, forced on lavapipe) draw exactly what direct writes draw, including a
// block changed between frames, with validation clean.
TEST(VulkanBackend, StagedUploadsDrawWhatDirectWritesDraw) {
  auto direct = makeBackend(/*validation=*/true);
  auto staged = makeBackend(/*validation=*/true, /*stageBufferUploads=*/true);
  ASSERT_NE(direct, nullptr);
  ASSERT_NE(staged, nullptr);
  Grid grid(200);
  for (int frame = 0; frame < 2; ++frame) {
    if (frame == 1) {  // one instance changes colour: a new block, staged again
      grid.blocks[7].bytes = materialBytes(kBlue);
      grid.blocks[7].generation = nextUniformGeneration();
    }
    const FrameResult want = renderOrFail(*direct, grid.frame);
    const FrameResult got = renderOrFail(*staged, grid.frame);
    EXPECT_EQ(got.hdr, want.hdr) << "frame " << frame;
  }
  EXPECT_GT(staged->resources().stagedUploadBytes, 0u);
  EXPECT_EQ(staged->resources().materialUploads, 201u);
  for (const auto* backend : {direct.get(), staged.get()}) {
    EXPECT_TRUE(backend->validationErrors().empty())
        << (backend->validationErrors().empty() ? "" : backend->validationErrors().front());
  }
}

// The app's device: an incomplete one is refused with a message, not used.
TEST(VulkanBackend, IncompleteAppDeviceIsAnError) {
  std::string error;
  EXPECT_EQ(createVulkanBackend(AppDevice{}, VulkanOptions{}, &error), nullptr);
  EXPECT_NE(error.find("the app's Vulkan device is incomplete"), std::string::npos) << error;
}

TEST(VulkanBackend, InvalidFrameFailsWithMessage) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);
  FrameResult result;
  std::string error;
  EXPECT_FALSE(backend->render(emptyFrame(0, 4, kBlack), &result, &error));
  EXPECT_NE(error.find("frame size"), std::string::npos) << error;

  Mesh broken = fullScreenTriangle(0.0f);
  broken.indices = {0, 1, 7};
  FrameDesc frame = emptyFrame(4, 4, kBlack);
  frame.draws.push_back(solidDraw(broken, kRed));
  error.clear();
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;

  ShaderProgram noSpirv;
  frame.draws[0].mesh = &broken;
  broken.indices = {0, 1, 2};
  frame.draws[0].program = &noSpirv;
  error.clear();
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_NE(error.find("SPIR-V"), std::string::npos) << error;

  // The backend still works after failures.
  frame.draws[0].program = &solidProgram();
  FrameResult good = renderOrFail(*backend, frame);
  ASSERT_EQ(good.hdr.size(), 4u * 4u * 4u);
  expectHdr(good, 0, 0, kRed);
}

}  // namespace
}  // namespace facet::runtime
