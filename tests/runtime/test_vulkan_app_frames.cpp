// The Vulkan backend on an app's own device and images (vulkan_backend.h): the post pass
// writing the app's image, and frames recorded into the app's command buffers. Each test runs
// with validation and synchronization validation on the app's instance; an error fails it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "app_vulkan.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/vulkan_backend.h"
#include "vk_test_frames.h"

namespace facet::runtime {
namespace {

using namespace testing;
using example::AppTarget;
using example::AppVulkan;

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

// The app's device (examples/app/app_vulkan.h) with validation and synchronization validation.
struct AppFixture {
  AppVulkan app;
  std::unique_ptr<VulkanRenderer> renderer;

  explicit AppFixture(PostPath path = PostPath::Auto, bool readBackHdr = true, bool stageBufferUploads = false,
                      uint32_t msaaSamples = 1, bool fxaa = false, double renderScale = 1.0, bool bloom = false) {
    std::string error;
    if (!app.create(/*validation=*/true, &error)) {
      ADD_FAILURE() << error;
      return;
    }
    VulkanOptions options;
    options.postPath = path;
    options.readBackHdr = readBackHdr;
    options.stageBufferUploads = stageBufferUploads;
    options.msaaSamples = msaaSamples;
    options.fxaa = fxaa;
    options.renderScale = renderScale;
    options.post.bloom = bloom;
    options.bloom = {0.3, 5, 0.5};
    renderer = createVulkanBackend(app.appDevice(), options, &error);
    EXPECT_NE(renderer, nullptr) << error;
  }
  std::vector<uint8_t> renderLdr(const FrameDesc& frame) {
    FrameResult result;
    std::string error;
    EXPECT_TRUE(renderer->render(frame, &result, &error)) << error;
    return result.ldr;
  }
  // An image of the app's the test reads back.
  std::unique_ptr<AppTarget> image(VkFormat format, uint32_t width, uint32_t height, VkImageUsageFlags usage,
                                   VkImageCreateFlags flags = 0) {
    auto target = std::make_unique<AppTarget>();
    std::string error;
    EXPECT_TRUE(target->create(app, format, width, height, usage, flags, &error)) << error;
    return target;
  }
  std::vector<uint8_t> read(AppTarget& target) {
    std::vector<uint8_t> rgba;
    std::string error;
    EXPECT_TRUE(target.read(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, &rgba, &error)) << error;
    return rgba;
  }
  void expectNoValidationErrors() const {
    const auto& errors = app.validationErrors;
    EXPECT_TRUE(errors.empty()) << errors.size()
                                << " validation errors, first: " << (errors.empty() ? "" : errors.front());
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
// same bytes as render()'s readback, on both render paths, without and with MSAA (the app's
// image then shares the framebuffer with the multisampled attachments).
TEST(VulkanAppImage, PostPassWritesTheAppsImageAsRenderReadsBack) {
  const ImageKind kinds[] = {
      {"UNORM attachment", VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, 0},
      {"SRGB mutable attachment", VK_FORMAT_R8G8B8A8_SRGB, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
       VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT},
      {"SRGB copy destination", VK_FORMAT_R8G8B8A8_SRGB, VK_IMAGE_USAGE_TRANSFER_DST_BIT, 0},
  };
  for (const auto& [path, samples] : {std::pair{PostPath::Merged, 1u}, std::pair{PostPath::Separate, 1u},
                                      std::pair{PostPath::Merged, 4u}, std::pair{PostPath::Separate, 4u}}) {
    SCOPED_TRACE(std::string(toString(path)) + ", MSAA " + std::to_string(samples));
    AppFixture f(path, true, false, samples);
    ASSERT_NE(f.renderer, nullptr);
    TestScene scene;
    const FrameDesc frame = scene.frame(kRed);
    const std::vector<uint8_t> want = f.renderLdr(frame);
    for (const ImageKind& kind : kinds) {
      SCOPED_TRACE(kind.name);
      auto image = f.image(kind.format, frame.width, frame.height, kind.usage, kind.flags);
      AppImage target = image->describe(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
      std::string error;
      // Twice: the second frame reuses the image's cached framebuffer, from the layout the first left.
      ASSERT_TRUE(f.renderer->renderToImage(frame, target, &error)) << error;
      target.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      ASSERT_TRUE(f.renderer->renderToImage(frame, target, &error)) << error;
      expectSameImage(f.read(*image), want, kind.name);
      f.renderer->forgetImage(image->image);  // before the app destroys it
      image.reset();
    }
    f.expectNoValidationErrors();
  }
}

// Frames into an image of each kind (rendered into where its usage allows, else copied) are the
// bytes of render()'s readback, validation-clean.
void expectAppImagesAreTheReadback(AppFixture& f, std::initializer_list<ImageKind> kinds) {
  TestScene scene;
  const FrameDesc frame = scene.frame(kRed);
  const std::vector<uint8_t> want = f.renderLdr(frame);
  for (const ImageKind& kind : kinds) {
    SCOPED_TRACE(kind.name);
    auto image = f.image(kind.format, frame.width, frame.height, kind.usage, kind.flags);
    AppImage target = image->describe(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    std::string error;
    ASSERT_TRUE(f.renderer->renderToImage(frame, target, &error)) << error;
    target.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    ASSERT_TRUE(f.renderer->renderToImage(frame, target, &error)) << error;
    expectSameImage(f.read(*image), want, kind.name);
    f.renderer->forgetImage(image->image);
    image.reset();
  }
  f.expectNoValidationErrors();
}

// With FXAA the post pass writes the backend's tone-mapped image and the FXAA pass its own
// output, copied into the app's image whatever its usage: the same bytes as render()'s readback.
TEST(VulkanAppImage, WithFxaaTheAppsImageIsRenderReadsBack) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(toString(path));
    AppFixture f(path, false, false, 1, true);
    ASSERT_NE(f.renderer, nullptr);
    EXPECT_TRUE(f.renderer->fxaa());
    expectAppImagesAreTheReadback(
        f, {{"UNORM attachment", VK_FORMAT_R8G8B8A8_UNORM,
             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, 0},
            {"SRGB copy destination", VK_FORMAT_R8G8B8A8_SRGB, VK_IMAGE_USAGE_TRANSFER_DST_BIT, 0}});
  }
}

// With a render scale the post pass upscales into the app's image (rendered into, or copied into):
// the same bytes as render()'s readback, from either requested path (both run the separate one).
TEST(VulkanAppImage, WithARenderScaleTheAppsImageIsRenderReadsBack) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(toString(path));
    AppFixture f(path, false, false, 1, false, 0.5);
    ASSERT_NE(f.renderer, nullptr);
    EXPECT_EQ(f.renderer->postPath(), PostPath::Separate);
    expectAppImagesAreTheReadback(
        f, {{"UNORM attachment", VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, 0},
            {"SRGB copy destination", VK_FORMAT_R8G8B8A8_SRGB, VK_IMAGE_USAGE_TRANSFER_DST_BIT, 0}});
  }
}

// With bloom the chain runs between the forward and the post pass, which writes the app's image
// (rendered into, or copied into): the same bytes as render()'s readback, from either requested
// path (both run the separate one).
TEST(VulkanAppImage, WithBloomTheAppsImageIsRenderReadsBack) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(toString(path));
    AppFixture f(path, false, false, 1, false, 1.0, true);
    ASSERT_NE(f.renderer, nullptr);
    EXPECT_EQ(f.renderer->postPath(), PostPath::Separate);
    EXPECT_EQ(f.renderer->bloomLevels(), 5);
    expectAppImagesAreTheReadback(
        f, {{"UNORM attachment", VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, 0},
            {"SRGB copy destination", VK_FORMAT_R8G8B8A8_SRGB, VK_IMAGE_USAGE_TRANSFER_DST_BIT, 0}});
  }
}

