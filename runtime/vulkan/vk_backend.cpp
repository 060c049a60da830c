// The Vulkan RenderBackend: a headless forward pass into RGBA16F + D32, a post pass into RGBA8,
// and a readback. The frame graph (render_path.h) decides the render passes: merged (the post
// pass is subpass 1, reading HDR as an input attachment; HDR and depth transient unless HDR is
// read back) or separate (two render passes, HDR stored and sampled). render() and
// renderToImage() record the backend's own command buffer, submit it and wait on a fence;
// recordFrame() records into the app's, which the app submits, with up to framesInFlight frames
// unfinished. So what a frame writes exists once per frame in flight (FrameSlot), and what it
// replaces is retired, not destroyed (vk_retire.h); the LDR attachment is the backend's own
// target or a view of the app's image (vk_app_images.h).
#include <chrono>
#include <cstring>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/vulkan_backend.h"
#include "vk_app_images.h"
#include "vk_bloom.h"
#include "vk_check.h"
#include "vk_commands.h"
#include "vk_context.h"
#include "vk_convert.h"
#include "vk_frame.h"
#include "vk_memory.h"
#include "vk_pipeline.h"
#include "vk_post_inputs.h"
#include "vk_resources.h"
#include "vk_retire.h"
#include "vk_targets.h"
#include "vk_textures.h"
#include "vk_uniform_blocks.h"
#include "vk_uploads.h"

