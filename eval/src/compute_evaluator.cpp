#include "facet/eval/compute_evaluator.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <vulkan/vulkan.h>

#include <cstdlib>
#include <cstring>
#include <functional>
#include <mutex>
#include <sstream>

namespace facet::eval {
namespace {

constexpr uint32_t kLocalSize = 64;

// Runs the registered destroy calls in reverse order when it goes out of scope.
struct Cleanup {
  std::vector<std::function<void()>> steps;
  void add(std::function<void()> f) { steps.push_back(std::move(f)); }
  ~Cleanup() {
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) (*it)();
  }
};

bool validationRequested() {
  const char* env = std::getenv("FACET_VK_VALIDATION");
  return env != nullptr && std::strcmp(env, "1") == 0;
}

std::string vkError(const char* what, VkResult r) { return std::string(what) + " failed: VkResult " + std::to_string(int(r)); }

bool compileCompute(const std::string& text, std::vector<uint32_t>* spirv, std::string* log) {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
  glslang::TShader shader(EShLangCompute);
  const char* src = text.c_str();
  shader.setStrings(&src, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 310, EEsProfile, false, false, messages)) {
    *log = std::string("GLSL compile error:\n") + shader.getInfoLog();
    return false;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    *log = std::string("GLSL link error:\n") + program.getInfoLog();
    return false;
  }
  glslang::SpvOptions options;
  glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), *spirv, &options);
  return true;
}

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)
    static_cast<std::vector<std::string>*>(user)->push_back(data->pMessage ? data->pMessage : "(no message)");
  return VK_FALSE;
}

}  // namespace

struct GpuEvaluator::Impl {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkCommandPool commandPool = VK_NULL_HANDLE;
  std::vector<std::string> validationErrors;
  std::string initError;
  std::string deviceName;

  bool init(bool validationOption);
  ~Impl();
  uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags flags) const;
  bool makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage, VkBuffer* buffer, VkDeviceMemory* memory, void** mapped,
                  Cleanup* cleanup, std::string* error);
};

bool GpuEvaluator::Impl::init(bool validationOption) {
  bool validation = validationOption || validationRequested();
  std::vector<const char*> layers, extensions;
  if (validation) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> props(count);
    vkEnumerateInstanceLayerProperties(&count, props.data());
    bool found = false;
    for (const auto& p : props) found = found || std::strcmp(p.layerName, "VK_LAYER_KHRONOS_validation") == 0;
    if (!found) {
      initError = "FACET_VK_VALIDATION=1 but VK_LAYER_KHRONOS_validation is not installed";
      return false;
    }
    layers.push_back("VK_LAYER_KHRONOS_validation");
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "facet-gpu-eval";
  app.apiVersion = VK_API_VERSION_1_1;
  VkDebugUtilsMessengerCreateInfoEXT debugInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  debugInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
  debugInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  debugInfo.pfnUserCallback = onValidationMessage;
  debugInfo.pUserData = &validationErrors;
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  ici.enabledLayerCount = uint32_t(layers.size());
  ici.ppEnabledLayerNames = layers.data();
  ici.enabledExtensionCount = uint32_t(extensions.size());
  ici.ppEnabledExtensionNames = extensions.data();
  if (validation) ici.pNext = &debugInfo;  // also reports errors of vkCreateInstance itself
  if (VkResult r = vkCreateInstance(&ici, nullptr, &instance); r != VK_SUCCESS) {
    instance = VK_NULL_HANDLE;
    initError = vkError("vkCreateInstance", r);
    return false;
  }
  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (create == nullptr || create(instance, &debugInfo, nullptr, &messenger) != VK_SUCCESS) {
      initError = "cannot create the debug utils messenger";
      return false;
    }
  }
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  for (VkPhysicalDevice d : devices) {
    uint32_t qCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &qCount, nullptr);
    std::vector<VkQueueFamilyProperties> qs(qCount);
    vkGetPhysicalDeviceQueueFamilyProperties(d, &qCount, qs.data());
    for (uint32_t i = 0; i < qCount && physical == VK_NULL_HANDLE; ++i) {
      if (qs[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
        physical = d;
        queueFamily = i;
      }
    }
    if (physical != VK_NULL_HANDLE) break;
  }
  if (physical == VK_NULL_HANDLE) {
    initError = "no Vulkan device with a compute queue";
    return false;
  }
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(physical, &props);
  deviceName = props.deviceName;
  float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = queueFamily;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  if (VkResult r = vkCreateDevice(physical, &dci, nullptr, &device); r != VK_SUCCESS) {
    device = VK_NULL_HANDLE;
    initError = vkError("vkCreateDevice", r);
    return false;
  }
  vkGetDeviceQueue(device, queueFamily, 0, &queue);
  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.queueFamilyIndex = queueFamily;
  if (VkResult r = vkCreateCommandPool(device, &pci, nullptr, &commandPool); r != VK_SUCCESS) {
    commandPool = VK_NULL_HANDLE;
    initError = vkError("vkCreateCommandPool", r);
    return false;
  }
  return true;
}

