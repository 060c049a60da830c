#include "vk_context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "vk_check.h"

namespace facet::runtime::vulkan {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Formats the backend renders into, and the features it needs of each (optimal tiling).
struct RequiredFormat {
  VkFormat format;
  VkFormatFeatureFlags features;
};
constexpr RequiredFormat kRequiredFormats[] = {
    {VK_FORMAT_R16G16B16A16_SFLOAT,
     VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT},
    {VK_FORMAT_D32_SFLOAT, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT},
    {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT},
};

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT types,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData) {
  auto* messages = static_cast<DebugMessages*>(userData);
  std::string text = data && data->pMessage ? data->pMessage : "(no message)";
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    messages->errors.push_back(text);
    // Also printed: errors at vkDestroyDevice/vkDestroyInstance (leaks) happen after the last
    // chance anyone has to call validationErrors().
    std::fprintf(stderr, "[vulkan validation error] %s\n", text.c_str());
  } else if ((severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) &&
             (types & VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT)) {
    messages->warnings.push_back(text);
  }
  return VK_FALSE;  // never abort the call that triggered the message
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(DebugMessages* messages) {
  VkDebugUtilsMessengerCreateInfoEXT info{};
  info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = debugCallback;
  info.pUserData = messages;
  return info;
}

bool layerAvailable(const char* name) {
  uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
  for (const VkLayerProperties& layer : layers) {
    if (std::strcmp(layer.layerName, name) == 0) return true;
  }
  return false;
}

bool instanceExtensionAvailable(const char* layer, const char* name) {
  uint32_t count = 0;
  if (vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> extensions(count);
  if (vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()) != VK_SUCCESS) {
    return false;
  }
  for (const VkExtensionProperties& extension : extensions) {
    if (std::strcmp(extension.extensionName, name) == 0) return true;
  }
  return false;
}

// Lower is better. A CPU device (lavapipe) first: its output is the same on every machine,
// which is what tests and golden images want.
int deviceRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 3;
    default: return 4;
  }
}

}  // namespace

static std::string unusableReason(VkPhysicalDevice candidate, const VkPhysicalDeviceProperties& props) {
  std::string why;
  if (props.apiVersion < VK_API_VERSION_1_1) why = "Vulkan 1.1 not supported";
  for (const RequiredFormat& required : kRequiredFormats) {
    VkFormatProperties formatProps{};
    vkGetPhysicalDeviceFormatProperties(candidate, required.format, &formatProps);
    if ((formatProps.optimalTilingFeatures & required.features) != required.features) {
      why = "format " + std::to_string(static_cast<int>(required.format)) + " lacks features";
    }
  }
  return why;
}

bool validationRequestedByEnvironment() {
  const char* value = std::getenv("FACET_VK_VALIDATION");
  return value && value[0] != '\0' && std::strcmp(value, "0") != 0;
}

Context::~Context() {
  if (!owned_) return;  // the app's device and instance: the app destroys them
  if (device) {
    vkDeviceWaitIdle(device);
    vkDestroyDevice(device, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance, messenger_, nullptr);
  }
  if (instance) vkDestroyInstance(instance, nullptr);
}

bool Context::init(bool validation, bool float16Arithmetic, bool renderToSingleSampled, std::string* error) {
  return createInstance(validation, error) && pickPhysicalDevice(error) &&
         createDevice(float16Arithmetic, renderToSingleSampled, error);
}

bool Context::adopt(const AppDevice& app, std::string* error) {
  owned_ = false;
  if (!app.instance || !app.physicalDevice || !app.device || !app.queue) {
    *error = "the app's Vulkan device is incomplete: instance, physical device, device and queue are all required";
    return false;
  }
  instance = app.instance;
  physicalDevice = app.physicalDevice;
  device = app.device;
  queue = app.queue;
  queueFamily = app.queueFamily;
  vkGetPhysicalDeviceProperties(physicalDevice, &properties);
  if (std::string why = unusableReason(physicalDevice, properties); !why.empty()) {
    *error = std::string("the app's Vulkan device ") + properties.deviceName + " cannot run Facet: " + why;
    return false;
  }
  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
  if (queueFamily >= familyCount || !(families[queueFamily].queueFlags & VK_QUEUE_GRAPHICS_BIT)) {
    *error = "the app's queue family " + std::to_string(queueFamily) + " is not a graphics queue family";
    return false;
  }
  timestampValidBits = families[queueFamily].timestampValidBits;
  vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties);
  return true;
}

