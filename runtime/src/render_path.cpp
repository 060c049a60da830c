#include "facet/runtime/render_path.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace facet::runtime {

const char* toString(PostPath path) {
  switch (path) {
    case PostPath::Auto: return "auto";
    case PostPath::Merged: return "merged";
    case PostPath::Separate: return "separate";
  }
  return "?";
}

const char* toString(HdrFormat format) { return format == HdrFormat::R11G11B10Float ? "r11g11b10f" : "rgba16f"; }

uint32_t bytesPerPixel(HdrFormat format) { return format == HdrFormat::R11G11B10Float ? 4 : 8; }

bool isMsaaSampleCount(uint32_t samples) { return samples == 1 || samples == 2 || samples == 4; }

bool isRenderScale(double scale) { return scale >= kMinRenderScale && scale <= kMaxRenderScale; }

std::string renderScaleError(const char* what, double scale) {
  char text[160];
  std::snprintf(text, sizeof text, "%s must be in %g..%g, not %g", what, kMinRenderScale, kMaxRenderScale, scale);
  return text;
}

uint32_t scaledSize(uint32_t size, double scale) {
  return std::max<uint32_t>(1, static_cast<uint32_t>(std::lround(double(size) * scale)));
}

PostPath effectivePostPath(PostPath requested, double renderScale, bool bloom) {
  return renderScale < 1.0 || bloom ? PostPath::Separate : requested;
}

std::vector<ImageSize> bloomLevelSizes(uint32_t hdrWidth, uint32_t hdrHeight, int levels) {
  std::vector<ImageSize> sizes;
  ImageSize size{std::max<uint32_t>(1, (hdrWidth + 1) / 2), std::max<uint32_t>(1, (hdrHeight + 1) / 2)};
  // Image 0's mip count in the chain's rounding: the halvings (rounded up) to reach 1 × 1, plus one.
  uint32_t mips = 1;
  for (uint32_t side = std::max(size.width, size.height); side > 1; side = (side + 1) / 2) ++mips;
  const int count = std::min<int>(levels, int(mips));
  for (int i = 0; i < count; ++i) {
    sizes.push_back(size);
    size = {std::max<uint32_t>(1, (size.width + 1) / 2), std::max<uint32_t>(1, (size.height + 1) / 2)};
  }
  return sizes;
}

std::string bloomSettingsError(const char* what, const BloomSettings& bloom) {
  char text[200];
  if (!(bloom.intensity >= 0 && bloom.intensity <= 1))
    std::snprintf(text, sizeof text, "%s.intensity must be in 0..1, not %g", what, bloom.intensity);
  else if (bloom.levels < 1 || bloom.levels > kMaxBloomLevels)
    std::snprintf(text, sizeof text, "%s.levels must be in 1..%d, not %d", what, kMaxBloomLevels, bloom.levels);
  else if (!(bloom.threshold >= 0 && bloom.threshold <= 65504))
    std::snprintf(text, sizeof text, "%s.threshold must be in 0..65504 (fp16's largest), not %g", what,
                  bloom.threshold);
  else
    return "";
  return text;
}

ForwardPostGraph buildForwardPostGraph(uint32_t width, uint32_t height, PostPath path, bool readBackHdr,
                                       HdrFormat hdrFormat, uint32_t samples, bool fxaa, double renderScale,
                                       int bloomLevels, uint32_t shadowAtlasSize, bool toneMapSamples) {
  ForwardPostGraph g;
  const uint32_t hdrBytes = bytesPerPixel(hdrFormat);
  path = effectivePostPath(path, renderScale, bloomLevels > 0);
  const uint32_t fw = scaledSize(width, renderScale);
  const uint32_t fh = scaledSize(height, renderScale);
  g.hdr = g.graph.addResource({"hdr", fw, fh, hdrBytes, false, readBackHdr, 1});
  g.hdrSamples = samples > 1 ? g.graph.addResource({"hdr_ms", fw, fh, hdrBytes, false, false, samples}) : g.hdr;
  g.depth = g.graph.addResource({"depth", fw, fh, 4, true, false, samples});
  g.ldr = g.graph.addResource({"ldr", width, height, 4, false, true, 1});
  g.toneMapped = fxaa ? g.graph.addResource({"tonemapped", width, height, 4, false, false, 1}) : g.ldr;
  if (shadowAtlasSize > 0) {
    g.shadowAtlas =
        g.graph.addResource({"shadow", shadowAtlasSize, shadowAtlasSize, kShadowAtlasBytesPerTexel, true, false, 1});
    g.shadowPass = g.graph.addPass({"shadow", {}, {g.shadowAtlas}, {g.shadowAtlas}, {}});
  }
  fg::PassDesc forward{"forward", {}, {g.hdrSamples, g.depth}, {g.hdrSamples, g.depth}, {}};
  if (shadowAtlasSize > 0) forward.reads.push_back({g.shadowAtlas, fg::ReadKind::WholeTexture});
  if (samples > 1) forward.resolves.push_back(g.hdr);
  g.forwardPass = g.graph.addPass(forward);
  const fg::ReadKind read = path == PostPath::Separate ? fg::ReadKind::WholeTexture : fg::ReadKind::OwnPixel;
  const bool readsSamples = toneMapSamples && samples > 1 && path == PostPath::Merged;
  fg::PassDesc post{"post", {{readsSamples ? g.hdrSamples : g.hdr, read}}, {g.toneMapped}, {}, {}};
  if (bloomLevels > 0) {
    const std::vector<ImageSize> sizes = bloomLevelSizes(fw, fh, bloomLevels);
    for (size_t i = 0; i < sizes.size(); ++i) {
      const fg::ResourceId source = i == 0 ? g.hdr : g.bloom.back();
      g.bloom.push_back(g.graph.addResource(
          {"bloom" + std::to_string(i), sizes[i].width, sizes[i].height, hdrBytes, false, false, 1}));
      g.bloomDownPasses.push_back(g.graph.addPass(
          {"bloom_down" + std::to_string(i), {{source, fg::ReadKind::WholeTexture}}, {g.bloom.back()}, {}, {}}));
    }
    // Each finer level blends the coarser one's tent over its own downsample: loaded, then written.
    for (size_t i = sizes.size() - 1; i-- > 0;)
      g.bloomUpPasses.push_back(g.graph.addPass(
          {"bloom_up" + std::to_string(i), {{g.bloom[i + 1], fg::ReadKind::WholeTexture}}, {g.bloom[i]}, {}, {}}));
    post.reads.push_back({g.bloom[0], fg::ReadKind::WholeTexture});
  }
  g.postPass = g.graph.addPass(post);
  if (fxaa) g.fxaaPass = g.graph.addPass({"fxaa", {{g.toneMapped, fg::ReadKind::WholeTexture}}, {g.ldr}, {}, {}});
  return g;
}

}  // namespace facet::runtime