GpuEvaluator::Impl::~Impl() {
  if (commandPool != VK_NULL_HANDLE) vkDestroyCommandPool(device, commandPool, nullptr);
  if (device != VK_NULL_HANDLE) vkDestroyDevice(device, nullptr);
  if (messenger != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy != nullptr) destroy(instance, messenger, nullptr);
  }
  if (instance != VK_NULL_HANDLE) vkDestroyInstance(instance, nullptr);
}

uint32_t GpuEvaluator::Impl::memoryType(uint32_t bits, VkMemoryPropertyFlags flags) const {
  VkPhysicalDeviceMemoryProperties mp;
  vkGetPhysicalDeviceMemoryProperties(physical, &mp);
  for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & flags) == flags) return i;
  return UINT32_MAX;
}

bool GpuEvaluator::Impl::makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage, VkBuffer* buffer, VkDeviceMemory* memory,
                                    void** mapped, Cleanup* cleanup, std::string* error) {
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = size;
  bci.usage = usage;
  if (VkResult r = vkCreateBuffer(device, &bci, nullptr, buffer); r != VK_SUCCESS) return *error = vkError("vkCreateBuffer", r), false;
  VkBuffer b = *buffer;
  cleanup->add([this, b] { vkDestroyBuffer(device, b, nullptr); });
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, b, &req);
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  if (mai.memoryTypeIndex == UINT32_MAX) return *error = "no host-visible coherent memory", false;
  if (VkResult r = vkAllocateMemory(device, &mai, nullptr, memory); r != VK_SUCCESS) return *error = vkError("vkAllocateMemory", r), false;
  VkDeviceMemory m = *memory;
  cleanup->add([this, m] { vkFreeMemory(device, m, nullptr); });
  vkBindBufferMemory(device, b, m, 0);
  if (VkResult r = vkMapMemory(device, m, 0, VK_WHOLE_SIZE, 0, mapped); r != VK_SUCCESS) return *error = vkError("vkMapMemory", r), false;
  return true;
}

GpuEvaluator::GpuEvaluator(bool validation) : impl_(std::make_unique<Impl>()) { impl_->init(validation); }
GpuEvaluator::~GpuEvaluator() = default;
bool GpuEvaluator::ready() const { return impl_->initError.empty() && impl_->commandPool != VK_NULL_HANDLE; }
const std::string& GpuEvaluator::initError() const { return impl_->initError; }
std::string GpuEvaluator::deviceName() const { return impl_->deviceName; }

std::string GpuEvaluator::shaderSource(const GpuEvalRequest& request) {
  std::ostringstream s;
  s << "#version 310 es\n"
    << "precision " << (request.precision == FloatPrecision::kHighp ? "highp" : "mediump") << " float;\n"
    << "precision highp int;\n"
    << "layout(local_size_x = " << kLocalSize << ") in;\n"
    << "layout(std430, binding = 0) readonly buffer Inputs { highp vec4 inputs[]; };\n"
    << "layout(std430, binding = 1) writeonly buffer Outputs { highp vec4 outputs[]; };\n";
  if (request.lut != nullptr) s << "layout(binding = 2) uniform mediump sampler2D lut;\n";
  for (const auto& chunk : request.chunks) s << chunk << "\n";
  s << "void main() {\n"
    << "    uint index = gl_GlobalInvocationID.x;\n"
    << "    " << (request.highpInputs ? "highp " : "") << "vec4 in0 = inputs[2u * index];\n"
    << "    " << (request.highpInputs ? "highp " : "") << "vec4 in1 = inputs[2u * index + 1u];\n"
    << "    vec4 result = vec4(0.0);\n"
    << "    {\n" << request.body << "\n    }\n"
    << "    outputs[index] = result;\n"
    << "}\n";
  return s.str();
}