bool Context::createInstance(bool validation, std::string* error) {
  uint32_t loaderVersion = VK_API_VERSION_1_0;
  if (!check(vkEnumerateInstanceVersion(&loaderVersion), "vkEnumerateInstanceVersion", error)) {
    return false;
  }
  if (loaderVersion < VK_API_VERSION_1_1) {
    *error = "Vulkan 1.1 is required, the loader only offers " + std::to_string(VK_API_VERSION_MAJOR(loaderVersion)) +
             "." + std::to_string(VK_API_VERSION_MINOR(loaderVersion));
    return false;
  }

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  if (validation) {
    if (!layerAvailable(kValidationLayer)) {
      *error = std::string(
                   "Vulkan validation was requested (VulkanOptions::validation or "
                   "FACET_VK_VALIDATION=1) but ") +
               kValidationLayer + " is not installed (Debian: vulkan-validationlayers)";
      return false;
    }
    if (!instanceExtensionAvailable(nullptr, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) &&
        !instanceExtensionAvailable(kValidationLayer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
      *error = "Vulkan validation was requested but " VK_EXT_DEBUG_UTILS_EXTENSION_NAME " is not available";
      return false;
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    // Synchronization validation finds missing barriers and subpass dependencies (hazards the
    // core checks cannot see), which the merged render pass depends on getting right.
    if (!instanceExtensionAvailable(kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
      *error = "Vulkan validation was requested but " VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME
               " (needed for synchronization validation) is not available";
      return false;
    }
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
  }

  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "facet";
  app.pEngineName = "facet";
  app.apiVersion = VK_API_VERSION_1_1;

  // Chained into the create info too, so that vkCreateInstance/vkDestroyInstance are covered.
  VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(&messages);

  const VkValidationFeatureEnableEXT enabledFeatures[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{};
  features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
  features.pNext = &debugInfo;
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enabledFeatures;

  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pNext = validation ? &features : nullptr;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  if (!check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance", error)) {
    instance = VK_NULL_HANDLE;
    return false;
  }

  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) {
      *error = "vkGetInstanceProcAddr(vkCreateDebugUtilsMessengerEXT) returned null";
      return false;
    }
    if (!check(create(instance, &debugInfo, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT", error)) {
      messenger_ = VK_NULL_HANDLE;
      return false;
    }
    validationEnabled = true;
  }
  return true;
}

bool Context::pickPhysicalDevice(std::string* error) {
  uint32_t count = 0;
  if (!check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices", error)) {
    return false;
  }
  std::vector<VkPhysicalDevice> devices(count);
  if (count > 0 &&
      !check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices", error)) {
    return false;
  }

  std::string rejected;  // why each device was passed over, for the error message
  int bestRank = 1 << 30;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(candidate, &props);
    std::string why = unusableReason(candidate, props);
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &familyCount, families.data());
    uint32_t family = UINT32_MAX;
    for (uint32_t i = 0; i < familyCount; ++i) {
      if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && families[i].queueCount > 0) {
        family = i;
        break;
      }
    }
    if (family == UINT32_MAX) why = "no graphics queue";
    if (!why.empty()) {
      rejected += std::string("; ") + props.deviceName + ": " + why;
      continue;
    }
    int rank = deviceRank(props.deviceType);
    if (rank < bestRank) {
      bestRank = rank;
      physicalDevice = candidate;
      properties = props;
      queueFamily = family;
      timestampValidBits = families[family].timestampValidBits;
    }
  }
  if (!physicalDevice) {
    *error = "no usable Vulkan device (" + std::to_string(count) + " found" + rejected + ")";
    return false;
  }
  vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties);
  return true;
}

