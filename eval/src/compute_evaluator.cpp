#include "facet/eval/compute_evaluator.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <mutex>
#include <sstream>

#include "facet/runtime/vulkan_backend.h"
#include "vk_check.h"
#include "vk_context.h"

namespace facet::eval {
namespace {

using runtime::vulkan::check;

constexpr uint32_t kLocalSize = 64;

// Runs the registered destroy calls in reverse order when it goes out of scope.
struct Cleanup {
  std::vector<std::function<void()>> steps;
  void add(std::function<void()> f) { steps.push_back(std::move(f)); }
  ~Cleanup() {
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) (*it)();
  }
};

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

// The request's compute shader as SPIR-V: compiled, then rewritten by its transformSpirv.
bool requestSpirv(const GpuEvalRequest& request, std::vector<uint32_t>* spirv, std::string* error) {
  if (!compileCompute(GpuEvaluator::shaderSource(request), spirv, error)) return false;
  if (request.transformSpirv && !request.transformSpirv(spirv, error)) {
    if (error->empty()) *error = "the SPIR-V transform failed";
    return false;
  }
  return true;
}

// The queue family must run compute work as well: a graphics family need not (Vulkan guarantees
// only that some family does both).
bool computeQueue(const runtime::vulkan::Context& ctx, std::string* error) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice, &count, families.data());
  if (ctx.queueFamily < count && (families[ctx.queueFamily].queueFlags & VK_QUEUE_COMPUTE_BIT)) return true;
  *error = std::string("the queue family ") + std::to_string(ctx.queueFamily) + " of " + ctx.properties.deviceName +
           " runs no compute work";
  return false;
}

// One call's Vulkan objects, created step by step and destroyed in reverse order when it ends:
// the input and output buffers, the optional LUT, the pipeline and its descriptor set, and the
// command buffer that dispatches it. The steps run in order: uploadInputs, createLut (with a
// LUT), createPipeline, bindResources, dispatch, then outputs.
class ComputeRun {
 public:
  ComputeRun(const runtime::vulkan::Context& ctx, VkCommandPool commandPool)
      : ctx_(ctx), device_(ctx.device), commandPool_(commandPool) {}

  // in0 and in1 interleaved into the input buffer, `padded` invocations of each.
  bool uploadInputs(const GpuEvalRequest& request, size_t padded, std::string* error) {
    void* inPtr = nullptr;
    if (!makeBuffer(padded * 2 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, &inBuffer_, &inPtr, error) ||
        !makeBuffer(padded * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, &outBuffer_, &outPtr_, error))
      return false;
    std::vector<glm::vec4> interleaved(padded * 2, glm::vec4(0.0f));
    for (size_t i = 0; i < request.in0.size(); ++i) {
      interleaved[2 * i] = request.in0[i];
      interleaved[2 * i + 1] = request.in1[i];
    }
    std::memcpy(inPtr, interleaved.data(), interleaved.size() * sizeof(glm::vec4));
    return true;
  }

