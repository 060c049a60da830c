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

PostPath effectivePostPath(PostPath requested, double renderScale) {
  return renderScale < 1.0 ? PostPath::Separate : requested;
}

ForwardPostGraph buildForwardPostGraph(uint32_t width, uint32_t height, PostPath path, bool readBackHdr,
                                       HdrFormat hdrFormat, uint32_t samples, bool fxaa, double renderScale,
                                       uint32_t shadowAtlasSize) {
  ForwardPostGraph g;
  const uint32_t hdrBytes = bytesPerPixel(hdrFormat);
  path = effectivePostPath(path, renderScale);
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
  g.postPass = g.graph.addPass({"post", {{g.hdr, read}}, {g.toneMapped}, {}, {}});
  if (fxaa) g.fxaaPass = g.graph.addPass({"fxaa", {{g.toneMapped, fg::ReadKind::WholeTexture}}, {g.ldr}, {}, {}});
  return g;
}

}  // namespace facet::runtime