bool Context::createDevice(bool float16Arithmetic, bool renderToSingleSampled, std::string* error) {
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{};
  queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queueInfo.queueFamilyIndex = queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkDeviceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  // 16-bit float arithmetic in shaders (Vulkan 1.1 + the extension; core in 1.2), for the
  // true-half test builds (compiler::BuildOptions::fp16TrueHalf).
  VkPhysicalDeviceShaderFloat16Int8Features float16{};
  float16.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES;
  const char* float16Extension = VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME;
  uint32_t extensionCount = 0;
  vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &extensionCount, nullptr);
  std::vector<VkExtensionProperties> extensions(extensionCount);
  vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &extensionCount, extensions.data());
  const auto offered = [&](const char* name) {
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
  };
  std::vector<const char*> enabled;
  // The mobile form of MSAA (multisampled attachments the app never allocates), on a Vulkan 1.1
  // device through the two extensions it requires there (core in 1.2).
  VkPhysicalDeviceMultisampledRenderToSingleSampledFeaturesEXT renderToSingle{};
  renderToSingle.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTISAMPLED_RENDER_TO_SINGLE_SAMPLED_FEATURES_EXT;
  const char* const renderToSingleExtensions[] = {VK_KHR_CREATE_RENDERPASS_2_EXTENSION_NAME,
                                                  VK_KHR_DEPTH_STENCIL_RESOLVE_EXTENSION_NAME,
                                                  VK_EXT_MULTISAMPLED_RENDER_TO_SINGLE_SAMPLED_EXTENSION_NAME};
  if (renderToSingleSampled &&
      std::all_of(std::begin(renderToSingleExtensions), std::end(renderToSingleExtensions), offered)) {
    VkPhysicalDeviceFeatures2 features{};
    features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    features.pNext = &renderToSingle;
    vkGetPhysicalDeviceFeatures2(physicalDevice, &features);
    if (renderToSingle.multisampledRenderToSingleSampled) {
      renderToSingle.pNext = nullptr;
      info.pNext = &renderToSingle;
      enabled.insert(enabled.end(), std::begin(renderToSingleExtensions), std::end(renderToSingleExtensions));
    }
  }
  if (float16Arithmetic) {
    const bool listed = offered(float16Extension);
    VkPhysicalDeviceFeatures2 features{};
    features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    features.pNext = &float16;
    if (listed) vkGetPhysicalDeviceFeatures2(physicalDevice, &features);
    if (!listed || !float16.shaderFloat16) {
      *error = std::string("16-bit float arithmetic asked for, but ") + properties.deviceName + " has no shaderFloat16";
      return false;
    }
    float16 = {};
    float16.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES;
    float16.shaderFloat16 = VK_TRUE;
    float16.pNext = const_cast<void*>(info.pNext);
    info.pNext = &float16;
    enabled.push_back(float16Extension);
  }
  // ASTC textures are sampled as they are where the device can (phones); lavapipe cannot, and
  // the texture cache decodes them there (vk_textures.cpp).
  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(physicalDevice, &supported);
  VkPhysicalDeviceFeatures enabledFeatures{};
  enabledFeatures.textureCompressionASTC_LDR = supported.textureCompressionASTC_LDR;
  info.pEnabledFeatures = &enabledFeatures;
  info.enabledExtensionCount = static_cast<uint32_t>(enabled.size());
  info.ppEnabledExtensionNames = enabled.data();
  if (!check(vkCreateDevice(physicalDevice, &info, nullptr, &device), "vkCreateDevice", error)) {
    device = VK_NULL_HANDLE;
    return false;
  }
  vkGetDeviceQueue(device, queueFamily, 0, &queue);
  astcLdr = enabledFeatures.textureCompressionASTC_LDR == VK_TRUE;
  if (renderToSingle.multisampledRenderToSingleSampled) {
    createRenderPass2 =
        reinterpret_cast<PFN_vkCreateRenderPass2KHR>(vkGetDeviceProcAddr(device, "vkCreateRenderPass2KHR"));
  }
  return true;
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const {
  for (uint32_t i = 0; i < memoryProperties.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) && (memoryProperties.memoryTypes[i].propertyFlags & required) == required) {
      return i;
    }
  }
  return UINT32_MAX;
}

}  // namespace facet::runtime::vulkan
