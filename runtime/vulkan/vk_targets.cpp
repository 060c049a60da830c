#include "vk_targets.h"

#include <array>

#include "facet/runtime/render_path.h"
#include "vk_check.h"
#include "vk_context.h"
#include "vk_pipeline.h"

namespace facet::runtime::vulkan {

bool createFramebuffer(VkDevice device, VkRenderPass pass, const VkImageView* views, uint32_t count, uint32_t width,
                       uint32_t height, VkFramebuffer* out, std::string* error) {
  VkFramebufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  info.renderPass = pass;
  info.attachmentCount = count;
  info.pAttachments = views;
  info.width = width;
  info.height = height;
  info.layers = 1;
  if (!check(vkCreateFramebuffer(device, &info, nullptr, out), "vkCreateFramebuffer", error)) {
    *out = VK_NULL_HANDLE;
    return false;
  }
  return true;
}

std::vector<VkImageView> forwardViews(const RenderTargets& targets, bool merged, VkImageView ldr) {
  std::vector<VkImageView> views{targets.hdr.view, targets.depth.view};
  if (merged) views.push_back(ldr);
  if (targets.hdrSamples.view) views.push_back(targets.hdrSamples.view);
  return views;
}

bool createRenderTargets(const Context& ctx, uint32_t width, uint32_t height, const TargetConfig& config,
                         RenderTargets* targets, std::string* error) {
  RenderTargets t;
  t.width = width;
  t.height = height;
  t.forwardWidth = scaledSize(width, config.renderScale);
  t.forwardHeight = scaledSize(height, config.renderScale);
  const uint32_t fw = t.forwardWidth;
  const uint32_t fh = t.forwardHeight;
  const VkDeviceSize pixels = VkDeviceSize{width} * height;
  // A transient image may only be used as an attachment (no sampling, no copies).
  VkImageUsageFlags hdrUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  hdrUsage |= config.merged ? VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT : VK_IMAGE_USAGE_SAMPLED_BIT;
  if (config.readBackHdr) hdrUsage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if (config.hdrTransient) hdrUsage |= VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
  VkImageUsageFlags depthUsage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  if (config.depthTransient) depthUsage |= VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
  const bool own = config.ownOutput;
  const bool msaa = config.samples != VK_SAMPLE_COUNT_1_BIT && !config.renderToSingleSampled;
  const VkImageCreateFlags renderedMultisampled =
      config.samples != VK_SAMPLE_COUNT_1_BIT && config.renderToSingleSampled
          ? VK_IMAGE_CREATE_MULTISAMPLED_RENDER_TO_SINGLE_SAMPLED_BIT_EXT
          : 0;
  // The samples are only cleared, drawn, resolved and read by the post subpass in the same render
  // pass (the frame graph: transient).
  const VkImageUsageFlags samplesUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT |
                                         (config.postReadsSamples ? VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT : 0);
  bool ok =
      createImage(ctx, fw, fh, config.hdrFormat, hdrUsage, VK_IMAGE_ASPECT_COLOR_BIT, &t.hdr, error, 1, false,
                  VK_SAMPLE_COUNT_1_BIT, renderedMultisampled) &&
      createImage(ctx, fw, fh, kDepthFormat, depthUsage, VK_IMAGE_ASPECT_DEPTH_BIT, &t.depth, error, 1, false,
                  msaa ? config.samples : VK_SAMPLE_COUNT_1_BIT, renderedMultisampled) &&
      (!msaa || createImage(ctx, fw, fh, config.hdrFormat, samplesUsage, VK_IMAGE_ASPECT_COLOR_BIT, &t.hdrSamples,
                            error, 1, false, config.samples)) &&
      (!own ||
       (createImage(ctx, width, height, kLdrFormat,
                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
                    &t.ldr, error) &&
        (!config.readBackHdr ||
         createHostBuffer(ctx, VkDeviceSize{fw} * fh * (config.hdrFormat == VK_FORMAT_R16G16B16A16_SFLOAT ? 8 : 4),
                          VK_BUFFER_USAGE_TRANSFER_DST_BIT, &t.hdrReadback, error)) &&
        createHostBuffer(ctx, pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, &t.ldrReadback, error)));
  // FXAA: the post pass writes toneMapped, the FXAA pass samples it and writes ldr.
  ok = ok &&
       (!config.fxaa ||
        (createImage(ctx, width, height, kLdrFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                     VK_IMAGE_ASPECT_COLOR_BIT, &t.toneMapped, error) &&
         createFramebuffer(ctx.device, config.fxaaPass, &t.ldr.view, 1, width, height, &t.fxaaFramebuffer, error)));
  const VkImageView postOutput = config.fxaa ? t.toneMapped.view : t.ldr.view;
  if (ok && config.merged) {
    // Without an own output, each app image has its own framebuffer (vk_app_images.h).
    const std::vector<VkImageView> views = forwardViews(t, true, postOutput);
    ok = !own || createFramebuffer(ctx.device, config.forwardPass, views.data(), uint32_t(views.size()), width, height,
                                   &t.forwardFramebuffer, error);
  } else if (ok) {
    const std::vector<VkImageView> views = forwardViews(t, false, VK_NULL_HANDLE);
    ok = createFramebuffer(ctx.device, config.forwardPass, views.data(), uint32_t(views.size()), fw, fh,
                           &t.forwardFramebuffer, error) &&
         (!own ||
          createFramebuffer(ctx.device, config.postPass, &postOutput, 1, width, height, &t.postFramebuffer, error));
  }
  if (!ok) {
    destroyRenderTargets(ctx.device, &t);
    *targets = RenderTargets{};
    return false;
  }
  *targets = t;
  return true;
}

void destroyRenderTargets(VkDevice device, RenderTargets* targets) {
  if (targets->forwardFramebuffer) vkDestroyFramebuffer(device, targets->forwardFramebuffer, nullptr);
  if (targets->postFramebuffer) vkDestroyFramebuffer(device, targets->postFramebuffer, nullptr);
  if (targets->fxaaFramebuffer) vkDestroyFramebuffer(device, targets->fxaaFramebuffer, nullptr);
  destroyImage(device, &targets->toneMapped);
  destroyImage(device, &targets->hdr);
  destroyImage(device, &targets->depth);
  destroyImage(device, &targets->hdrSamples);
  destroyImage(device, &targets->ldr);
  destroyHostBuffer(device, &targets->hdrReadback);
  destroyHostBuffer(device, &targets->ldrReadback);
  *targets = RenderTargets{};
}

}  // namespace facet::runtime::vulkan