  // The LUT: an R8 image filled from a staging buffer (by the command buffer), sampled linearly
  // with clamp to edge.
  bool createLut(const GpuR8Texture& lut, std::string* error) {
    if (lut.texels.size() != size_t{lut.width} * lut.height || lut.width == 0 || lut.height == 0)
      return fail("LUT size does not match its texels", error);
    lut_ = &lut;
    void* stagingPtr = nullptr;
    if (!makeBuffer(lut.texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, &staging_, &stagingPtr, error)) return false;
    std::memcpy(stagingPtr, lut.texels.data(), lut.texels.size());
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = VK_FORMAT_R8_UNORM;
    ici.extent = {lut.width, lut.height, 1};
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (!check(vkCreateImage(device_, &ici, nullptr, &image_), "vkCreateImage", error)) return false;
    destroyLater([d = device_, i = image_] { vkDestroyImage(d, i, nullptr); });
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, image_, &req);
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = ctx_.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (mai.memoryTypeIndex == UINT32_MAX) mai.memoryTypeIndex = ctx_.findMemoryType(req.memoryTypeBits, 0);
    VkDeviceMemory imageMemory;
    if (!check(vkAllocateMemory(device_, &mai, nullptr, &imageMemory), "vkAllocateMemory", error)) return false;
    destroyLater([d = device_, imageMemory] { vkFreeMemory(d, imageMemory, nullptr); });
    vkBindImageMemory(device_, image_, imageMemory, 0);
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = image_;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = VK_FORMAT_R8_UNORM;
    vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    if (!check(vkCreateImageView(device_, &vci, nullptr, &view_), "vkCreateImageView", error)) return false;
    destroyLater([d = device_, v = view_] { vkDestroyImageView(d, v, nullptr); });
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = VK_FILTER_LINEAR;
    sci.minFilter = VK_FILTER_LINEAR;
    sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sci.maxLod = 0.0f;
    if (!check(vkCreateSampler(device_, &sci, nullptr, &sampler_), "vkCreateSampler", error)) return false;
    destroyLater([d = device_, s = sampler_] { vkDestroySampler(d, s, nullptr); });
    return true;
  }

  // The compute pipeline of `spirv` and its layout: 0 = inputs, 1 = outputs, 2 = the LUT (when given).
  bool createPipeline(const std::vector<uint32_t>& spirv, std::string* error) {
    std::vector<VkDescriptorSetLayoutBinding> bindings = {
        {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
    if (lut_)
      bindings.push_back({2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    VkDescriptorSetLayoutCreateInfo dslci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    dslci.bindingCount = uint32_t(bindings.size());
    dslci.pBindings = bindings.data();
    if (!check(vkCreateDescriptorSetLayout(device_, &dslci, nullptr, &setLayout_), "vkCreateDescriptorSetLayout",
               error))
      return false;
    destroyLater([d = device_, l = setLayout_] { vkDestroyDescriptorSetLayout(d, l, nullptr); });
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &setLayout_;
    if (!check(vkCreatePipelineLayout(device_, &plci, nullptr, &pipelineLayout_), "vkCreatePipelineLayout", error))
      return false;
    destroyLater([d = device_, l = pipelineLayout_] { vkDestroyPipelineLayout(d, l, nullptr); });
    VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    smci.codeSize = spirv.size() * sizeof(uint32_t);
    smci.pCode = spirv.data();
    VkShaderModule module;
    if (!check(vkCreateShaderModule(device_, &smci, nullptr, &module), "vkCreateShaderModule", error)) return false;
    destroyLater([d = device_, module] { vkDestroyShaderModule(d, module, nullptr); });
    VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    cpci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                  nullptr,
                  0,
                  VK_SHADER_STAGE_COMPUTE_BIT,
                  module,
                  "main",
                  nullptr};
    cpci.layout = pipelineLayout_;
    if (!check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline_),
               "vkCreateComputePipelines", error))
      return false;
    destroyLater([d = device_, p = pipeline_] { vkDestroyPipeline(d, p, nullptr); });
    return true;
  }

  // The descriptor set: the buffers, and the LUT's image and sampler.
  bool bindResources(std::string* error) {
    VkDescriptorPoolSize poolSizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},
                                        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
    VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpci.maxSets = 1;
    dpci.poolSizeCount = 2;
    dpci.pPoolSizes = poolSizes;
    VkDescriptorPool pool;
    if (!check(vkCreateDescriptorPool(device_, &dpci, nullptr, &pool), "vkCreateDescriptorPool", error)) return false;
    destroyLater([d = device_, pool] { vkDestroyDescriptorPool(d, pool, nullptr); });
    VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dsai.descriptorPool = pool;
    dsai.descriptorSetCount = 1;
    dsai.pSetLayouts = &setLayout_;
    if (!check(vkAllocateDescriptorSets(device_, &dsai, &set_), "vkAllocateDescriptorSets", error)) return false;
    VkDescriptorBufferInfo inInfo{inBuffer_, 0, VK_WHOLE_SIZE}, outInfo{outBuffer_, 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo imageInfo{sampler_, view_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    std::vector<VkWriteDescriptorSet> writes(2, VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET});
    writes[0].dstSet = writes[1].dstSet = set_;
    writes[0].dstBinding = 0;
    writes[1].dstBinding = 1;
    writes[0].descriptorCount = writes[1].descriptorCount = 1;
    writes[0].descriptorType = writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[0].pBufferInfo = &inInfo;
    writes[1].pBufferInfo = &outInfo;
    if (lut_) {
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = set_;
      w.dstBinding = 2;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      w.pImageInfo = &imageInfo;
      writes.push_back(w);
    }
    vkUpdateDescriptorSets(device_, uint32_t(writes.size()), writes.data(), 0, nullptr);
    return true;
  }

  // Records the LUT's upload (when given), the dispatch of `groups` work groups and the barrier
  // that makes the outputs visible to the host, submits it and waits for it.
  bool dispatch(uint32_t groups, VkQueue queue, std::string* error) {
    VkCommandBufferAllocateInfo cbai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cbai.commandPool = commandPool_;
    cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cbai.commandBufferCount = 1;
    VkCommandBuffer cmd;
    if (!check(vkAllocateCommandBuffers(device_, &cbai, &cmd), "vkAllocateCommandBuffers", error)) return false;
    destroyLater([d = device_, pool = commandPool_, cmd] { vkFreeCommandBuffers(d, pool, 1, &cmd); });
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &begin);
    if (lut_) recordLutUpload(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1, &set_, 0, nullptr);
    vkCmdDispatch(cmd, groups, 1, 1);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0,
                         nullptr, 0, nullptr);
    vkEndCommandBuffer(cmd);

    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    if (!check(vkCreateFence(device_, &fci, nullptr, &fence), "vkCreateFence", error)) return false;
    destroyLater([d = device_, fence] { vkDestroyFence(d, fence, nullptr); });
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    return check(vkQueueSubmit(queue, 1, &submit, fence), "vkQueueSubmit", error) &&
           check(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences", error);
  }

  // The first n outputs, once dispatch() has returned.
  std::vector<glm::vec4> outputs(size_t n) const {
    std::vector<glm::vec4> values(n);
    std::memcpy(values.data(), outPtr_, n * sizeof(glm::vec4));
    return values;
  }

 private:
  static bool fail(const char* message, std::string* error) {
    *error = message;
    return false;
  }

  void destroyLater(std::function<void()> destroy) { cleanup_.add(std::move(destroy)); }

  // A host-visible, coherent buffer, mapped at *mapped.
  bool makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage, VkBuffer* buffer, void** mapped, std::string* error) {
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size;
    bci.usage = usage;
    if (!check(vkCreateBuffer(device_, &bci, nullptr, buffer), "vkCreateBuffer", error)) return false;
    destroyLater([d = device_, b = *buffer] { vkDestroyBuffer(d, b, nullptr); });
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, *buffer, &req);
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = ctx_.findMemoryType(
        req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    if (mai.memoryTypeIndex == UINT32_MAX) return fail("no host-visible coherent memory", error);
    VkDeviceMemory memory;
    if (!check(vkAllocateMemory(device_, &mai, nullptr, &memory), "vkAllocateMemory", error)) return false;
    destroyLater([d = device_, memory] { vkFreeMemory(d, memory, nullptr); });
    vkBindBufferMemory(device_, *buffer, memory, 0);
    return check(vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, mapped), "vkMapMemory", error);
  }

  // Staging buffer -> image, then the image readable by the compute shader.
  void recordLutUpload(VkCommandBuffer cmd) const {
    VkImageMemoryBarrier toTransfer{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    toTransfer.srcAccessMask = 0;
    toTransfer.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toTransfer.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    toTransfer.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    toTransfer.srcQueueFamilyIndex = toTransfer.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toTransfer.image = image_;
    toTransfer.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &toTransfer);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {lut_->width, lut_->height, 1};
    vkCmdCopyBufferToImage(cmd, staging_, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    VkImageMemoryBarrier toRead = toTransfer;
    toRead.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toRead.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    toRead.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    toRead.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &toRead);
  }

  const runtime::vulkan::Context& ctx_;
  VkDevice device_;
  VkCommandPool commandPool_;
  Cleanup cleanup_;  // destroys what the steps created, in reverse order, when the run ends
  VkBuffer inBuffer_ = VK_NULL_HANDLE, outBuffer_ = VK_NULL_HANDLE, staging_ = VK_NULL_HANDLE;
  void* outPtr_ = nullptr;
  const GpuR8Texture* lut_ = nullptr;
  VkImage image_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace

// The runtime's Vulkan context (its own instance and device, or the app's), and the command pool
// the runs allocate from.
struct GpuEvaluator::Impl {
  runtime::vulkan::Context ctx;
  VkCommandPool commandPool = VK_NULL_HANDLE;
  std::string initError;

  // After ctx.init or ctx.adopt: the queue runs compute work; the pool.
  bool finishInit() {
    if (!computeQueue(ctx, &initError)) return false;
    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.queueFamilyIndex = ctx.queueFamily;
    if (!check(vkCreateCommandPool(ctx.device, &pci, nullptr, &commandPool), "vkCreateCommandPool", &initError)) {
      commandPool = VK_NULL_HANDLE;
      return false;
    }
    return true;
  }

  ~Impl() {
    if (commandPool != VK_NULL_HANDLE) vkDestroyCommandPool(ctx.device, commandPool, nullptr);
  }
};

GpuEvaluator::GpuEvaluator(bool validation) : impl_(std::make_unique<Impl>()) {
  const bool layers = validation || runtime::vulkan::validationRequestedByEnvironment();
  if (impl_->ctx.init(layers, /*float16Arithmetic=*/false, /*renderToSingleSampled=*/false, &impl_->initError))
    impl_->finishInit();
}

GpuEvaluator::GpuEvaluator(const runtime::AppDevice& device) : impl_(std::make_unique<Impl>()) {
  if (impl_->ctx.adopt(device, &impl_->initError)) impl_->finishInit();
}