TEST(VulkanAppImage, ImageWithoutAttachmentOrTransferUsageIsRefused) {
  AppFixture f;
  ASSERT_NE(f.renderer, nullptr);
  TestScene scene;
  const FrameDesc frame = scene.frame(kRed);
  auto image = f.image(VK_FORMAT_R8G8B8A8_SRGB, frame.width, frame.height,
                       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
  // _SRGB without MUTABLE_FORMAT cannot take the UNORM view, and it has no TRANSFER_DST either.
  AppImage target = image->describe(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
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
// uploads written directly and staged (copies recorded into the app's command buffer), into
// images rendered to and copied to, with validation and synchronization validation clean.
TEST(VulkanAppFrames, RecordedFramesInFlightMatchRender) {
  constexpr int kFrames = 6;
  struct Run {
    PostPath path;
    bool staged;              // uploads through staging copies recorded into the app's command buffer
    VkImageUsageFlags usage;  // COLOR_ATTACHMENT: rendered into; TRANSFER_DST: copied into
  };
  constexpr VkImageUsageFlags kRendered = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  constexpr VkImageUsageFlags kCopied = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  for (const Run& run : {Run{PostPath::Merged, false, kRendered}, Run{PostPath::Separate, false, kRendered},
                         Run{PostPath::Merged, true, kRendered}, Run{PostPath::Separate, false, kCopied}}) {
    const PostPath path = run.path;
    const bool staged = run.staged;
    SCOPED_TRACE(std::string(toString(path)) + (staged ? ", staged uploads" : "") +
                 (run.usage == kCopied ? ", copied" : ""));
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
    // The app's frame loop (AppVulkan::recordAndSubmit): before recording frame i it waits for
    // the fence of frame i - 2, the rule for VulkanOptions::framesInFlight = 2. Frame i + 1 is
    // recorded and submitted while frame i may still run.
    std::vector<std::unique_ptr<AppTarget>> images;
    for (int i = 0; i < kFrames; ++i) {
      changing.apply(i);
      images.push_back(f.image(VK_FORMAT_R8G8B8A8_UNORM, shape.width, shape.height, run.usage));
      const AppImage target = images.back()->describe(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
      std::string error;
      ASSERT_TRUE(f.app.recordAndSubmit(*f.renderer, changing.frame(), target, i, &error)) << error;
    }
    ASSERT_TRUE(f.app.waitIdle());
    for (int i = 0; i < kFrames; ++i) {
      SCOPED_TRACE("frame " + std::to_string(i));
      expectSameImage(f.read(*images[size_t(i)]), want[size_t(i)], "recorded frame");
    }
    // The frames differ from each other, so a frame showing another's state would be caught.
    EXPECT_NE(want[0], want[1]);
    EXPECT_NE(want[1], want[2]);
    EXPECT_EQ(f.renderer->resources().stagedUploadBytes > 0, staged);
    f.expectNoValidationErrors();
  }
}

// Frames that go straight into the app's image need no LDR target of the backend's own; a later
// render() (which reads one back) adds it, and both give the same image.
TEST(VulkanAppFrames, RenderAfterRecordedFramesGivesTheSameImage) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(toString(path));
    AppFixture f(path);
    ASSERT_NE(f.renderer, nullptr);
    TestScene scene;
    const FrameDesc frame = scene.frame(kRed);
    auto image = f.image(VK_FORMAT_R8G8B8A8_UNORM, frame.width, frame.height, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
    const AppImage target = image->describe(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    std::string error;
    ASSERT_TRUE(f.app.recordAndSubmit(*f.renderer, frame, target, 0, &error)) << error;
    ASSERT_TRUE(f.app.recordAndSubmit(*f.renderer, frame, target, 1, &error)) << error;
    const std::vector<uint8_t> rendered = f.renderLdr(frame);  // after both submissions, on the same queue
    expectSameImage(f.read(*image), rendered, "recorded, then rendered");
    f.expectNoValidationErrors();
  }
}

TEST(VulkanAppFrames, NullCommandBufferIsAnError) {
  AppFixture f;
  ASSERT_NE(f.renderer, nullptr);
  TestScene scene;
  const FrameDesc frame = scene.frame(kRed);
  auto image = f.image(VK_FORMAT_R8G8B8A8_UNORM, frame.width, frame.height, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
  const AppImage target = image->describe(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  std::string error;
  EXPECT_FALSE(f.renderer->recordFrame(frame, target, VK_NULL_HANDLE, &error));
  EXPECT_NE(error.find("command buffer is null"), std::string::npos) << error;
}

}  // namespace
}  // namespace facet::runtime
