// An engine's view of Facet: the app owns the Vulkan instance and device, loads one material
// package, makes two instances of it with different parameters, renders a few frames with the
// runtime on its device into its own image, and writes the last one as PNG. It links facet_runtime_core and
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

namespace {

using namespace facet::runtime;

int validationErrors = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL onValidation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                            VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                            void*) {
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    ++validationErrors;
    std::fprintf(stderr, "validation: %s\n", data->pMessage);
  }
  return VK_FALSE;
}

bool layerAvailable(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const VkLayerProperties& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

// The app's own Vulkan objects, as an engine would already have them.
struct AppVulkan {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;

  bool create(bool validation, std::string* error) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "facet-app-example";
    app.apiVersion = VK_API_VERSION_1_1;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = onValidation;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    if (validation) {
      if (!layerAvailable(layer)) {
        *error = "FACET_VK_VALIDATION is set but VK_LAYER_KHRONOS_validation is not installed";
        return false;
      }
      info.enabledLayerCount = 1;
      info.ppEnabledLayerNames = &layer;
      info.enabledExtensionCount = 1;
      info.ppEnabledExtensionNames = &extension;
    }
    if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) {
      *error = "vkCreateInstance failed";
      return false;
    }
    if (validation) {
      auto make = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
      if (!make || make(instance, &messengerInfo, nullptr, &messenger) != VK_SUCCESS) {
        *error = "cannot create the debug messenger";
        return false;
      }
    }
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    for (VkPhysicalDevice candidate : devices) {
      uint32_t families = 0;
      vkGetPhysicalDeviceQueueFamilyProperties(candidate, &families, nullptr);
      std::vector<VkQueueFamilyProperties> props(families);
      vkGetPhysicalDeviceQueueFamilyProperties(candidate, &families, props.data());
      for (uint32_t f = 0; f < families && !physicalDevice; ++f) {
        if (props[f].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
          physicalDevice = candidate;
          queueFamily = f;
        }
      }
    }
    if (!physicalDevice) {
      *error = "no Vulkan device with a graphics queue";
      return false;
    }
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    if (vkCreateDevice(physicalDevice, &deviceInfo, nullptr, &device) != VK_SUCCESS) {
      *error = "vkCreateDevice failed";
      return false;
    }
    vkGetDeviceQueue(device, queueFamily, 0, &queue);
    return true;
  }

  ~AppVulkan() {
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
      if (destroy) destroy(instance, messenger, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

uint32_t memoryType(VkPhysicalDevice physicalDevice, uint32_t typeBits, VkMemoryPropertyFlags flags) {
  VkPhysicalDeviceMemoryProperties props{};
  vkGetPhysicalDeviceMemoryProperties(physicalDevice, &props);
  for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
  return UINT32_MAX;
}

// The engine's own render target (its swapchain image, say) and, to write the PNG, the engine's
// own copy of it into host memory: the runtime renders into the image and reads nothing back.
struct AppTarget {
  const AppVulkan* vk = nullptr;
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory imageMemory = VK_NULL_HANDLE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory bufferMemory = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;

  bool create(const AppVulkan& app, uint32_t width, uint32_t height, std::string* error) {
    vk = &app;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = VK_FORMAT_R8G8B8A8_UNORM;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    VkBufferCreateInfo bufferInfo{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bufferInfo.size = VkDeviceSize(width) * height * 4;
    bufferInfo.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    if (vkCreateImage(app.device, &info, nullptr, &image) != VK_SUCCESS ||
        vkCreateBuffer(app.device, &bufferInfo, nullptr, &buffer) != VK_SUCCESS) {
      *error = "cannot create the app's image";
      return false;
    }
    VkMemoryRequirements imageNeeds{}, bufferNeeds{};
    vkGetImageMemoryRequirements(app.device, image, &imageNeeds);
    vkGetBufferMemoryRequirements(app.device, buffer, &bufferNeeds);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = imageNeeds.size;
    alloc.memoryTypeIndex = memoryType(app.physicalDevice, imageNeeds.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (vkAllocateMemory(app.device, &alloc, nullptr, &imageMemory) != VK_SUCCESS ||
        vkBindImageMemory(app.device, image, imageMemory, 0) != VK_SUCCESS) {
      *error = "cannot allocate the app's image";
      return false;
    }
    alloc.allocationSize = bufferNeeds.size;
    alloc.memoryTypeIndex = memoryType(app.physicalDevice, bufferNeeds.memoryTypeBits,
                                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    if (vkAllocateMemory(app.device, &alloc, nullptr, &bufferMemory) != VK_SUCCESS ||
        vkBindBufferMemory(app.device, buffer, bufferMemory, 0) != VK_SUCCESS) {
      *error = "cannot allocate the app's readback buffer";
      return false;
    }
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.queueFamilyIndex = app.queueFamily;
    if (vkCreateCommandPool(app.device, &poolInfo, nullptr, &pool) != VK_SUCCESS) {
      *error = "cannot create the app's command pool";
      return false;
    }
    return true;
  }

  // The image (left in TRANSFER_SRC_OPTIMAL by renderToImage) into host memory, rows top first.
  bool read(uint32_t width, uint32_t height, std::vector<uint8_t>* rgba, std::string* error) {
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = pool;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    if (vkAllocateCommandBuffers(vk->device, &allocInfo, &cmd) != VK_SUCCESS) {
      *error = "cannot allocate a command buffer";
      return false;
    }
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &begin);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr,
                         0, nullptr);
    vkEndCommandBuffer(cmd);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    if (vkQueueSubmit(vk->queue, 1, &submit, VK_NULL_HANDLE) != VK_SUCCESS || vkQueueWaitIdle(vk->queue) != VK_SUCCESS) {
      *error = "the app's readback failed";
      return false;
    }
    void* mapped = nullptr;
    if (vkMapMemory(vk->device, bufferMemory, 0, VK_WHOLE_SIZE, 0, &mapped) != VK_SUCCESS) {
      *error = "cannot map the app's readback buffer";
      return false;
    }
    rgba->resize(size_t(width) * height * 4);
    std::memcpy(rgba->data(), mapped, rgba->size());
    vkUnmapMemory(vk->device, bufferMemory);
    return true;
  }

  ~AppTarget() {
    if (!vk) return;
    if (pool) vkDestroyCommandPool(vk->device, pool, nullptr);
    if (buffer) vkDestroyBuffer(vk->device, buffer, nullptr);
    if (bufferMemory) vkFreeMemory(vk->device, bufferMemory, nullptr);
    if (image) vkDestroyImage(vk->device, image, nullptr);
    if (imageMemory) vkFreeMemory(vk->device, imageMemory, nullptr);
  }
};

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
  {
    AppVulkan vk;
    if (!vk.create(validation, &error)) return fail(error);
    VulkanOptions options;
    options.readBackHdr = false;  // the mobile path: HDR and depth never leave tile memory
    auto renderer = createVulkanBackend(AppDevice{vk.instance, vk.physicalDevice, vk.device, vk.queueFamily, vk.queue},
                                        options, &error);
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
    const Texture environment = environmentTexture(*lighting);
    setEnvironment(frame, *lighting, environment);

    // One sphere mesh, uploaded once, drawn by both instances, into the app's own image.
    const Mesh sphere = makeSphere();
    AppTarget target;
    if (!target.create(vk, width, height, &error)) return fail(error);
    AppImage image{target.image, VK_FORMAT_R8G8B8A8_UNORM, width, height, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    const int kFrames = 4;
    for (int i = 0; i < kFrames; ++i) {
      // An animated parameter: only `rough`'s block is uploaded again each frame.
      if (!rough->setParameter(*roughness, 0.55f + 0.05f * float(i), &error)) return fail(error);
      frame.draws = {glossy->draw(sphere, modelAt(-1.15f)), rough->draw(sphere, modelAt(1.15f))};
      if (!renderer->renderToImage(frame, image, &error)) return fail(error);
      image.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;  // where the last frame left it
    }
    const ResourceCounts counts = renderer->resources();
    std::printf("%d frames %ux%u: %zu mesh buffer(s), %llu mesh upload(s), %zu material block(s), "
                "%llu block upload(s)\n",
                kFrames, width, height, counts.meshBuffers, static_cast<unsigned long long>(counts.meshUploads),
                counts.materialBuffers, static_cast<unsigned long long>(counts.materialUploads));
    // 1 sphere; 2 blocks: both on the first frame, then `rough` once per later frame.
    if (counts.meshBuffers != 1 || counts.meshUploads != 1 || counts.materialBuffers != 2 ||
        counts.materialUploads != uint64_t(2 + kFrames - 1)) {
      return fail("unexpected GPU resource counts");
    }
    std::vector<uint8_t> pixels;
    if (!target.read(width, height, &pixels, &error) || !writePng(argv[2], width, height, pixels, &error)) {
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
  if (validationErrors > 0) return fail(std::to_string(validationErrors) + " Vulkan validation error(s)");
  std::printf("wrote %s\n", argv[2]);
  return 0;
}