GpuEvaluator::~GpuEvaluator() = default;
bool GpuEvaluator::ready() const { return impl_->initError.empty() && impl_->commandPool != VK_NULL_HANDLE; }
const std::string& GpuEvaluator::initError() const { return impl_->initError; }
std::string GpuEvaluator::deviceName() const { return impl_->ctx.properties.deviceName; }

std::string GpuEvaluator::shaderSource(const GpuEvalRequest& request) {
  std::ostringstream s;
  s << "#version 310 es\n"
    << "precision " << (request.precision == FloatPrecision::Highp ? "highp" : "mediump") << " float;\n"
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
    << "    {\n"
    << request.body << "\n    }\n"
    << "    outputs[index] = result;\n"
    << "}\n";
  return s.str();
}

GpuEvalResult GpuEvaluator::run(const GpuEvalRequest& request) {
  GpuEvalResult out;
  if (!ready()) return out.error = impl_->initError, out;
  if (request.in0.size() != request.in1.size()) return out.error = "in0 and in1 differ in size", out;
  std::vector<uint32_t> spirv;
  if (!requestSpirv(request, &spirv, &out.error)) return out;

  std::vector<std::string>& validationErrors = impl_->ctx.messages.errors;
  validationErrors.clear();
  const size_t n = request.in0.size();
  const size_t groups =
      std::max<size_t>((n + kLocalSize - 1) / kLocalSize, 1);  // every invocation reads and writes in bounds
  ComputeRun call(impl_->ctx, impl_->commandPool);
  if (!call.uploadInputs(request, groups * kLocalSize, &out.error) ||
      (request.lut != nullptr && !call.createLut(*request.lut, &out.error)) ||
      !call.createPipeline(spirv, &out.error) || !call.bindResources(&out.error) ||
      !call.dispatch(uint32_t(groups), impl_->ctx.queue, &out.error))
    return out;
  out.values = call.outputs(n);
  if (!validationErrors.empty()) {
    out.error = "Vulkan validation errors:";
    for (const auto& m : validationErrors) out.error += "\n  " + m;
  }
  return out;
}

}  // namespace facet::eval
