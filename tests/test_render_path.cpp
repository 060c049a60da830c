// The two Vulkan render paths on every example scene: the merged one (post pass as subpass 1
// reading its own pixel through an input attachment; HDR and depth transient) and the separate
// fallback (post samples the stored HDR texture) give the same image, with validation (including
// synchronization validation) reporting nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "facet/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "test_support.h"

namespace {

using namespace facet::runtime;

struct Backend {
  const char* label;
  VulkanOptions options;
};

std::vector<std::string> exampleScenes() {
  std::vector<std::string> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(facet::test::examplePath("scenes"))) {
    if (entry.path().extension() == ".json") scenes.push_back(entry.path().string());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

int maxLdrDifference(const FrameResult& a, const FrameResult& b) {
  int worst = 0;
  for (size_t i = 0; i < a.ldr.size(); ++i) worst = std::max(worst, std::abs(int(a.ldr[i]) - int(b.ldr[i])));
  return worst;
}

TEST(RenderPath, AutoChoosesMergedAndSeparateCanBeForced) {
  std::string error;
  auto automatic = createVulkanBackend({true}, &error);
  ASSERT_TRUE(automatic) << error;
  EXPECT_EQ(automatic->postPath(), PostPath::Merged);
  VulkanOptions forced;
  forced.validation = true;
  forced.postPath = PostPath::Separate;
  auto separate = createVulkanBackend(forced, &error);
  ASSERT_TRUE(separate) << error;
  EXPECT_EQ(separate->postPath(), PostPath::Separate);
}

TEST(RenderPath, MergedAndSeparatePathsGiveTheSameImageOnEveryExampleScene) {
  facet::compiler::BuildOptions build;
  build.pointLightCounts = {0, 1, 2, 4};  // what the example scenes use (lamps.json: two)
  const std::string packages = facet::test::writeExamplePackages("render-path-packages", build);
  VulkanOptions separate{true, PostPath::Separate, true};
  VulkanOptions mergedReadBack{true, PostPath::Merged, true};
  VulkanOptions mergedTransient{true, PostPath::Merged, false};  // the mobile path
  std::string error;
  auto separateBackend = createVulkanBackend(separate, &error);
  ASSERT_TRUE(separateBackend) << error;
  auto mergedBackend = createVulkanBackend(mergedReadBack, &error);
  ASSERT_TRUE(mergedBackend) << error;
  auto transientBackend = createVulkanBackend(mergedTransient, &error);
  ASSERT_TRUE(transientBackend) << error;
  EXPECT_FALSE(transientBackend->readsBackHdr());

  const std::vector<std::string> scenes = exampleScenes();
  ASSERT_GE(scenes.size(), 5u);
  for (const std::string& path : scenes) {
    SCOPED_TRACE(path);
    auto scene = loadScene(path, &error);
    ASSERT_TRUE(scene) << error;
    auto frame = SceneFrame::prepare(*scene, packages, &error);
    ASSERT_TRUE(frame) << error;
    FrameResult a, b, c;
    ASSERT_TRUE(separateBackend->render(frame->frame(), &a, &error)) << error;
    ASSERT_TRUE(mergedBackend->render(frame->frame(), &b, &error)) << error;
    ASSERT_TRUE(transientBackend->render(frame->frame(), &c, &error)) << error;
    ASSERT_EQ(a.ldr.size(), b.ldr.size());
    ASSERT_EQ(a.ldr.size(), c.ldr.size());
    ASSERT_FALSE(a.ldr.empty());
    EXPECT_LE(maxLdrDifference(a, b), 1);
    EXPECT_LE(maxLdrDifference(a, c), 1);
    // The forward pass is the same in both paths, so the HDR it stores is too.
    EXPECT_EQ(a.hdr, b.hdr);
    EXPECT_TRUE(c.hdr.empty());
    // Not a blank frame: the scene put something other than the clear colour on screen.
    EXPECT_NE(std::count(c.ldr.begin(), c.ldr.end(), c.ldr[0]), static_cast<std::ptrdiff_t>(c.ldr.size()));
  }
  for (const auto* backend : {separateBackend.get(), mergedBackend.get(), transientBackend.get()}) {
    for (const std::string& message : backend->validationErrors()) ADD_FAILURE() << "Vulkan validation: " << message;
  }
}

}  // namespace
