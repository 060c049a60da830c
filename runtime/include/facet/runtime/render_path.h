// The frame Facet renders, as a frame graph: a forward pass into HDR colour + depth, then a post
// pass writing LDR. How the post pass reads HDR decides the render path: its own pixel (merged:
// one render pass, HDR and depth never leave tile memory) or the whole texture (separate: HDR is
// stored and sampled back). Both backends and facet-view build their graph here, so the byte
// counts they report are those of the path they run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "facet/runtime/frame_graph.h"
#include "facet/scene/post_settings.h"

namespace facet::runtime {

enum class PostPath {
  Auto,      // merged when the backend supports it, else separate
  Merged,    // post reads its own pixel: subpass input (Vulkan) / framebuffer fetch (GLES)
  Separate,  // post samples the stored HDR texture
};

const char* toString(PostPath path);

// The HDR target's format. R11G11B10F halves the bytes per pixel (4 instead of 8, no alpha) for
// 6 (red, green) and 5 (blue) mantissa bits instead of 10: the error it costs is measured in
// docs/runtime.md ("HDR format"). Both need float colour render targets (core Vulkan formats,
// GLES 3.2 or EXT_color_buffer_float) that can be read as input attachments / by framebuffer fetch.
enum class HdrFormat {
  Rgba16Float,     // VK_FORMAT_R16G16B16A16_SFLOAT / GL_RGBA16F
  R11G11B10Float,  // VK_FORMAT_B10G11R11_UFLOAT_PACK32 / GL_R11F_G11F_B10F: unsigned, no alpha
};
const char* toString(HdrFormat format);  // "rgba16f", "r11g11b10f"
uint32_t bytesPerPixel(HdrFormat format);

// Render scale: the forward pass renders at scale × the output size and the post pass upscales
// (bilinear). 0.5..1.0: below half the output an upscaled pixel covers more than 2×2 output
// pixels, where a bilinear filter shows its blocks.
inline constexpr double kMinRenderScale = 0.5;
inline constexpr double kMaxRenderScale = 1.0;
bool isRenderScale(double scale);  // in [kMinRenderScale, kMaxRenderScale]; false for NaN
// "<what> must be in 0.5..1, not <scale>": the message for a scale isRenderScale refuses.
std::string renderScaleError(const char* what, double scale);
// The forward pass's size for an output of `size` pixels: rounded to nearest, at least 1.
uint32_t scaledSize(uint32_t size, double scale);

// Bloom's chain (chunks/bloom.glsl): image 0 is half the HDR image's width and height rounded up
// (a quarter of its pixels), each next one half the one before, rounded up, down to 1 × 1. The
// sizes of min(levels, the mip count of image 0) images: a frame too small for the levels asked
// renders fewer (the documented fallback: a scene's levels cannot know every window size).
struct ImageSize {
  uint32_t width = 0;
  uint32_t height = 0;
};
std::vector<ImageSize> bloomLevelSizes(uint32_t hdrWidth, uint32_t hdrHeight, int levels);
// "" for settings in range, else "<what>.intensity must be in 0..1, not 2" and the like.
std::string bloomSettingsError(const char* what, const BloomSettings& bloom);

struct ForwardPostGraph {
  fg::FrameGraph graph;
  fg::ResourceId hdr = 0;  // RGBA16F or R11G11B10F, one sample: what the post pass reads
  // The forward pass's colour: hdr itself at one sample; with MSAA a multisampled image of hdr's
  // format, resolved into hdr at the end of the forward pass (and transient).
  fg::ResourceId hdrSamples = 0;
  fg::ResourceId depth = 0;  // D32, as many samples as hdrSamples (never resolved: not stored)
  fg::ResourceId ldr = 0;    // RGBA8, read after the frame (presented or read back)
  // What the post pass writes: ldr itself, or with FXAA an RGBA8 image the FXAA pass samples
  // (it reads neighbouring pixels, so the image leaves tile memory: stored, then sampled).
  fg::ResourceId toneMapped = 0;
  uint32_t forwardPass = 0;
  uint32_t postPass = 0;
  uint32_t fxaaPass = UINT32_MAX;  // UINT32_MAX when FXAA is off: no pass, no image
  // Bloom: the chain's images (bloomLevelSizes), written by a downsample pass each and, all but
  // the last, loaded and blended into by an upsample pass; the post pass samples bloom[0]. Empty
  // when bloom is off.
  std::vector<fg::ResourceId> bloom;
  std::vector<uint32_t> bloomDownPasses, bloomUpPasses;  // up passes from the coarsest: level n-2 first
  // The sun's shadow atlas (D16, shadowAtlasSize²) and the pass that draws the casters into it
  // before the forward pass, which samples it whole (a texture, never its own pixel): the atlas
  // is stored, and sampled from memory. UINT32_MAX without a shadow.
  fg::ResourceId shadowAtlas = UINT32_MAX;
  uint32_t shadowPass = UINT32_MAX;
};

// Bytes per texel of the shadow atlas: D16 (docs/shadows.md: 1/65536 steps of the cascade's
// depth range, finer than a receiver's biases).
inline constexpr uint32_t kShadowAtlasBytesPerTexel = 2;

// path must be Merged or Separate. readBackHdr: HDR is also read after the frame (tests, eval),
// which forces it to be stored. samples: the forward pass's MSAA sample count (1, 2 or 4).
// fxaa: an FXAA pass after the post pass (chunks/fxaa.glsl) writes ldr. renderScale < 1: HDR and
// depth are scaledSize() of width × height and the post pass samples HDR (a subpass cannot change
// resolution), so the merged path becomes the separate one. bloomLevels > 0: the bloom chain of
// that many levels (fewer for a small frame, bloomLevelSizes), in the HDR format; its downsample
// samples the whole HDR image, so HDR is stored and the merged path becomes the separate one.
// shadowAtlasSize > 0: a shadow pass into a square D16 atlas of that size comes first, and the
// forward pass samples it. toneMapSamples (merged path with MSAA): the post pass reads each sample
// of hdrSamples, its own pixel's, instead of the resolved hdr (which is still resolved).
ForwardPostGraph buildForwardPostGraph(uint32_t width, uint32_t height, PostPath path, bool readBackHdr,
                                       HdrFormat hdrFormat = HdrFormat::Rgba16Float, uint32_t samples = 1,
                                       bool fxaa = false, double renderScale = 1.0, int bloomLevels = 0,
                                       uint32_t shadowAtlasSize = 0, bool toneMapSamples = false);

// The path a backend runs: a render scale below 1, or bloom (its chain samples the whole HDR
// image, which must be stored anyway), turns the merged path into the separate one.
PostPath effectivePostPath(PostPath requested, double renderScale, bool bloom = false);

// The MSAA sample counts Facet renders with: 1 (off), 2 and 4. The backends refuse a count the
// device does not offer for both the HDR colour and the depth format.
bool isMsaaSampleCount(uint32_t samples);

}  // namespace facet::runtime