GpuEvalResult GpuEvaluator::run(const GpuEvalRequest& request) {
  GpuEvalResult out;
  if (!ready()) return out.error = impl_->initError, out;
  if (request.in0.size() != request.in1.size()) return out.error = "in0 and in1 differ in size", out;
  std::vector<uint32_t> spirv;
  if (!compileCompute(shaderSource(request), &spirv, &out.error)) return out;
  if (request.transformSpirv && !request.transformSpirv(&spirv, &out.error)) {
    if (out.error.empty()) out.error = "the SPIR-V transform failed";
    return out;
  }

  VkDevice device = impl_->device;
  impl_->validationErrors.clear();
  Cleanup cleanup;
  const size_t n = request.in0.size();
  const size_t groups = (n + kLocalSize - 1) / kLocalSize;
  const size_t padded = std::max<size_t>(groups, 1) * kLocalSize;  // every invocation reads and writes in bounds

  VkBuffer inBuf, outBuf;
  VkDeviceMemory inMem, outMem;
  void *inPtr = nullptr, *outPtr = nullptr;
  if (!impl_->makeBuffer(padded * 2 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, &inBuf, &inMem, &inPtr, &cleanup, &out.error) ||
      !impl_->makeBuffer(padded * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, &outBuf, &outMem, &outPtr, &cleanup, &out.error))
    return out;
  std::vector<glm::vec4> interleaved(padded * 2, glm::vec4(0.0f));
  for (size_t i = 0; i < n; ++i) {
    interleaved[2 * i] = request.in0[i];
    interleaved[2 * i + 1] = request.in1[i];
  }
  std::memcpy(inPtr, interleaved.data(), interleaved.size() * sizeof(glm::vec4));

  // Optional LUT: R8 image filled from a staging buffer, sampled linearly with clamp to edge.
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  VkBuffer staging = VK_NULL_HANDLE;
  const GpuR8Texture* lut = request.lut;
  if (lut != nullptr) {
    if (lut->texels.size() != size_t{lut->width} * lut->height || lut->width == 0 || lut->height == 0)
      return out.error = "LUT size does not match its texels", out;
    VkDeviceMemory stagingMem;
    void* stagingPtr = nullptr;
    if (!impl_->makeBuffer(lut->texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, &staging, &stagingMem, &stagingPtr, &cleanup, &out.error))
      return out;
    std::memcpy(stagingPtr, lut->texels.data(), lut->texels.size());
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = VK_FORMAT_R8_UNORM;
    ici.extent = {lut->width, lut->height, 1};
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (VkResult r = vkCreateImage(device, &ici, nullptr, &image); r != VK_SUCCESS) return out.error = vkError("vkCreateImage", r), out;
    cleanup.add([device, image] { vkDestroyImage(device, image, nullptr); });
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, image, &req);
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = impl_->memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (mai.memoryTypeIndex == UINT32_MAX) mai.memoryTypeIndex = impl_->memoryType(req.memoryTypeBits, 0);
    VkDeviceMemory imageMem;
    if (VkResult r = vkAllocateMemory(device, &mai, nullptr, &imageMem); r != VK_SUCCESS) return out.error = vkError("vkAllocateMemory", r), out;
    cleanup.add([device, imageMem] { vkFreeMemory(device, imageMem, nullptr); });
    vkBindImageMemory(device, image, imageMem, 0);
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = VK_FORMAT_R8_UNORM;
    vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    if (VkResult r = vkCreateImageView(device, &vci, nullptr, &view); r != VK_SUCCESS) return out.error = vkError("vkCreateImageView", r), out;
    cleanup.add([device, view] { vkDestroyImageView(device, view, nullptr); });
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = VK_FILTER_LINEAR;
    sci.minFilter = VK_FILTER_LINEAR;
    sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sci.maxLod = 0.0f;
    if (VkResult r = vkCreateSampler(device, &sci, nullptr, &sampler); r != VK_SUCCESS) return out.error = vkError("vkCreateSampler", r), out;
    cleanup.add([device, sampler] { vkDestroySampler(device, sampler, nullptr); });
  }

  // Descriptors: 0 = inputs, 1 = outputs, 2 = LUT (when given).
  std::vector<VkDescriptorSetLayoutBinding> bindings = {
      {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
  if (lut != nullptr) bindings.push_back({2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  VkDescriptorSetLayoutCreateInfo dslci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  dslci.bindingCount = uint32_t(bindings.size());
  dslci.pBindings = bindings.data();
  VkDescriptorSetLayout setLayout;
  if (VkResult r = vkCreateDescriptorSetLayout(device, &dslci, nullptr, &setLayout); r != VK_SUCCESS)
    return out.error = vkError("vkCreateDescriptorSetLayout", r), out;
  cleanup.add([device, setLayout] { vkDestroyDescriptorSetLayout(device, setLayout, nullptr); });
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = 1;
  plci.pSetLayouts = &setLayout;
  VkPipelineLayout pipelineLayout;
  if (VkResult r = vkCreatePipelineLayout(device, &plci, nullptr, &pipelineLayout); r != VK_SUCCESS)
    return out.error = vkError("vkCreatePipelineLayout", r), out;
  cleanup.add([device, pipelineLayout] { vkDestroyPipelineLayout(device, pipelineLayout, nullptr); });
  VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  smci.codeSize = spirv.size() * sizeof(uint32_t);
  smci.pCode = spirv.data();
  VkShaderModule module;
  if (VkResult r = vkCreateShaderModule(device, &smci, nullptr, &module); r != VK_SUCCESS)
    return out.error = vkError("vkCreateShaderModule", r), out;
  cleanup.add([device, module] { vkDestroyShaderModule(device, module, nullptr); });
  VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  cpci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_COMPUTE_BIT, module, "main", nullptr};
  cpci.layout = pipelineLayout;
  VkPipeline pipeline;
  if (VkResult r = vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline); r != VK_SUCCESS)
    return out.error = vkError("vkCreateComputePipelines", r), out;
  cleanup.add([device, pipeline] { vkDestroyPipeline(device, pipeline, nullptr); });

  VkDescriptorPoolSize poolSizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}, {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
  VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpci.maxSets = 1;
  dpci.poolSizeCount = 2;
  dpci.pPoolSizes = poolSizes;
  VkDescriptorPool pool;
  if (VkResult r = vkCreateDescriptorPool(device, &dpci, nullptr, &pool); r != VK_SUCCESS)
    return out.error = vkError("vkCreateDescriptorPool", r), out;
  cleanup.add([device, pool] { vkDestroyDescriptorPool(device, pool, nullptr); });
  VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  dsai.descriptorPool = pool;
  dsai.descriptorSetCount = 1;
  dsai.pSetLayouts = &setLayout;
  VkDescriptorSet set;
  if (VkResult r = vkAllocateDescriptorSets(device, &dsai, &set); r != VK_SUCCESS)
    return out.error = vkError("vkAllocateDescriptorSets", r), out;
  VkDescriptorBufferInfo inInfo{inBuf, 0, VK_WHOLE_SIZE}, outInfo{outBuf, 0, VK_WHOLE_SIZE};
  VkDescriptorImageInfo imageInfo{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  std::vector<VkWriteDescriptorSet> writes(2, VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET});
  writes[0].dstSet = writes[1].dstSet = set;
  writes[0].dstBinding = 0;
  writes[1].dstBinding = 1;
  writes[0].descriptorCount = writes[1].descriptorCount = 1;
  writes[0].descriptorType = writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  writes[0].pBufferInfo = &inInfo;
  writes[1].pBufferInfo = &outInfo;
  if (lut != nullptr) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = 2;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &imageInfo;
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);

  VkCommandBufferAllocateInfo cbai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  cbai.commandPool = impl_->commandPool;
  cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cbai.commandBufferCount = 1;
  VkCommandBuffer cmd;
  if (VkResult r = vkAllocateCommandBuffers(device, &cbai, &cmd); r != VK_SUCCESS)
    return out.error = vkError("vkAllocateCommandBuffers", r), out;
  VkCommandPool commandPool = impl_->commandPool;
  cleanup.add([device, commandPool, cmd] { vkFreeCommandBuffers(device, commandPool, 1, &cmd); });
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(cmd, &begin);
  if (lut != nullptr) {
    VkImageMemoryBarrier toTransfer{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    toTransfer.srcAccessMask = 0;
    toTransfer.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toTransfer.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    toTransfer.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    toTransfer.srcQueueFamilyIndex = toTransfer.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toTransfer.image = image;
    toTransfer.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &toTransfer);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {lut->width, lut->height, 1};
    vkCmdCopyBufferToImage(cmd, staging, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    VkImageMemoryBarrier toRead = toTransfer;
    toRead.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toRead.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    toRead.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    toRead.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0, nullptr, 1, &toRead);
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout, 0, 1, &set, 0, nullptr);
  vkCmdDispatch(cmd, uint32_t(padded / kLocalSize), 1, 1);
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
  vkEndCommandBuffer(cmd);

  VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence;
  if (VkResult r = vkCreateFence(device, &fci, nullptr, &fence); r != VK_SUCCESS) return out.error = vkError("vkCreateFence", r), out;
  cleanup.add([device, fence] { vkDestroyFence(device, fence, nullptr); });
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  if (VkResult r = vkQueueSubmit(impl_->queue, 1, &submit, fence); r != VK_SUCCESS) return out.error = vkError("vkQueueSubmit", r), out;
  if (VkResult r = vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX); r != VK_SUCCESS)
    return out.error = vkError("vkWaitForFences", r), out;

  out.values.resize(n);
  std::memcpy(out.values.data(), outPtr, n * sizeof(glm::vec4));
  if (!impl_->validationErrors.empty()) {
    out.error = "Vulkan validation errors:";
    for (const auto& m : impl_->validationErrors) out.error += "\n  " + m;
  }
  return out;
}

}  // namespace facet::eval
