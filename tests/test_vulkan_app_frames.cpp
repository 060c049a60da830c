// The Vulkan backend on an app's own device and images (vulkan_backend.h): the post pass
// writing the app's image, and frames recorded into the app's command buffers. Each test runs
// with validation and synchronization validation on the app's instance; an error fails it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "facet/render_backend.h"
#include "facet/vulkan_backend.h"
#include "vk_test_app_device.h"
#include "vk_test_frames.h"

namespace facet::runtime {
namespace {

using namespace testing;

constexpr Rgba kClear{0.25f, 0.5f, 2.0f, 1.0f};
constexpr Rgba kRed{1.0f, 0.0f, 0.0f, 1.0f};
constexpr Rgba kGreen{0.0f, 1.0f, 0.0f, 1.0f};

// Two overlapping triangles on the clear colour.
struct TestScene {
  Mesh big = triangle({{-1, -1, 0.5f}, {1, -1, 0.5f}, {0, 1, 0.5f}});
  Mesh small = triangle({{-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {-0.5f, 0.5f, 0.0f}});
  FrameDesc frame(const Rgba& smallColour) const {
    FrameDesc f = emptyFrame(24, 16, kClear);
    f.draws.push_back(solidDraw(big, kGreen));
    f.draws.push_back(solidDraw(small, smallColour));
    return f;
  }
};

struct AppFixture {
  TestAppDevice app;
  std::unique_ptr<VulkanRenderer> renderer;

