#include "app_vulkan.h"

#include <cstdio>
#include <cstring>

namespace facet::example {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL onValidation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                            VkDebugUtilsMessageTypeFlagsEXT,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data, void* app) {
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    const char* message = data->pMessage ? data->pMessage : "";
    static_cast<AppVulkan*>(app)->validationErrors.emplace_back(message);
    std::fprintf(stderr, "validation: %s\n", message);
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

}  // namespace

bool AppVulkan::create(bool validation, std::string* error) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "facet-app-example";
  app.apiVersion = VK_API_VERSION_1_1;
  const char* layer = "VK_LAYER_KHRONOS_validation";
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = onValidation;
  messengerInfo.pUserData = this;
  // Synchronization validation: a missing barrier between the app's work and the runtime's, or
  // between frames in flight, is an error too.
  const VkValidationFeatureEnableEXT enabled[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.pNext = &messengerInfo;
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enabled;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (validation) {
    if (!layerAvailable(layer)) {
      *error = "validation was asked for but VK_LAYER_KHRONOS_validation is not installed";
      return false;
    }
    info.pNext = &features;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 2;
    info.ppEnabledExtensionNames = extensions;
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

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = queueFamily;
  if (vkCreateCommandPool(device, &poolInfo, nullptr, &pool) != VK_SUCCESS) {
    *error = "cannot create the app's command pool";
    return false;
  }
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = pool;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = uint32_t(frameCommands.size());
  if (vkAllocateCommandBuffers(device, &allocInfo, frameCommands.data()) != VK_SUCCESS) {
    *error = "cannot allocate the app's command buffers";
    return false;
  }
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // as if an earlier frame had finished
  for (VkFence& fence : frameFences) {
    if (vkCreateFence(device, &fenceInfo, nullptr, &fence) != VK_SUCCESS) {
      *error = "cannot create the app's fences";
      return false;
    }
  }
  return true;
}

void AppVulkan::destroy() {
  if (device) {
    vkDeviceWaitIdle(device);
    for (VkFence fence : frameFences)
      if (fence) vkDestroyFence(device, fence, nullptr);
    // Destroying the pool frees its command buffers.
    if (pool) vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyDevice(device, nullptr);
  }
  if (messenger) {
    auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroyMessenger) destroyMessenger(instance, messenger, nullptr);
  }
  if (instance) vkDestroyInstance(instance, nullptr);
  frameFences = {};
  frameCommands = {};
  pool = VK_NULL_HANDLE;
  device = VK_NULL_HANDLE;
  messenger = VK_NULL_HANDLE;
  instance = VK_NULL_HANDLE;
}

bool AppVulkan::recordAndSubmit(runtime::VulkanRenderer& renderer, const runtime::FrameDesc& frame,
                                const runtime::AppImage& image, int index, std::string* error) {
  const size_t ring = size_t(index) % frameCommands.size();
  VkCommandBuffer cmd = frameCommands[ring];
  if (vkWaitForFences(device, 1, &frameFences[ring], VK_TRUE, UINT64_MAX) != VK_SUCCESS ||
      vkResetFences(device, 1, &frameFences[ring]) != VK_SUCCESS || vkResetCommandBuffer(cmd, 0) != VK_SUCCESS) {
    *error = "the app's frame fence failed";
    return false;
  }
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(cmd, &begin);
  if (!renderer.recordFrame(frame, image, cmd, error)) {
    vkEndCommandBuffer(cmd);
    return false;
  }
  vkEndCommandBuffer(cmd);
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  if (vkQueueSubmit(queue, 1, &submit, frameFences[ring]) != VK_SUCCESS) {
    *error = "the app's frame submission failed";
    return false;
  }
  return true;
}

uint32_t AppVulkan::memoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const {
  VkPhysicalDeviceMemoryProperties props{};
  vkGetPhysicalDeviceMemoryProperties(physicalDevice, &props);
  for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
  return UINT32_MAX;
}

bool AppTarget::create(const AppVulkan& app, VkFormat imageFormat, uint32_t imageWidth, uint32_t imageHeight,
                       VkImageUsageFlags imageUsage, VkImageCreateFlags createFlags, std::string* error) {
  vk = &app;
  format = imageFormat;
  width = imageWidth;
  height = imageHeight;
  usage = imageUsage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  flags = createFlags;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.flags = flags;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
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
  alloc.memoryTypeIndex = app.memoryType(imageNeeds.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (vkAllocateMemory(app.device, &alloc, nullptr, &imageMemory) != VK_SUCCESS ||
      vkBindImageMemory(app.device, image, imageMemory, 0) != VK_SUCCESS) {
    *error = "cannot allocate the app's image";
    return false;
  }
  alloc.allocationSize = bufferNeeds.size;
  alloc.memoryTypeIndex = app.memoryType(bufferNeeds.memoryTypeBits,
                                         VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  if (vkAllocateMemory(app.device, &alloc, nullptr, &bufferMemory) != VK_SUCCESS ||
      vkBindBufferMemory(app.device, buffer, bufferMemory, 0) != VK_SUCCESS) {
    *error = "cannot allocate the app's readback buffer";
    return false;
  }
  return true;
}

bool AppTarget::read(VkImageLayout layout, std::vector<uint8_t>* rgba, std::string* error) {
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = vk->pool;
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
  vkCmdCopyImageToBuffer(cmd, image, layout, buffer, 1, &region);
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                       nullptr);
  vkEndCommandBuffer(cmd);
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  const bool done =
      vkQueueSubmit(vk->queue, 1, &submit, VK_NULL_HANDLE) == VK_SUCCESS && vkQueueWaitIdle(vk->queue) == VK_SUCCESS;
  vkFreeCommandBuffers(vk->device, vk->pool, 1, &cmd);
  if (!done) {
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

AppTarget::~AppTarget() {
  if (!vk) return;
  vkDeviceWaitIdle(vk->device);
  if (buffer) vkDestroyBuffer(vk->device, buffer, nullptr);
  if (bufferMemory) vkFreeMemory(vk->device, bufferMemory, nullptr);
  if (image) vkDestroyImage(vk->device, image, nullptr);
  if (imageMemory) vkFreeMemory(vk->device, imageMemory, nullptr);
}

}  // namespace facet::example