namespace facet::runtime {
namespace {

using namespace vulkan;

// A single-level sampler clamped to the edge, filtering with `filter`; with a compare op other
// than NEVER, a depth compare sampler.
bool createClampedSampler(VkDevice device, VkFilter filter, VkSampler* out, std::string* error,
                          VkCompareOp compare = VK_COMPARE_OP_NEVER) {
  VkSamplerCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  info.compareEnable = compare != VK_COMPARE_OP_NEVER ? VK_TRUE : VK_FALSE;
  info.compareOp = compare;
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxLod = 0.0f;
  if (!check(vkCreateSampler(device, &info, nullptr, out), "vkCreateSampler", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

// The uniform blocks of a draw's set 0: FrameUniforms, ObjectUniforms, MaterialParams and
// ShadowUniforms (createForwardSetLayout).
constexpr uint32_t kDrawBlocks = 4;

// A pool of `count` sets of `layout` (one per frame slot) and the sets.
bool createSlotSets(VkDevice device, VkDescriptorSetLayout layout, const std::vector<VkDescriptorPoolSize>& sizes,
                    uint32_t count, VkDescriptorPool* pool, std::vector<VkDescriptorSet>* sets, std::string* error) {
  VkDescriptorPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  poolInfo.maxSets = count;
  poolInfo.poolSizeCount = uint32_t(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  if (!check(vkCreateDescriptorPool(device, &poolInfo, nullptr, pool), "vkCreateDescriptorPool", error)) {
    *pool = VK_NULL_HANDLE;
    return false;
  }
  const std::vector<VkDescriptorSetLayout> layouts(count, layout);
  sets->assign(count, VK_NULL_HANDLE);
  VkDescriptorSetAllocateInfo setInfo{};
  setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  setInfo.descriptorPool = *pool;
  setInfo.descriptorSetCount = count;
  setInfo.pSetLayouts = layouts.data();
  return check(vkAllocateDescriptorSets(device, &setInfo, sets->data()), "vkAllocateDescriptorSets", error);
}

// A frame in flight may use what a cache evicts only if it is younger than the eviction age.
static_assert(kMaxFramesInFlight <= kEvictAfterFrames, "evicted entries must not be in use by frames in flight");

// A lavapipe frame under ASan and validation takes well under a second; a minute means hung.
constexpr uint64_t kFenceTimeoutNs = 60ull * 1000 * 1000 * 1000;

// A pipeline built for one ShaderProgram. The SPIR-V is kept so that a different program later
// allocated at the same address is noticed and gets its own pipeline.
struct CachedPipeline {
  std::vector<uint32_t> vertexSpirv;
  std::vector<uint32_t> fragmentSpirv;
  VkPipeline pipeline = VK_NULL_HANDLE;
  uint64_t lastUsedFrame = 0;  // released after kEvictAfterFrames frames unused (frame_eviction.h)
};

class VulkanBackend final : public VulkanRenderer {
 public:
  VulkanBackend() = default;
  ~VulkanBackend() override;
  VulkanBackend(const VulkanBackend&) = delete;
  VulkanBackend& operator=(const VulkanBackend&) = delete;

  bool init(const VulkanOptions& options, std::string* error);
  bool initOn(const AppDevice& device, const VulkanOptions& options, std::string* error);

  const char* name() const override { return "vulkan"; }
  PostPath postPath() const override { return path_; }
  bool readsBackHdr() const override { return readBackHdr_; }
  HdrFormat hdrFormat() const override { return hdrFormat_; }
  uint32_t msaaSamples() const override { return uint32_t(samples_.count); }
  bool toneMapsSamples() const override { return samples_.postReadsSamples; }
  bool fxaa() const override { return fxaa_; }
  double renderScale() const override { return renderScale_; }
  int bloomLevels() const override { return bloomOn_ ? bloom_.levels : 0; }
  std::string msaaMethod() const override;
  bool render(const FrameDesc& frame, FrameResult* result, std::string* error) override;
  bool renderToImage(const FrameDesc& frame, const AppImage& target, std::string* error) override;
  bool recordFrame(const FrameDesc& frame, const AppImage& target, VkCommandBuffer cmd, std::string* error) override;
  void forgetImage(VkImage image) override { appImages_.forget(image); }
  const std::vector<std::string>& validationErrors() const override { return ctx_.messages.errors; }
  ResourceCounts resources() const override {
    ResourceCounts counts{meshes_.residentCount(),       meshes_.uploadCount(),  materialBlocks_.residentCount(),
                          materialBlocks_.uploadCount(), ctx_.memoryAllocations, uploads_.stagedBytes()};
    counts.compressedTextureUploads = textures_.compressedUploads();
    counts.decodedTextureUploads = textures_.decodedUploads();
    counts.programs = pipelines_.size();
    counts.programBuilds = pipelineBuilds_;
    return counts;
  }

 private:
  bool planRenderPath(const VulkanOptions& options, std::string* error);
  bool createFixedObjects(std::string* error);
  bool checkSampleCount(std::string* error) const;
  bool ensureTargets(uint32_t width, uint32_t height, bool ownOutput, std::string* error);
  bool pipelineFor(const ShaderProgram& program, const DrawItem& draw, VertexLayout layout, bool depthOnly,
                   VkPipeline* out, std::string* error);
  bool ensureShadowAtlas(uint32_t size, std::string* error);
  bool uploadFrame(const FrameDesc& frame, std::vector<DrawSlot>* slots, std::string* error);
  bool ensureArena(VkDeviceSize size, std::string* error);
  bool prepareTextures(const FrameDesc& frame, std::string* error);
  bool allocateDrawSets(const FrameDesc& frame, std::vector<DrawSlot>* slots, std::string* error);
  bool renderFrame(const FrameDesc& frame, const AppImage* appImage, FrameResult* result, std::string* error);
  bool prepareFrame(const FrameDesc& frame, const AppImage* appImage, std::vector<DrawSlot>* slots, FrameOutput* output,
                    std::string* error);
  void writePostSet();
  bool createFxaaObjects(std::string* error);
  bool outputFor(const AppImage* appImage, FrameOutput* output, std::string* error);
  TargetConfig targetConfig() const;
  bool upscales() const { return renderScale_ < 1.0; }
  FrameObjects frameObjects(VkQueryPool timestamps, const FrameDesc& frame) const;
  // Submits the frame's command buffer and waits for it; *cpuMilliseconds (when not null): from
  // `start` until the submission returned (FrameResult::cpuSubmitMilliseconds).
  bool submitAndWait(std::string* error, double* cpuMilliseconds, std::chrono::steady_clock::time_point start);
  void readBack(FrameResult* result) const;
  void readTimes(FrameResult* result) const;

  // Declared first so it is destroyed last: the destructor body below destroys everything
  // created from the device before ~Context destroys the device and the instance.
  Context ctx_;

  // Fixed at creation from the options and the frame graph.
  PostPath path_ = PostPath::Merged;
  const PostShaders* post_ = nullptr;  // the post variant VulkanOptions::post chose
  bool readBackHdr_ = true;
  bool toneMapSamples_ = true;  // VulkanOptions::toneMapSamples, where the path allows it (samples_)
  uint32_t framesInFlight_ = 2;
  HdrFormat hdrFormat_ = HdrFormat::Rgba16Float;
  VertexPacking vertexPacking_ = VertexPacking::Packed;
  VkFormat hdrVkFormat_ = kHdrFormat;
  AttachmentOps hdrOps_, depthOps_, ldrOps_;
  // FXAA: ldrOps_ are the tone-mapped image's (the post pass's output), fxaaOps_ the output's.
  bool fxaa_ = false;
  AttachmentOps fxaaOps_;
  bool hdrTransient_ = false;
  bool depthTransient_ = false;
  // Below 1: HDR and depth at scaledSize() of the output, sampled bilinearly by the post pass's
  // upscaled form (the separate path).
  double renderScale_ = 1.0;
  // Bloom (post_->effects.bloom): the chain between the forward and the post pass, its passes'
  // ops from the frame graph.
  bool bloomOn_ = false;
  BloomSettings bloom_;
  AttachmentOps bloomDownOps_, bloomUpOps_;
  BloomChain bloomChain_;
  ForwardSamples samples_;       // MSAA: the count and the multisampled colour's ops
  bool clearInSubpass_ = false;  // FrameObjects::clearInSubpass: lavapipe's render-to-single-sampled

  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkQueryPool timestamps_ = VK_NULL_HANDLE;  // null when the queue has no timestamps

  VkRenderPass forwardPass_ = VK_NULL_HANDLE;  // merged path: the one render pass
  VkRenderPass postPass_ = VK_NULL_HANDLE;     // separate path only
  // The same passes with the app's image as LDR (vk_pipeline.h, kAppImageLdrLayouts): the
  // merged pass, or the separate path's post pass. Compatible with the ones above.
  VkRenderPass appImagePass_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout forwardSetLayout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout postSetLayout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout textureSetLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout forwardLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout postLayout_ = VK_NULL_HANDLE;
  VkPipeline postPipeline_ = VK_NULL_HANDLE;
  VkSampler hdrSampler_ = VK_NULL_HANDLE;
  // FXAA only: its render pass into the own LDR target, its set (the tone-mapped image, bilinear
  // through fxaaSampler_) and pipeline.
  VkRenderPass fxaaPass_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout fxaaSetLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout fxaaLayout_ = VK_NULL_HANDLE;
  VkPipeline fxaaPipeline_ = VK_NULL_HANDLE;
  VkSampler fxaaSampler_ = VK_NULL_HANDLE;
  VkDescriptorPool fxaaPool_ = VK_NULL_HANDLE;

  // What one frame writes and the next frames in flight must not: its uniforms, its draw
  // descriptor sets and the post pass's set. Frame n uses slots_[n % framesInFlight]; when it is
  // prepared, the frame that used the slot before has finished (render() waits for every frame;
  // recordFrame's caller promises it, vulkan_backend.h), so the slot is rewritten in place.
  struct FrameSlot {
    HostBuffer arena;  // uniforms of one frame (vk_frame.h's layout), grown when needed
    // Draw descriptor sets (two per draw: uniforms and textures): reset every use, recreated
    // larger when needed. Capacity counts draws.
    VkDescriptorPool drawPool = VK_NULL_HANDLE;
    uint32_t drawPoolCapacity = 0;
    VkDescriptorSet postSet = VK_NULL_HANDLE;  // from postPool_, written every use (HDR view)
    VkDescriptorSet fxaaSet = VK_NULL_HANDLE;  // FXAA only, from fxaaPool_, written every use
  };
  std::vector<FrameSlot> slots_;
  FrameSlot* slot_ = nullptr;  // the frame being prepared
  VkDescriptorPool postPool_ = VK_NULL_HANDLE;
  PostInputs postInputs_;  // the grading LUT and the post uniforms, when the variant reads them

  // Sampled textures, kept across frames; see vk_textures.h for the reuse rule.
  TextureCache textures_;

  // Device memory of meshes and material blocks (vk_memory.h), and their uploads (vk_uploads.h).
  BufferAllocator allocator_;
  UploadQueue uploads_;
  bool stageBufferUploads_ = false;
  // Meshes, uploaded once and shared by every draw of them; see vk_meshes.h.
  MeshCache meshes_;
  // Material instances' parameter blocks, uploaded when changed; see vk_uniform_blocks.h.
  UniformBlockCache materialBlocks_;

  RenderTargets targets_;
  // The sun's shadow pass (docs/shadows.md): its render pass and compare sampler, made once; the
  // atlas and its framebuffer, made at the first frame with a shadow pass and remade when the
  // atlas size changes. One atlas serves every frame in flight: the render pass's dependencies
  // order a frame's writes after the previous frame's reads.
  VkRenderPass shadowPass_ = VK_NULL_HANDLE;
  VkSampler shadowSampler_ = VK_NULL_HANDLE;
  Image shadowAtlas_;
  VkFramebuffer shadowFramebuffer_ = VK_NULL_HANDLE;
  ShadowBlocks shadowBlocks_;  // this frame's (layoutFrame)

  // Views and framebuffers of the app's images the post pass writes directly.
  AppImageCache appImages_;
  // What frames in flight may still use; see vk_retire.h.
  RetireQueue retire_;
  uint64_t frameNumber_ = 0;
  // Frames were recorded (recordFrame) since the queue was last known idle: render() waits for
  // the queue before reusing a frame slot that one of them may still read.
  bool recordedSinceIdle_ = false;
  // Keyed by program, the fixed-function state a draw asks for (blending, culling, masked, at the far plane), its
  // mesh's vertex layout (packed with 16-bit or fp32 positions, or full precision) and the pass
  // (forward, or the shadow pass's depth only). A program may be freed without the backend knowing:
  // a pipeline no draw asked for in kEvictAfterFrames frames is destroyed, as meshes and blocks are released.
  std::map<std::tuple<const ShaderProgram*, Blending, bool, bool, VertexLayout, bool, bool>, CachedPipeline> pipelines_;
  uint64_t pipelineBuilds_ = 0;

  // Set when a submission failed or did not finish: the command buffer and fence may still be
  // in use, so no further frame is attempted. Holds the original error.
  std::string deviceFailure_;
};

VulkanBackend::~VulkanBackend() {
  VkDevice device = ctx_.device;
  if (!device) return;  // nothing below can exist without a device
  vkDeviceWaitIdle(device);
  for (auto& entry : pipelines_) {
    if (entry.second.pipeline) vkDestroyPipeline(device, entry.second.pipeline, nullptr);
  }
  retire_.releaseAll();
  appImages_.destroy();
  textures_.destroy();
  meshes_.destroy();
  materialBlocks_.destroy();
  allocator_.destroy();  // after everything sub-allocated from it was released
  destroyRenderTargets(device, &targets_);
  if (shadowFramebuffer_) vkDestroyFramebuffer(device, shadowFramebuffer_, nullptr);
  destroyImage(device, &shadowAtlas_);
  if (shadowSampler_) vkDestroySampler(device, shadowSampler_, nullptr);
  if (shadowPass_) vkDestroyRenderPass(device, shadowPass_, nullptr);
  bloomChain_.destroy();
  // Destroying a pool frees its sets.
  for (FrameSlot& slot : slots_) {
    destroyHostBuffer(device, &slot.arena);
    if (slot.drawPool) vkDestroyDescriptorPool(device, slot.drawPool, nullptr);
  }
  if (postPool_) vkDestroyDescriptorPool(device, postPool_, nullptr);
  postInputs_.destroy();
  if (hdrSampler_) vkDestroySampler(device, hdrSampler_, nullptr);
  if (fxaaPool_) vkDestroyDescriptorPool(device, fxaaPool_, nullptr);
  if (fxaaSampler_) vkDestroySampler(device, fxaaSampler_, nullptr);
  if (fxaaPipeline_) vkDestroyPipeline(device, fxaaPipeline_, nullptr);
  if (fxaaLayout_) vkDestroyPipelineLayout(device, fxaaLayout_, nullptr);
  if (fxaaSetLayout_) vkDestroyDescriptorSetLayout(device, fxaaSetLayout_, nullptr);
  if (fxaaPass_) vkDestroyRenderPass(device, fxaaPass_, nullptr);
  if (postPipeline_) vkDestroyPipeline(device, postPipeline_, nullptr);
  if (postLayout_) vkDestroyPipelineLayout(device, postLayout_, nullptr);
  if (forwardLayout_) vkDestroyPipelineLayout(device, forwardLayout_, nullptr);
  if (postSetLayout_) vkDestroyDescriptorSetLayout(device, postSetLayout_, nullptr);
  if (forwardSetLayout_) vkDestroyDescriptorSetLayout(device, forwardSetLayout_, nullptr);
  if (textureSetLayout_) vkDestroyDescriptorSetLayout(device, textureSetLayout_, nullptr);
  if (postPass_) vkDestroyRenderPass(device, postPass_, nullptr);
  if (appImagePass_) vkDestroyRenderPass(device, appImagePass_, nullptr);
  if (forwardPass_) vkDestroyRenderPass(device, forwardPass_, nullptr);
  if (timestamps_) vkDestroyQueryPool(device, timestamps_, nullptr);
  if (fence_) vkDestroyFence(device, fence_, nullptr);
  // Destroying the pool frees its command buffer.
  if (commandPool_) vkDestroyCommandPool(device, commandPool_, nullptr);
}

bool VulkanBackend::init(const VulkanOptions& options, std::string* error) {
  const bool validation = options.validation || validationRequestedByEnvironment();
  if (!planRenderPath(options, error) || !ctx_.init(validation, options.float16Arithmetic,
                                                    options.msaaSamples > 1 && options.renderToSingleSampled, error))
    return false;
  samples_.renderToSingleSampled = ctx_.createRenderPass2;
  clearInSubpass_ = samples_.renderToSingleSampled && std::strncmp(ctx_.properties.deviceName, "llvmpipe", 8) == 0;
  return createFixedObjects(error);
}

bool VulkanBackend::initOn(const AppDevice& device, const VulkanOptions& options, std::string* error) {
  return planRenderPath(options, error) && ctx_.adopt(device, error) && createFixedObjects(error);
}

// Derives the render passes' load/store ops and the transient targets from the frame graph.
// They do not depend on the frame size, so a 1x1 graph decides them once.
bool VulkanBackend::planRenderPath(const VulkanOptions& options, std::string* error) {
  if (!isRenderScale(options.renderScale)) {
    *error = renderScaleError("VulkanOptions::renderScale", options.renderScale);
    return false;
  }
  renderScale_ = options.renderScale;
  bloomOn_ = options.post.bloom;
  bloom_ = options.bloom;
  if (bloomOn_ && !(*error = bloomSettingsError("VulkanOptions::bloom", bloom_)).empty()) return false;
  path_ = effectivePostPath(options.postPath == PostPath::Separate ? PostPath::Separate : PostPath::Merged,
                            renderScale_, bloomOn_);
  readBackHdr_ = options.readBackHdr;
  if (options.framesInFlight < 1 || options.framesInFlight > kMaxFramesInFlight) {
    *error = "VulkanOptions::framesInFlight must be 1.." + std::to_string(kMaxFramesInFlight) + ", not " +
             std::to_string(options.framesInFlight);
    return false;
  }
  framesInFlight_ = options.framesInFlight;
  stageBufferUploads_ = options.stageBufferUploads;
  hdrFormat_ = options.hdrFormat;
  vertexPacking_ = options.vertexPacking;
  hdrVkFormat_ = hdrFormat_ == HdrFormat::R11G11B10Float ? VK_FORMAT_B10G11R11_UFLOAT_PACK32 : kHdrFormat;
  post_ = findPostShaders(options.post, error);
  if (!post_) return false;
  if (!isMsaaSampleCount(options.msaaSamples)) {
    *error = "VulkanOptions::msaaSamples must be 1, 2 or 4, not " + std::to_string(options.msaaSamples);
    return false;
  }
  samples_.count = static_cast<VkSampleCountFlagBits>(options.msaaSamples);
  toneMapSamples_ = options.toneMapSamples;
  fxaa_ = options.fxaa;
  // Large enough for every bloom level (bloomLevelSizes): the ops do not depend on the size.
  const uint32_t planSize = bloomOn_ ? 2u << bloom_.levels : 1;
  const int bloomLevels = bloomOn_ ? bloom_.levels : 0;
  const ForwardPostGraph g =
      buildForwardPostGraph(planSize, planSize, path_, readBackHdr_, hdrFormat_, options.msaaSamples, options.fxaa,
                            renderScale_, bloomLevels, 0, toneMapSamples_);
  fg::CompiledGraph compiled;
  if (!g.graph.compile(&compiled, error)) return false;
  const size_t expected =
      (path_ == PostPath::Merged ? 1 : 2) + (fxaa_ ? 1 : 0) + (bloomOn_ ? 2 * bloom_.levels - 1 : 0);
  if (compiled.renderPasses.size() != expected) {
    *error = std::string("frame graph gave ") + std::to_string(compiled.renderPasses.size()) +
             " render passes for the " + toString(path_) + " path";
    return false;
  }
  // The render pass each pass runs in (bloom's chain sits between the forward and the post pass).
  const auto renderPassOf = [&](uint32_t pass) {
    for (uint32_t r = 0; r < compiled.renderPasses.size(); ++r)
      for (uint32_t p : compiled.renderPasses[r].subpasses)
        if (p == pass) return r;
    return uint32_t(0);
  };
  const uint32_t postRenderPass = renderPassOf(g.postPass);
  if (bloomOn_) {
    bloomDownOps_ = toVulkan(*compiled.attachment(renderPassOf(g.bloomDownPasses[0]), g.bloom[0]));
    if (!g.bloomUpPasses.empty())
      bloomUpOps_ = toVulkan(*compiled.attachment(renderPassOf(g.bloomUpPasses.back()), g.bloom[0]));
  }
  hdrOps_ = toVulkan(*compiled.attachment(0, g.hdr));
  depthOps_ = toVulkan(*compiled.attachment(0, g.depth));
  ldrOps_ = toVulkan(*compiled.attachment(postRenderPass, g.toneMapped));
  if (fxaa_) fxaaOps_ = toVulkan(*compiled.attachment(renderPassOf(g.fxaaPass), g.ldr));
  hdrTransient_ = compiled.traffic[g.hdr].transient;
  depthTransient_ = compiled.traffic[g.depth].transient;
  if (g.hdrSamples != g.hdr) {
    samples_.colour = toVulkan(*compiled.attachment(0, g.hdrSamples));
    if (!compiled.traffic[g.hdrSamples].transient || !depthTransient_) {
      *error = "frame graph stores the MSAA samples";  // render_path.h resolves them in the pass
      return false;
    }
  }
  return true;
}

std::string VulkanBackend::msaaMethod() const {
  std::string method = samples_.count == VK_SAMPLE_COUNT_1_BIT ? "off"
                       : samples_.renderToSingleSampled
                           ? "VK_EXT_multisampled_render_to_single_sampled (samples kept by the driver)"
                       : samples_.postReadsSamples
                           ? "multisampled attachments resolved by pResolveAttachments; the post subpass tone maps "
                             "each sample (subpassInputMS)"
                           : "multisampled attachments resolved by pResolveAttachments";
  // createImage falls back to device-local memory where the device has no lazily allocated type.
  const Image& transient = samples_.resolveAttachment() ? targets_.hdrSamples : targets_.depth;
  if (depthTransient_ && transient.image) {
    method += transient.lazilyAllocated ? "; transient attachments in lazily allocated memory"
                                        : "; transient attachments in device-local memory (the device offers no "
                                          "lazily allocated memory type)";
  }
  return method;
}

// A count the device does not offer is an error here, never a validation error later: the
// framebuffer limits bound every attachment, the image format's own counts the HDR format's.
bool VulkanBackend::checkSampleCount(std::string* error) const {
  const VkPhysicalDeviceLimits& limits = ctx_.properties.limits;
  VkImageFormatProperties hdrImage{};
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
  const VkSampleCountFlags hdrCounts =
      vkGetPhysicalDeviceImageFormatProperties(ctx_.physicalDevice, hdrVkFormat_, VK_IMAGE_TYPE_2D,
                                               VK_IMAGE_TILING_OPTIMAL, usage, 0, &hdrImage) == VK_SUCCESS
          ? hdrImage.sampleCounts
          : VkSampleCountFlags{VK_SAMPLE_COUNT_1_BIT};
  const VkSampleCountFlags offered =
      limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts & hdrCounts;
  if ((offered & samples_.count) != 0) return true;
  std::string list;
  for (uint32_t n = 1; n <= 64; n *= 2) {
    if (offered & n) list += (list.empty() ? "" : ", ") + std::to_string(n);
  }
  *error = "MSAA " + std::to_string(uint32_t(samples_.count)) + "x is not offered by this device for " +
           toString(hdrFormat_) + " colour with D32F depth (sample counts offered: " + list + ")";
  return false;
}

// Objects that live as long as the backend and do not depend on the frame.
bool VulkanBackend::createFixedObjects(std::string* error) {
  VkDevice device = ctx_.device;

  if (!createSubmitRecorder(device, ctx_.queueFamily, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, &commandPool_,
                            &commandBuffer_, &fence_, error)) {
    return false;
  }

  const bool merged = path_ == PostPath::Merged;
  // Known only now: whether the context took VK_EXT_multisampled_render_to_single_sampled, whose
  // implicit resolve leaves no samples to read.
  samples_.postReadsSamples = toneMapSamples_ && merged && samples_.resolveAttachment();
  if (!checkSampleCount(error)) return false;
  // RGBA16F is checked with the context's required formats; R11G11B10F's colour-attachment use is
  // optional in Vulkan (supported on lavapipe and current mobile GPUs), so it is checked here.
  VkFormatProperties hdrProperties{};
  vkGetPhysicalDeviceFormatProperties(ctx_.physicalDevice, hdrVkFormat_, &hdrProperties);
  const VkFormatFeatureFlags hdrNeeds =
      VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT |
      (merged ? 0 : VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) | (readBackHdr_ ? VK_FORMAT_FEATURE_TRANSFER_SRC_BIT : 0) |
      (upscales() || bloomOn_ ? VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT : 0);
  if ((hdrProperties.optimalTilingFeatures & hdrNeeds) != hdrNeeds) {
    *error = std::string("the device cannot use ") + toString(hdrFormat_) + " as the HDR target (format features " +
             std::to_string(hdrProperties.optimalTilingFeatures) + ", needs " + std::to_string(hdrNeeds) + ")";
    return false;
  }
  // Both packed layouts: a mesh gets one or the other by its positions' error (vertex_packing.h).
  if (vertexPacking_ == VertexPacking::Packed &&
      (!supportsVertexLayout(ctx_.physicalDevice, VertexLayout::Packed, error) ||
       !supportsVertexLayout(ctx_.physicalDevice, VertexLayout::PackedFloatPositions, error))) {
    return false;
  }
  const VkDescriptorType hdrType =
      merged ? VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  const LdrLayouts postOutput = fxaa_ ? kFxaaInputLayouts : LdrLayouts{};
  const bool passesMade =
      merged ? createMergedRenderPass(device, hdrVkFormat_, hdrOps_, depthOps_, ldrOps_, samples_, postOutput,
                                      &forwardPass_, error) &&
                   createMergedRenderPass(device, hdrVkFormat_, hdrOps_, depthOps_, ldrOps_, samples_,
                                          kAppImageLdrLayouts, &appImagePass_, error)
             : createForwardRenderPass(device, hdrVkFormat_, hdrOps_, depthOps_, samples_, &forwardPass_, error) &&
                   createPostRenderPass(device, ldrOps_, postOutput, &postPass_, error) &&
                   createPostRenderPass(device, ldrOps_, kAppImageLdrLayouts, &appImagePass_, error);
  if (!passesMade || !createShadowRenderPass(device, &shadowPass_, error) ||
      !createForwardSetLayout(device, &forwardSetLayout_, error) ||
      !createPostSetLayout(device, hdrType, PostInputs::bindings(post_->effects, upscales()), &postSetLayout_, error) ||
      !createTextureSetLayout(device, &textureSetLayout_, error) ||
      !createPipelineLayout(device, {forwardSetLayout_, textureSetLayout_}, &forwardLayout_, error) ||
      !createPipelineLayout(device, {postSetLayout_}, &postLayout_, error)) {
    return false;
  }
  if (!textures_.init(&ctx_, &retire_, error)) return false;
  appImages_.init(device, &retire_);
  allocator_.init(&ctx_, stageBufferUploads_);
  uploads_.init(&allocator_, &retire_);
  meshes_.init(&allocator_, &uploads_, &retire_, vertexPacking_);
  materialBlocks_.init(&allocator_, &uploads_, &retire_);

  if (ctx_.timestampValidBits > 0) {
    VkQueryPoolCreateInfo queryInfo{};
    queryInfo.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
    queryInfo.queryCount = kTimestampCount;
    if (!check(vkCreateQueryPool(device, &queryInfo, nullptr, &timestamps_), "vkCreateQueryPool", error)) {
      timestamps_ = VK_NULL_HANDLE;
      return false;
    }
  }

  const PostShaders& post = *post_;
  PipelineDesc postDesc;
  postDesc.kind = PipelineKind::Post;
  postDesc.vertexSpirv = &post.vertexSpirv;
  postDesc.fragmentSpirv = samples_.postReadsSamples ? &post.fragmentSamplesSpirv
                           : merged                  ? &post.fragmentFetchSpirv
                           : upscales()              ? &post.fragmentUpscaledSpirv
                                                     : &post.fragmentSpirv;
  postDesc.postSampleCount = samples_.postReadsSamples ? uint32_t(samples_.count) : 0;
  postDesc.layout = postLayout_;
  postDesc.renderPass = merged ? forwardPass_ : postPass_;
  postDesc.subpass = merged ? 1 : 0;
  postDesc.colourSlots = merged ? 2 : 1;
  postDesc.what = "post pass shaders";
  if (!createGraphicsPipeline(device, postDesc, &postPipeline_, error)) return false;

  // Nearest + clamp: the post pass reads exactly one HDR texel per output pixel.
  // Upscaling: bilinear between the smaller HDR image's texels.
  if (!createClampedSampler(device, upscales() ? VK_FILTER_LINEAR : VK_FILTER_NEAREST, &hdrSampler_, error))
    return false;
  // The receivers' depth compare (chunks/shadow_sun.glsl): lit when ref <= stored. Bilinear
  // filtering of the comparisons only where the format allows it (lavapipe's D16 does not).
  VkFormatProperties atlasProperties{};
  vkGetPhysicalDeviceFormatProperties(ctx_.physicalDevice, kShadowAtlasFormat, &atlasProperties);
  const VkFormatFeatureFlags atlasNeeds =
      VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
  if ((atlasProperties.optimalTilingFeatures & atlasNeeds) != atlasNeeds) {
    *error = "the device cannot render and sample D16 depth (the shadow atlas)";
    return false;
  }
  const bool linearAtlas =
      (atlasProperties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
  if (!createClampedSampler(device, linearAtlas ? VK_FILTER_LINEAR : VK_FILTER_NEAREST, &shadowSampler_, error,
                            VK_COMPARE_OP_LESS_OR_EQUAL))
    return false;

  slots_.resize(framesInFlight_);
  const auto slotCount = static_cast<uint32_t>(slots_.size());
  if (!postInputs_.init(&ctx_, post_->effects, upscales(), slotCount, error)) return false;
  postInputs_.setBloom(bloom_);
  if (bloomOn_ &&
      !bloomChain_.init(&ctx_, hdrVkFormat_, bloom_, bloomDownOps_, bloomUpOps_, slotCount, readBackHdr_, error))
    return false;
  std::vector<VkDescriptorPoolSize> postPoolSizes{{hdrType, slotCount}};
  for (const VkDescriptorSetLayoutBinding& b : PostInputs::bindings(post_->effects, upscales()))
    postPoolSizes.push_back({b.descriptorType, slotCount});
  std::vector<VkDescriptorSet> postSets;
  if (!createSlotSets(device, postSetLayout_, postPoolSizes, slotCount, &postPool_, &postSets, error)) return false;
  for (uint32_t i = 0; i < slotCount; ++i) slots_[i].postSet = postSets[i];
  return !fxaa_ || createFxaaObjects(error);
}

// The FXAA pass: a render pass into the own LDR target, a pipeline sampling the tone-mapped image
// bilinearly (chunks/fxaa.glsl reads between texel centres), and a set per frame slot.
bool VulkanBackend::createFxaaObjects(std::string* error) {
  VkDevice device = ctx_.device;
  if (!createPostRenderPass(device, fxaaOps_, LdrLayouts{}, &fxaaPass_, error) ||
      !createPostSetLayout(device, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {}, &fxaaSetLayout_, error) ||
      !createPipelineLayout(device, {fxaaSetLayout_}, &fxaaLayout_, error)) {
    return false;
  }
  PipelineDesc desc;
  desc.kind = PipelineKind::Post;
  desc.vertexSpirv = &post_->vertexSpirv;
  desc.fragmentSpirv = &fxaaShader().fragmentSpirv;
  desc.layout = fxaaLayout_;
  desc.renderPass = fxaaPass_;
  desc.subpass = 0;
  desc.colourSlots = 1;
  desc.what = "FXAA pass shaders";
  if (!createGraphicsPipeline(device, desc, &fxaaPipeline_, error)) return false;
  if (!createClampedSampler(device, VK_FILTER_LINEAR, &fxaaSampler_, error)) return false;
  const auto slotCount = static_cast<uint32_t>(slots_.size());
  std::vector<VkDescriptorSet> sets;
  if (!createSlotSets(device, fxaaSetLayout_, {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, slotCount}}, slotCount,
                      &fxaaPool_, &sets, error))
    return false;
  for (uint32_t i = 0; i < slotCount; ++i) slots_[i].fxaaSet = sets[i];
  return true;
}

bool VulkanBackend::render(const FrameDesc& frame, FrameResult* result, std::string* error) {
  std::string scratch;
  if (!error) error = &scratch;
  if (!result) {
    *error = "render: result is null";
    return false;
  }
  return renderFrame(frame, nullptr, result, error);
}

bool VulkanBackend::renderToImage(const FrameDesc& frame, const AppImage& target, std::string* error) {
  std::string scratch;
  if (!error) error = &scratch;
  if (!checkAppImage(frame, target, "renderToImage", error)) return false;
  return renderFrame(frame, &target, nullptr, error);
}

bool VulkanBackend::recordFrame(const FrameDesc& frame, const AppImage& target, VkCommandBuffer cmd,
                                std::string* error) {
  std::string scratch;
  if (!error) error = &scratch;
  if (!cmd) {
    *error = "recordFrame: the command buffer is null";
    return false;
  }
  if (!checkAppImage(frame, target, "recordFrame", error)) return false;
  if (!deviceFailure_.empty()) {
    *error = "Vulkan backend unusable after an earlier failure: " + deviceFailure_;
    return false;
  }
  try {
    // The caller's promise: frame frameNumber_ + 1 - framesInFlight_ and all before it have
    // finished, so what was retired while preparing them is free (vk_retire.h).
    const uint64_t next = frameNumber_ + 1;
    if (next > framesInFlight_) retire_.releaseThrough(next - framesInFlight_);
    std::vector<DrawSlot> slots;
    FrameOutput output;
    if (!prepareFrame(frame, &target, &slots, &output, error)) return false;
    // Not timed: the query pool would be shared by frames in flight.
    const FrameObjects objects = frameObjects(VK_NULL_HANDLE, frame);
    if (!uploads_.record(cmd, error)) return false;
    recordPasses(cmd, objects, output, {targets_.forwardWidth, targets_.forwardHeight}, {frame.width, frame.height},
                 frame.clearColor, slots);
    if (!output.directImage) recordCopyToAppImage(cmd, targets_, target);
    appImages_.evictUnused(frameNumber_);
    recordedSinceIdle_ = true;
    return true;
  } catch (const std::exception& e) {
    *error = std::string("Vulkan backend: ") + e.what();
    return false;
  }
}

// Everything before recording: the frame checked, the targets, pipelines, meshes, uniforms,
// textures and descriptor sets ready in this frame's slot, and where the passes write.
bool VulkanBackend::prepareFrame(const FrameDesc& frame, const AppImage* appImage, std::vector<DrawSlot>* slots,
                                 FrameOutput* output, std::string* error) {
  retire_.beginFrame(++frameNumber_);
  slot_ = &slots_[frameNumber_ % slots_.size()];
  // The backend's own LDR target only for a readback or a copy (TargetConfig::ownOutput). FXAA
  // writes the own target and the frame is copied into the app's image.
  const bool ownOutput = !appImage || !rendersDirectly(*appImage) || fxaa_;
  // With a shadow pass, the casters are drawn as draws of their own after the forward draws
  // (FrameDraws), checked with them.
  if (!checkFrame(frame, ctx_.properties.limits, error) ||
      !ensureTargets(frame.width, frame.height, ownOutput, error) ||
      (frame.shadow && !ensureShadowAtlas(frame.shadow->atlasSize, error)) || !uploadFrame(frame, slots, error) ||
      !prepareTextures(frame, error) || !allocateDrawSets(frame, slots, error) || !outputFor(appImage, output, error)) {
    return false;
  }
  if (bloomOn_) {
    BloomChain::Targets old;
    if (!bloomChain_.ensureTargets(targets_.forwardWidth, targets_.forwardHeight, &old, error)) return false;
    if (!old.levels.empty()) {
      VkDevice device = ctx_.device;
      retire_.retire([device, old]() mutable { BloomChain::destroyTargets(device, &old); });
    }
    const auto slot = uint32_t(frameNumber_ % slots_.size());
    bloomChain_.writeSets(slot, targets_.hdr.view, postInputs_.uniformBuffer(slot));
  }
  writePostSet();
  return postInputs_.prepare(frame, slot_->postSet, size_t(frameNumber_ % slots_.size()), error);
}

// result: read back into (render); null when the frame goes into appImage (renderToImage).
bool VulkanBackend::renderFrame(const FrameDesc& frame, const AppImage* appImage, FrameResult* result,
                                std::string* error) {
  const auto start = std::chrono::steady_clock::now();
  if (!deviceFailure_.empty()) {
    *error = "Vulkan backend unusable after an earlier failure: " + deviceFailure_;
    return false;
  }
  // The API promises no exceptions; the only ones possible here are allocation failures.
  try {
    if (recordedSinceIdle_) {
      // The app has submitted its recorded frames (the rule in vulkan_backend.h); this frame's
      // slot and what they retired are free once they have finished.
      if (!check(vkQueueWaitIdle(ctx_.queue), "vkQueueWaitIdle", error)) {
        deviceFailure_ = *error;
        return false;
      }
      retire_.releaseAll();
      recordedSinceIdle_ = false;
    }
    std::vector<DrawSlot> slots;
    FrameOutput output;
    if (!prepareFrame(frame, appImage, &slots, &output, error)) return false;
    const FrameObjects objects = frameObjects(timestamps_, frame);
    VkCommandBuffer cmd = commandBuffer_;
    VkCommandBufferBeginInfo beginInfo{};
    beginInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (!check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer", error) ||
        !check(vkBeginCommandBuffer(cmd, &beginInfo), "vkBeginCommandBuffer", error)) {
      return false;
    }
    if (!uploads_.record(cmd, error)) return false;
    recordPasses(cmd, objects, output, {targets_.forwardWidth, targets_.forwardHeight}, {frame.width, frame.height},
                 frame.clearColor, slots);
    if (!appImage) {
      recordReadback(cmd, objects.merged, readBackHdr_, targets_);
      if (bloomOn_ && readBackHdr_) bloomChain_.recordReadback(cmd);
    } else if (!output.directImage) {
      recordCopyToAppImage(cmd, targets_, *appImage);
    }
    if (!check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", error)) return false;
    if (!submitAndWait(error, result ? &result->cpuSubmitMilliseconds : nullptr, start)) {
      deviceFailure_ = *error;
      return false;
    }
    // Waited for: this frame and everything submitted before it on the queue has finished.
    retire_.releaseAll();
    appImages_.evictUnused(frameNumber_);
    if (result) {
      readBack(result);
      readTimes(result);
    }
    return true;
  } catch (const std::exception& e) {
    *error = std::string("Vulkan backend: ") + e.what();
    return false;
  }
}

// The backend's own LDR target (render, and renderToImage into an image it cannot render to),
// or the app's image as the LDR attachment.
bool VulkanBackend::outputFor(const AppImage* appImage, FrameOutput* output, std::string* error) {
  const bool merged = path_ == PostPath::Merged;
  output->forwardPass = forwardPass_;
  output->postPass = postPass_;
  output->framebuffers = {targets_.forwardFramebuffer, targets_.postFramebuffer};
  output->fxaaPass = fxaaPass_;
  output->fxaaFramebuffer = targets_.fxaaFramebuffer;
  if (!appImage || !rendersDirectly(*appImage) || fxaa_) return true;
  output->directImage = appImage;
  if (merged) {
    output->forwardPass = appImagePass_;
  } else {
    output->postPass = appImagePass_;
  }
  return appImages_.framebuffersFor(*appImage, targets_, targetConfig(), frameNumber_, &output->framebuffers, error);
}

FrameObjects VulkanBackend::frameObjects(VkQueryPool timestamps, const FrameDesc& frame) const {
  return {path_ == PostPath::Merged,
          samples_.resolveAttachment(),
          clearInSubpass_,
          forwardLayout_,
          postLayout_,
          postPipeline_,
          slot_->postSet,
          fxaaLayout_,
          fxaaPipeline_,
          slot_->fxaaSet,
          bloomOn_ ? &bloomChain_ : nullptr,
          uint32_t(frameNumber_ % slots_.size()),
          timestamps,
          slot_->arena.buffer,
          frame.shadow ? &*frame.shadow : nullptr,
          shadowPass_,
          shadowFramebuffer_};
}

bool VulkanBackend::ensureShadowAtlas(uint32_t size, std::string* error) {
  if (shadowAtlas_.width == size) return true;
  VkDevice device = ctx_.device;
  if (shadowAtlas_.image) {
    // Frames in flight may still draw into or sample the old atlas.
    retire_.retire([device, old = shadowAtlas_, framebuffer = shadowFramebuffer_]() mutable {
      vkDestroyFramebuffer(device, framebuffer, nullptr);
      destroyImage(device, &old);
    });
    shadowAtlas_ = Image{};
    shadowFramebuffer_ = VK_NULL_HANDLE;
  }
  if (!createImage(ctx_, size, size, kShadowAtlasFormat,
                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_ASPECT_DEPTH_BIT,
                   &shadowAtlas_, error)) {
    return false;
  }
  if (!createFramebuffer(device, shadowPass_, &shadowAtlas_.view, 1, size, size, &shadowFramebuffer_, error)) {
    destroyImage(device, &shadowAtlas_);
    return false;
  }
  return true;
}

TargetConfig VulkanBackend::targetConfig() const {
  TargetConfig config;
  config.merged = path_ == PostPath::Merged;
  config.readBackHdr = readBackHdr_;
  config.hdrTransient = hdrTransient_;
  config.depthTransient = depthTransient_;
  config.samples = samples_.count;
  config.renderToSingleSampled = samples_.renderToSingleSampled != nullptr;
  config.postReadsSamples = samples_.postReadsSamples;
  config.hdrFormat = hdrVkFormat_;
  config.forwardPass = forwardPass_;
  config.postPass = postPass_;
  config.fxaa = fxaa_;
  config.fxaaPass = fxaaPass_;
  config.renderScale = renderScale_;
  return config;
}

// Recreated for a new size, or to add the own output a frame needs (kept once made: render() and
// recordFrame() may alternate).
bool VulkanBackend::ensureTargets(uint32_t width, uint32_t height, bool ownOutput, std::string* error) {
  const bool haveOwnOutput = targets_.ldr.image != VK_NULL_HANDLE;
  if (targets_.width == width && targets_.height == height && (haveOwnOutput || !ownOutput)) return true;
  // Frames in flight may still render into the old targets.
  appImages_.dropAll();
  if (targets_.width != 0) {
    VkDevice device = ctx_.device;
    retire_.retire([device, old = targets_]() mutable { destroyRenderTargets(device, &old); });
    targets_ = RenderTargets{};
  }
  TargetConfig config = targetConfig();
  config.ownOutput = ownOutput;
  return createRenderTargets(ctx_, width, height, config, &targets_, error);
}

// The post pass reads this frame's HDR image through the slot's set.
void VulkanBackend::writePostSet() {
  const bool merged = path_ == PostPath::Merged;
  // An input attachment descriptor ignores the sampler.
  VkDescriptorImageInfo imageInfo{merged ? VK_NULL_HANDLE : hdrSampler_,
                                  samples_.postReadsSamples ? targets_.hdrSamples.view : targets_.hdr.view,
                                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet write{};
  write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  write.dstSet = slot_->postSet;
  write.dstBinding = abi::kPostHdrBinding;
  write.descriptorCount = 1;
  write.descriptorType = merged ? VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &imageInfo;
  vkUpdateDescriptorSets(ctx_.device, 1, &write, 0, nullptr);
  if (bloomOn_) {
    const VkDescriptorImageInfo bloom{bloomChain_.sampler(), bloomChain_.level0(),
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    write.dstBinding = abi::kPostBloomBinding;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &bloom;
    vkUpdateDescriptorSets(ctx_.device, 1, &write, 0, nullptr);
    write.dstBinding = abi::kPostHdrBinding;
  }
  if (!fxaa_) return;
  const VkDescriptorImageInfo toneMapped{fxaaSampler_, targets_.toneMapped.view,
                                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  write.dstSet = slot_->fxaaSet;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &toneMapped;
  vkUpdateDescriptorSets(ctx_.device, 1, &write, 0, nullptr);
}

bool VulkanBackend::pipelineFor(const ShaderProgram& program, const DrawItem& draw, VertexLayout layout, bool depthOnly,
                                VkPipeline* out, std::string* error) {
  const auto key =
      std::make_tuple(&program, draw.blending, draw.cullBackFaces, draw.masked, layout, depthOnly, draw.atFarPlane);
  auto found = pipelines_.find(key);
  if (found != pipelines_.end()) {
    CachedPipeline& cached = found->second;
    if (cached.vertexSpirv == program.vertexSpirv && cached.fragmentSpirv == program.fragmentSpirv) {
      cached.lastUsedFrame = frameNumber_;
      *out = cached.pipeline;
      return true;
    }
    // Another program now lives at this address; frames in flight may still draw with it.
    VkDevice device = ctx_.device;
    retire_.retire([device, pipeline = cached.pipeline] { vkDestroyPipeline(device, pipeline, nullptr); });
    pipelines_.erase(found);
  }
  PipelineDesc desc;
  desc.kind = PipelineKind::Forward;
  desc.blending = draw.blending;
  desc.cullBackFaces = draw.cullBackFaces;
  desc.atFarPlane = draw.atFarPlane;
  desc.samples = samples_.count;
  desc.alphaToCoverage = draw.masked;
  desc.vertexLayout = layout;
  desc.vertexSpirv = &program.vertexSpirv;
  desc.fragmentSpirv = &program.fragmentSpirv;
  desc.layout = forwardLayout_;
  desc.renderPass = forwardPass_;
  desc.what = "material shaders";
  if (depthOnly) {
    desc.kind = PipelineKind::Depth;
    desc.samples = VK_SAMPLE_COUNT_1_BIT;
    desc.alphaToCoverage = false;
    desc.renderPass = shadowPass_;
    desc.what = "depth-only shaders";
  }
  VkPipeline pipeline = VK_NULL_HANDLE;
  if (!createGraphicsPipeline(ctx_.device, desc, &pipeline, error)) return false;
  pipelines_[key] = CachedPipeline{program.vertexSpirv, program.fragmentSpirv, pipeline, frameNumber_};
  ++pipelineBuilds_;
  *out = pipeline;
  return true;
}

bool VulkanBackend::ensureArena(VkDeviceSize size, std::string* error) {
  HostBuffer& arena = slot_->arena;
  if (arena.buffer && arena.size >= size) return true;
  destroyHostBuffer(ctx_.device, &arena);  // the slot's previous frame has finished
  VkDeviceSize capacity = 64 * 1024;
  while (capacity < size) capacity *= 2;
  return createHostBuffer(ctx_, capacity, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                          &arena, error);
}

// Makes each draw's mesh resident, builds (or finds) its pipeline for the mesh's vertex layout,
// then lays the frame's uniforms out in the arena and copies them in.
bool VulkanBackend::uploadFrame(const FrameDesc& frame, std::vector<DrawSlot>* slots, std::string* error) {
  const VkDeviceSize size = layoutFrame(frame, ctx_.properties.limits, slots, &shadowBlocks_);
  if (!meshes_.prepare(frame, error)) return false;
  const FrameDraws draws(frame);
  for (size_t i = 0; i < draws.size(); ++i) {
    DrawSlot& slot = (*slots)[i];
    const DrawItem& draw = draws[i];
    slot.mesh = meshes_.locate(draw.mesh);
    if (!pipelineFor(*draw.program, draw, slot.mesh.layout, draws.isCaster(i), &slot.pipeline, error)) {
      *error = "draw " + std::to_string(i) + ": " + *error;
      return false;
    }
  }
  // Frames in flight may still draw with an evicted pipeline: destroyed once they have finished.
  VkDevice device = ctx_.device;
  evictUnusedEntries(pipelines_, frameNumber_, [&](const CachedPipeline& cached) {
    retire_.retire([device, pipeline = cached.pipeline] { vkDestroyPipeline(device, pipeline, nullptr); });
  });
  if (!materialBlocks_.prepare(frame, error) || !ensureArena(size, error)) return false;
  for (size_t i = 0; i < draws.size(); ++i) {
    DrawSlot& slot = (*slots)[i];
    slot.materialBuffer = draws[i].materialBlock ? materialBlocks_.locate(draws[i].materialBlock) : slot_->arena.buffer;
  }
  // Host-coherent memory, and vkQueueSubmit makes host writes visible to the device.
  writeFrame(frame, *slots, shadowBlocks_, samples_.count != VK_SAMPLE_COUNT_1_BIT, slot_->arena.mapped);
  return true;
}

bool VulkanBackend::prepareTextures(const FrameDesc& frame, std::string* error) {
  if (textures_.prepare(frame, error)) return true;
  if (textures_.deviceFailed()) deviceFailure_ = *error;
  return false;
}

bool VulkanBackend::allocateDrawSets(const FrameDesc& frame, std::vector<DrawSlot>* slots, std::string* error) {
  const uint32_t count = static_cast<uint32_t>(slots->size());
  if (count == 0) return true;
  VkDevice device = ctx_.device;
  VkDescriptorPool& drawPool = slot_->drawPool;
  if (count > slot_->drawPoolCapacity) {
    // The slot's previous frame has finished: its sets are no longer in use.
    if (drawPool) vkDestroyDescriptorPool(device, drawPool, nullptr);
    drawPool = VK_NULL_HANDLE;
    slot_->drawPoolCapacity = 0;
    uint32_t capacity = 64;
    while (capacity < count) capacity *= 2;
    const VkDescriptorPoolSize poolSizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kDrawBlocks * capacity},
                                               {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kTextureSlots * capacity}};
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.maxSets = 2 * capacity;
    info.poolSizeCount = 2;
    info.pPoolSizes = poolSizes;
    if (!check(vkCreateDescriptorPool(device, &info, nullptr, &drawPool), "vkCreateDescriptorPool", error)) {
      drawPool = VK_NULL_HANDLE;
      return false;
    }
    slot_->drawPoolCapacity = capacity;
  } else if (!check(vkResetDescriptorPool(device, drawPool, 0), "vkResetDescriptorPool", error)) {
    return false;
  }

  // Per draw: set 0 then set 1.
  std::vector<VkDescriptorSetLayout> layouts;
  layouts.reserve(2 * size_t{count});
  for (uint32_t i = 0; i < count; ++i) {
    layouts.push_back(forwardSetLayout_);
    layouts.push_back(textureSetLayout_);
  }
  std::vector<VkDescriptorSet> sets(layouts.size());
  VkDescriptorSetAllocateInfo allocInfo{};
  allocInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  allocInfo.descriptorPool = drawPool;
  allocInfo.descriptorSetCount = 2 * count;
  allocInfo.pSetLayouts = layouts.data();
  if (!check(vkAllocateDescriptorSets(device, &allocInfo, sets.data()), "vkAllocateDescriptorSets", error)) {
    return false;
  }

  std::vector<VkDescriptorBufferInfo> buffers(kDrawBlocks * size_t{count});
  std::vector<VkDescriptorImageInfo> images(kTextureSlots * size_t{count});
  std::vector<VkWriteDescriptorSet> writes((kDrawBlocks + kTextureSlots) * size_t{count});
  // The receivers (forward draws of a frame with a shadow pass) sample the atlas; the casters
  // keep whatever the frame binds there (the dummy texture).
  const FrameDraws draws(frame);
  for (uint32_t i = 0; i < count; ++i) {
    DrawSlot& slot = (*slots)[i];
    slot.set = sets[2 * i];
    slot.textureSet = sets[2 * i + 1];
    VkDescriptorBufferInfo* blocks = &buffers[kDrawBlocks * i];
    blocks[0] = {slot_->arena.buffer, slot.frameOffset, sizeof(abi::FrameUniforms)};
    blocks[1] = {slot_->arena.buffer, slot.objectOffset, sizeof(abi::ObjectUniforms)};
    blocks[2] = {slot.materialBuffer, slot.materialOffset, slot.materialSize};
    blocks[3] = {slot_->arena.buffer, shadowBlocks_.uniformsOffset, sizeof(abi::ShadowUniforms)};
    const uint32_t bindings[kDrawBlocks] = {abi::kFrameBinding, abi::kObjectBinding, abi::kMaterialBinding,
                                            abi::kShadowBinding};
    for (uint32_t b = 0; b < kDrawBlocks; ++b) {
      VkWriteDescriptorSet& write = writes[kDrawBlocks * i + b];
      write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      write.dstSet = slot.set;
      write.dstBinding = bindings[b];
      write.descriptorCount = 1;
      write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
      write.pBufferInfo = &blocks[b];
    }
    // Every binding is written, the unused ones with the dummy texture: Vulkan 1.1 has no
    // partially bound descriptor sets, and a shader may declare any of the 16.
    TextureSlots textureSlots = textures_.slotsFor(frame, draws[i]);
    if (frame.shadow && !draws.isCaster(i)) {
      textureSlots[abi::kShadowAtlasBinding] = TextureSlot{shadowAtlas_.view, shadowSampler_};
    }
    for (uint32_t b = 0; b < kTextureSlots; ++b) {
      VkDescriptorImageInfo& image = images[kTextureSlots * i + b];
      image = {textureSlots[b].sampler, textureSlots[b].view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
      VkWriteDescriptorSet& write = writes[kDrawBlocks * size_t{count} + kTextureSlots * i + b];
      write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      write.dstSet = slot.textureSet;
      write.dstBinding = b;
      write.descriptorCount = 1;
      write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      write.pImageInfo = &image;
    }
  }
  vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  return true;
}

bool VulkanBackend::submitAndWait(std::string* error, double* cpuMilliseconds,
                                  std::chrono::steady_clock::time_point start) {
  if (!check(vkResetFences(ctx_.device, 1, &fence_), "vkResetFences", error)) return false;
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commandBuffer_;
  if (!check(vkQueueSubmit(ctx_.queue, 1, &submit, fence_), "vkQueueSubmit", error)) {
    return false;
  }
  if (cpuMilliseconds)
    *cpuMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return check(vkWaitForFences(ctx_.device, 1, &fence_, VK_TRUE, kFenceTimeoutNs), "vkWaitForFences", error);
}

void VulkanBackend::readBack(FrameResult* result) const {
  const size_t values = size_t{targets_.width} * targets_.height * 4;
  result->width = targets_.width;
  result->height = targets_.height;
  result->hdrWidth = targets_.forwardWidth;
  result->hdrHeight = targets_.forwardHeight;
  result->hdr.clear();
  if (readBackHdr_) {
    const size_t hdrValues = size_t{targets_.forwardWidth} * targets_.forwardHeight * 4;
    result->hdr.resize(hdrValues);
    if (hdrFormat_ == HdrFormat::R11G11B10Float) {
      const auto* texels = static_cast<const uint32_t*>(targets_.hdrReadback.mapped);
      for (size_t i = 0; i < hdrValues / 4; ++i) {
        unpackB10G11R11(texels[i], &result->hdr[4 * i]);
        result->hdr[4 * i + 3] = 1.0f;  // no alpha stored: what a sampler returns for it
      }
    } else {
      const auto* halves = static_cast<const uint16_t*>(targets_.hdrReadback.mapped);
      for (size_t i = 0; i < hdrValues; ++i) result->hdr[i] = halfToFloat(halves[i]);
    }
  }
  result->ldr.resize(values);
  std::memcpy(result->ldr.data(), targets_.ldrReadback.mapped, values);
  result->bloom.clear();
  result->bloomWidth = result->bloomHeight = 0;
  result->bloomLevels = bloomOn_ ? bloomChain_.levelCount() : 0;
  if (bloomOn_ && readBackHdr_) bloomChain_.readLevel0(&result->bloom, &result->bloomWidth, &result->bloomHeight);
}

// Timestamps are in ticks of timestampPeriod nanoseconds, valid in their low timestampValidBits.
void VulkanBackend::readTimes(FrameResult* result) const {
  result->gpuTimes.clear();
  if (!timestamps_) return;
  uint64_t ticks[kTimestampCount] = {};
  const uint32_t written = bloomOn_ ? kTimestampCount : kTimestampCount - 1;  // the last is bloom's
  if (vkGetQueryPoolResults(ctx_.device, timestamps_, 0, written, written * sizeof(uint64_t), ticks, sizeof(uint64_t),
                            VK_QUERY_RESULT_64_BIT) != VK_SUCCESS) {
    return;  // not available: the frame is still valid, only untimed
  }
  const uint64_t mask = ctx_.timestampValidBits >= 64 ? ~uint64_t{0} : (uint64_t{1} << ctx_.timestampValidBits) - 1;
  const double msPerTick = double(ctx_.properties.limits.timestampPeriod) * 1e-6;
  const auto span = [&](int from, int to) { return double((ticks[to] - ticks[from]) & mask) * msPerTick; };
  result->gpuTimes.push_back({"forward", span(0, 1)});
  if (bloomOn_) {
    result->gpuTimes.push_back({"bloom", span(1, 3)});
    result->gpuTimes.push_back({"post", span(3, 2)});
  } else {
    result->gpuTimes.push_back({"post", span(1, 2)});
  }
}

}  // namespace

std::unique_ptr<RenderBackend> createVulkanBackend(const VulkanOptions& options, std::string* error) {
  std::string scratch;
  if (!error) error = &scratch;
  try {
    auto backend = std::make_unique<VulkanBackend>();
    if (!backend->init(options, error)) return nullptr;
    return backend;
  } catch (const std::exception& e) {
    *error = std::string("createVulkanBackend: ") + e.what();
    return nullptr;
  }
}

std::unique_ptr<VulkanRenderer> createVulkanBackend(const AppDevice& device, const VulkanOptions& options,
                                                    std::string* error) {
  std::string scratch;
  if (!error) error = &scratch;
  try {
    auto backend = std::make_unique<VulkanBackend>();
    if (!backend->initOn(device, options, error)) return nullptr;
    return backend;
  } catch (const std::exception& e) {
    *error = std::string("createVulkanBackend: ") + e.what();
    return nullptr;
  }
}

}  // namespace facet::runtime