  explicit AppFixture(PostPath path = PostPath::Auto, bool readBackHdr = true, bool stageBufferUploads = false) {
    std::string error;
    if (!app.create(&error)) {
      ADD_FAILURE() << error;
      return;
    }
    VulkanOptions options;
    options.postPath = path;
    options.readBackHdr = readBackHdr;
    options.stageBufferUploads = stageBufferUploads;
    renderer = createVulkanBackend(app.appDevice(), options, &error);
    EXPECT_NE(renderer, nullptr) << error;
  }
  std::vector<uint8_t> renderLdr(const FrameDesc& frame) {
    FrameResult result;
    std::string error;
    EXPECT_TRUE(renderer->render(frame, &result, &error)) << error;
    return result.ldr;
  }
  void expectNoValidationErrors() const {
    EXPECT_TRUE(app.errors().empty()) << app.errors().size() << " validation errors, first: "
                                      << (app.errors().empty() ? "" : app.errors().front());
  }
};

void expectSameImage(const std::vector<uint8_t>& got, const std::vector<uint8_t>& want, const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  int worst = 0;
  for (size_t i = 0; i < got.size(); ++i) worst = std::max(worst, std::abs(int(got[i]) - int(want[i])));
  EXPECT_LE(worst, 1) << what << ": largest difference " << worst << "/255";
}

struct ImageKind {
  const char* name;
  VkFormat format;
  VkImageUsageFlags usage;
  VkImageCreateFlags flags;
};

// Rendered into (UNORM; SRGB viewed as UNORM) and copied into (no COLOR_ATTACHMENT usage): the
// same bytes as render()'s readback, on both render paths.
TEST(VulkanAppImage, PostPassWritesTheAppsImageAsRenderReadsBack) {
  const ImageKind kinds[] = {
      {"UNORM attachment", VK_FORMAT_R8G8B8A8_UNORM,
       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, 0},
      {"SRGB mutable attachment", VK_FORMAT_R8G8B8A8_SRGB,
       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT},
      {"SRGB copy destination", VK_FORMAT_R8G8B8A8_SRGB,
       VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, 0},
  };
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(toString(path));
    AppFixture f(path);
    ASSERT_NE(f.renderer, nullptr);
    TestScene scene;
    const FrameDesc frame = scene.frame(kRed);
    const std::vector<uint8_t> want = f.renderLdr(frame);
    for (const ImageKind& kind : kinds) {
      SCOPED_TRACE(kind.name);
      VkImage image = f.app.createImage(kind.format, frame.width, frame.height, kind.usage, kind.flags);
      ASSERT_NE(image, VK_NULL_HANDLE);
      AppImage target{image, kind.format, frame.width, frame.height, VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kind.usage, kind.flags};
      std::string error;
      // Twice: the second frame reuses the image's cached framebuffer, from the layout the first left.
      ASSERT_TRUE(f.renderer->renderToImage(frame, target, &error)) << error;
      target.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      ASSERT_TRUE(f.renderer->renderToImage(frame, target, &error)) << error;
      expectSameImage(f.app.read(image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, frame.width, frame.height), want,
                      kind.name);
      f.renderer->forgetImage(image);
      f.app.destroyImage(image);
    }
    f.expectNoValidationErrors();
  }
}

TEST(VulkanAppImage, ImageWithoutAttachmentOrTransferUsageIsRefused) {
  AppFixture f;
  ASSERT_NE(f.renderer, nullptr);
  TestScene scene;
  const FrameDesc frame = scene.frame(kRed);
  VkImage image = f.app.createImage(VK_FORMAT_R8G8B8A8_SRGB, frame.width, frame.height,
                                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  ASSERT_NE(image, VK_NULL_HANDLE);
  // _SRGB without MUTABLE_FORMAT cannot take the UNORM view, and it has no TRANSFER_DST either.
  AppImage target{image, VK_FORMAT_R8G8B8A8_SRGB, frame.width, frame.height, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                  VK_IMAGE_USAGE_SAMPLED_BIT};
  std::string error;
  EXPECT_FALSE(f.renderer->renderToImage(frame, target, &error));
  EXPECT_NE(error.find("MUTABLE_FORMAT"), std::string::npos) << error;
  f.expectNoValidationErrors();
}

// What changes between the recorded frames: the small triangle's colour (a persistent material
// block, as a material instance's) and its mesh (edited in place). Frame i's state.
struct ChangingScene {
  TestScene scene;
  UniformBlock block;
  void apply(int i) {
    const Rgba colours[3] = {kRed, {0.1f, 0.2f, 0.9f, 1.0f}, {3.0f, 2.0f, 0.0f, 1.0f}};
    block.bytes = materialBytes(colours[i % 3]);
    block.generation = nextUniformGeneration();
    const float x = i % 2 ? 0.9f : -0.5f;  // the right-angle vertex moves
    scene.small.vertices[0] = x;
  }
  FrameDesc frame() const {
    FrameDesc f = scene.frame(kRed);
    f.draws[1].materialParams.clear();
    f.draws[1].materialBlock = &block;
    return f;
  }
};

// Frames recorded into the app's command buffers, two in flight as the app's fences allow
// (VulkanOptions::framesInFlight = 2), with the material block and a mesh changing every frame:
// each image equals what render() gives for that frame's state, on both render paths, with
// uploads written directly and staged (copies recorded into the app's command buffer), with
// validation and synchronization validation clean.
TEST(VulkanAppFrames, RecordedFramesInFlightMatchRender) {
  constexpr int kFrames = 6;
  for (const auto& [path, staged] : {std::pair{PostPath::Merged, false}, {PostPath::Separate, false},
                                     {PostPath::Merged, true}}) {
    SCOPED_TRACE(std::string(toString(path)) + (staged ? ", staged uploads" : ""));
    AppFixture f(path, /*readBackHdr=*/false, staged);
    ASSERT_NE(f.renderer, nullptr);
    ChangingScene changing;
    std::vector<std::vector<uint8_t>> want;
    {
      std::string error;
      VulkanOptions options;
      options.postPath = path;
      auto reference = createVulkanBackend(f.app.appDevice(), options, &error);
      ASSERT_NE(reference, nullptr) << error;
      for (int i = 0; i < kFrames; ++i) {
        changing.apply(i);
        FrameResult result;
        ASSERT_TRUE(reference->render(changing.frame(), &result, &error)) << error;
        want.push_back(result.ldr);
      }
    }
    const FrameDesc shape = changing.frame();
    VkCommandBuffer cmds[2] = {f.app.allocateCommandBuffer(), f.app.allocateCommandBuffer()};
    VkFence fences[2] = {f.app.createFence(), f.app.createFence()};
    std::vector<VkImage> images;
    for (int i = 0; i < kFrames; ++i) {
      const int ring = i % 2;
      if (i >= 2) {  // the app's side of the rule: frame i - 2 has finished before frame i is recorded
        ASSERT_EQ(vkWaitForFences(f.app.device, 1, &fences[ring], VK_TRUE, UINT64_MAX), VK_SUCCESS);
        ASSERT_EQ(vkResetFences(f.app.device, 1, &fences[ring]), VK_SUCCESS);
      }
      changing.apply(i);
      const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
      images.push_back(f.app.createImage(VK_FORMAT_R8G8B8A8_UNORM, shape.width, shape.height, usage));
      ASSERT_NE(images.back(), VK_NULL_HANDLE);
      const AppImage target{images.back(), VK_FORMAT_R8G8B8A8_UNORM, shape.width, shape.height,
                            VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, usage};
      ASSERT_EQ(vkResetCommandBuffer(cmds[ring], 0), VK_SUCCESS);
      VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
      begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
      ASSERT_EQ(vkBeginCommandBuffer(cmds[ring], &begin), VK_SUCCESS);
      std::string error;
      ASSERT_TRUE(f.renderer->recordFrame(changing.frame(), target, cmds[ring], &error)) << error;
      ASSERT_EQ(vkEndCommandBuffer(cmds[ring]), VK_SUCCESS);
      ASSERT_TRUE(f.app.submit(cmds[ring], fences[ring]));
    }
    ASSERT_EQ(vkWaitForFences(f.app.device, 2, fences, VK_TRUE, UINT64_MAX), VK_SUCCESS);
    for (int i = 0; i < kFrames; ++i) {
      SCOPED_TRACE("frame " + std::to_string(i));
      expectSameImage(f.app.read(images[size_t(i)], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, shape.width, shape.height),
                      want[size_t(i)], "recorded frame");
    }
    // The frames differ from each other, so a frame showing another's state would be caught.
    EXPECT_NE(want[0], want[1]);
    EXPECT_NE(want[1], want[2]);
    EXPECT_EQ(f.renderer->resources().stagedUploadBytes > 0, staged);
    f.expectNoValidationErrors();
  }
}

TEST(VulkanAppFrames, NullCommandBufferIsAnError) {
  AppFixture f;
  ASSERT_NE(f.renderer, nullptr);
  TestScene scene;
  const FrameDesc frame = scene.frame(kRed);
  VkImage image = f.app.createImage(VK_FORMAT_R8G8B8A8_UNORM, frame.width, frame.height,
                                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
  const AppImage target{image, VK_FORMAT_R8G8B8A8_UNORM, frame.width, frame.height, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT};
  std::string error;
  EXPECT_FALSE(f.renderer->recordFrame(frame, target, VK_NULL_HANDLE, &error));
  EXPECT_NE(error.find("command buffer is null"), std::string::npos) << error;
}

}  // namespace
}  // namespace facet::runtime
