// An engine's view of Facet: the app owns the Vulkan instance and device, loads one material
// package, makes two instances of it with different parameters, renders a few frames with the
// runtime on its device into its own image (the first frames synchronously, the last ones recorded
// into the app's own command buffers, two in flight), and writes the last one as PNG. It links facet_runtime_core and
// facet_runtime_vulkan only: no GL, no OSMesa, no scene reader (ctest example_app_link_weight).
//
//   facet-app-example <red_plastic.matpkg> <out.png>
//
// Exit status 1 on any error, including a Vulkan validation error when FACET_VK_VALIDATION is set
// (the app enables the layer on its own instance and counts what its messenger receives).
#include <vulkan/vulkan.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "app_vulkan.h"
#include "example_content.h"
#include "facet/runtime/png.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/vulkan_backend.h"

namespace {

using namespace facet::runtime;

using namespace facet::example;

// COLOR_ATTACHMENT: the runtime's post pass writes the image itself (AppTarget adds TRANSFER_SRC
// for its read()).
constexpr VkImageUsageFlags kImageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;

int fail(const std::string& message) {
  std::fprintf(stderr, "facet-app-example: error: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) return fail("usage: facet-app-example <red_plastic.matpkg> <out.png>");
  const char* validationEnv = std::getenv("FACET_VK_VALIDATION");
  const bool validation = validationEnv && *validationEnv && std::strcmp(validationEnv, "0") != 0;
  std::string error;

  // The engine's device. The runtime gets it and destroys none of it.
  AppVulkan vk;
  if (!vk.create(validation, &error)) return fail(error);
  {
    VulkanOptions options;
    options.readBackHdr = false;  // the mobile path: HDR and depth never leave tile memory
    auto renderer = createVulkanBackend(vk.appDevice(), options, &error);
    if (!renderer) return fail(error);

    // One material, made once, from package bytes the app already holds (an asset system, an
    // APK), two instances, a sphere, the sun and a sky: example_content.h, shared with app_gl.
    facet::example::ExampleContent content;
    if (!content.create(argv[1], &error)) return fail(error);
    const uint32_t width = content.kWidth, height = content.kHeight;

    // One sphere mesh, uploaded once, drawn by both instances, into the app's own image.
    AppTarget target;
    if (!target.create(vk, VK_FORMAT_R8G8B8A8_UNORM, width, height, kImageUsage, 0, &error)) return fail(error);
    AppImage image = target.describe(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    for (int i = 0; i < content.kFrames; ++i) {
      // An animated parameter: only `rough`'s block is uploaded again each frame.
      if (!content.animate(i, &error)) return fail(error);
      // The first two frames the runtime submits and waits for; the last two go into the app's
      // command buffers, the second recorded while the first may still run.
      const bool ok = i < 2 ? renderer->renderToImage(content.frame, image, &error)
                            : vk.recordAndSubmit(*renderer, content.frame, image, i, &error);
      if (!ok) return fail(error);
      image.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;  // where the last frame left it
    }
    const ResourceCounts counts = renderer->resources();
    if (std::string wrong = content.checkResources(counts); !wrong.empty()) return fail(wrong);
    std::printf("%llu vkAllocateMemory call(s)\n", static_cast<unsigned long long>(counts.memoryAllocations));
    std::vector<uint8_t> pixels;
    if (!target.read(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, &pixels, &error) ||
        !writePng(argv[2], width, height, pixels, &error)) {
      return fail(error);
    }
    if (std::string wrong = content.checkInstances(pixels); !wrong.empty()) return fail(wrong);
  }
  vk.destroy();  // the runtime is gone: the device reports any object it left behind
  if (!vk.validationErrors.empty()) {
    return fail(std::to_string(vk.validationErrors.size()) + " Vulkan validation error(s)");
  }
  std::printf("wrote %s\n", argv[2]);
  return 0;
}
