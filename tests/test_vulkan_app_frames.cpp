// The Vulkan backend on an app's own device and images (vulkan_backend.h): the post pass
// writing the app's image, and frames recorded into the app's command buffers. Each test runs
// with validation and synchronization validation on the app's instance; an error fails it.
#include <gtest/gtest.h>

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

  explicit AppFixture(PostPath path = PostPath::Auto, bool readBackHdr = true) {
    std::string error;
    if (!app.create(&error)) {
      ADD_FAILURE() << error;
      return;
    }
    VulkanOptions options;
    options.postPath = path;
    options.readBackHdr = readBackHdr;
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

}  // namespace
}  // namespace facet::runtime
