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

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <memory>
#include <string>
#include <vector>

#include "facet/render_backend.h"
#include "facet/runtime/environment.h"
#include "facet/runtime/exposure.h"
#include "facet/runtime/material_instance.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/png.h"
#include "facet/vulkan_backend.h"
#include "app_vulkan.h"

namespace {

using namespace facet::runtime;

using namespace facet::example;

// COLOR_ATTACHMENT: the runtime's post pass writes the image itself (AppTarget adds TRANSFER_SRC
// for its read()).
constexpr VkImageUsageFlags kImageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;

void store(float* dst, const glm::vec3& v, float w = 0) {
  dst[0] = v.x;
  dst[1] = v.y;
  dst[2] = v.z;
  dst[3] = w;
}

std::array<float, 16> modelAt(float x) {
  std::array<float, 16> m{};
  const glm::mat4 model = glm::translate(glm::mat4(1), glm::vec3(x, 0, 0));
  std::memcpy(m.data(), glm::value_ptr(model), sizeof m);
  return m;
}

bool readWholeFile(const char* path, std::vector<uint8_t>* bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

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
    // APK): they must outlive the material; only the variant drawn is decompressed.
    std::vector<uint8_t> packageBytes;
    if (!readWholeFile(argv[1], &packageBytes)) return fail(std::string("cannot read ") + argv[1]);
    auto loaded = LoadedMaterial::loadFromMemory(packageBytes, argv[1], &error);
    if (!loaded) return fail(error);
    auto material = Material::create(std::move(*loaded), {"high", true, 0}, &error);
    if (!material) return fail(error);
    std::printf("package: %zu bytes, %llu decompressed to draw variant %s\n", packageBytes.size(),
                static_cast<unsigned long long>(material->loaded().reader().bytesDecompressed()),
                material->variantKey().c_str());
    auto glossy = material->createInstance();
    auto rough = material->createInstance();
    const auto roughness = material->parameter("roughness");
    if (!roughness) return fail("the material has no 'roughness' parameter");
    if (!glossy->setParameter(*roughness, 0.15f, &error) ||
        !rough->setParameter("baseColor", std::array<float, 3>{0.1f, 0.35f, 0.8f}, &error) ||
        !rough->setParameter(*roughness, 0.7f, &error)) {
      return fail(error);
    }

    // The frame: camera, sun and a constant sky, pre-exposed (docs/lighting-units.md).
    const uint32_t width = 480, height = 240;
    const double exposure = exposureFromEv100(ev100(16, 1.0 / 125, 100));
    FrameDesc frame;
    frame.width = width;
    frame.height = height;
    const glm::vec3 eye(0, 0.4f, 6);
    const glm::mat4 viewProjection = glm::perspective(glm::radians(30.0f), float(width) / height, 0.1f, 100.0f) *
                                     glm::lookAt(eye, glm::vec3(0), glm::vec3(0, 1, 0));
    std::memcpy(frame.frame.viewProjection, glm::value_ptr(viewProjection), sizeof frame.frame.viewProjection);
    store(frame.frame.cameraPosition, eye, 1);
    store(frame.frame.lightDirection, glm::normalize(glm::vec3(0.4f, 0.55f, 0.73f)));
    store(frame.frame.lightColor, glm::vec3(1, 0.96f, 0.9f) * float(110000 * exposure));
    Scene sky;  // only its sky is read: a constant environment of 6000 cd/m²
    sky.skyLuminance = 6000;
    auto lighting = buildEnvironmentLighting(sky, exposure, &error);
    if (!lighting) return fail(error);
    for (size_t k = 0; k < facet::abi::kShCoefficients; ++k)
      for (size_t c = 0; c < 3; ++c) frame.frame.sh[k][c] = lighting->sh[k][c];
    for (int c = 0; c < 3; ++c) frame.clearColor[c] = lighting->meanRadiance[size_t(c)];
    const Texture environment = environmentTexture(*lighting);
    frame.frameTextures.push_back({facet::abi::kEnvironmentBinding, facet::abi::kEnvironmentName, &environment});
    frame.frameTextures.push_back({facet::abi::kDfgLutBinding, facet::abi::kDfgLutName, &dfgTexture()});

    // One sphere mesh, uploaded once, drawn by both instances, into the app's own image.
    const Mesh sphere = makeSphere();
    AppTarget target;
    if (!target.create(vk, VK_FORMAT_R8G8B8A8_UNORM, width, height, kImageUsage, 0, &error)) return fail(error);
    AppImage image = target.describe(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    const int kFrames = 4;
    for (int i = 0; i < kFrames; ++i) {
      // An animated parameter: only `rough`'s block is uploaded again each frame.
      if (!rough->setParameter(*roughness, 0.55f + 0.05f * float(i), &error)) return fail(error);
      frame.draws = {glossy->draw(sphere, modelAt(-1.15f)), rough->draw(sphere, modelAt(1.15f))};
      // The first two frames the runtime submits and waits for; the last two go into the app's
      // command buffers, the second recorded while the first may still run.
      const bool ok = i < 2 ? renderer->renderToImage(frame, image, &error)
                            : vk.recordAndSubmit(*renderer, frame, image, i, &error);
      if (!ok) return fail(error);
      image.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;  // where the last frame left it
    }
    const ResourceCounts counts = renderer->resources();
    std::printf("%d frames %ux%u: %zu mesh buffer(s), %llu mesh upload(s), %zu material block(s), "
                "%llu block upload(s), %llu vkAllocateMemory call(s)\n",
                kFrames, width, height, counts.meshBuffers, static_cast<unsigned long long>(counts.meshUploads),
                counts.materialBuffers, static_cast<unsigned long long>(counts.materialUploads),
                static_cast<unsigned long long>(counts.memoryAllocations));
    // 1 sphere; 2 blocks: both on the first frame, then `rough` once per later frame.
    if (counts.meshBuffers != 1 || counts.meshUploads != 1 || counts.materialBuffers != 2 ||
        counts.materialUploads != uint64_t(2 + kFrames - 1)) {
      return fail("unexpected GPU resource counts");
    }
    std::vector<uint8_t> pixels;
    if (!target.read(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, &pixels, &error) ||
        !writePng(argv[2], width, height, pixels, &error)) {
      return fail(error);
    }
    // The instances differ where it shows: the glossy one is red, the rough one blue (the centres
    // project about 88 pixels either side of the middle).
    const auto at = [&](uint32_t x, uint32_t y) { return &pixels[(size_t(y) * width + x) * 4]; };
    const uint8_t* left = at(width / 2 - 88, height / 2);
    const uint8_t* right = at(width / 2 + 88, height / 2);
    if (!(left[0] > left[2] + 64 && right[2] > right[0] + 64)) {
      return fail("the two instances did not draw as set (left rgb " + std::to_string(left[0]) + "," +
                  std::to_string(left[1]) + "," + std::to_string(left[2]) + ", right " + std::to_string(right[0]) +
                  "," + std::to_string(right[1]) + "," + std::to_string(right[2]) + ")");
    }
  }
  vk.destroy();  // the runtime is gone: the device reports any object it left behind
  if (!vk.validationErrors.empty()) {
    return fail(std::to_string(vk.validationErrors.size()) + " Vulkan validation error(s)");
  }
  std::printf("wrote %s\n", argv[2]);
  return 0;
}
